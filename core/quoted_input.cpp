#include "core/quoted_input.hpp"

#include <fmt/format.h>

namespace granshock {

namespace {

// The length of the valid UTF-8 sequence of a printable character at text[i] (a code
// point from U+00A0 on: U+0080-U+009F are the C1 controls, 0x9b among them a CSI), or 0.
std::size_t printable_utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const std::size_t n = lead >= 0xf0 && lead < 0xf5   ? 4
                        : lead >= 0xe0 && lead < 0xf0 ? 3
                        : lead >= 0xc2 && lead < 0xe0 ? 2
                                                      : 0;
  if (n == 0 || i + n > text.size()) return 0;
  unsigned code = lead & (0x7fu >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3fu);
  }
  const unsigned smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < smallest[n] || code > 0x10ffff || (code >= 0xd800 && code < 0xe000)) return 0;
  return code < 0xa0 ? 0 : n;
}

// At most max_bytes of text with every byte a terminal would act on escaped; a backslash
// doubled too where `backslash` (so that an escape in the input cannot pass for one of ours).
std::string escaped(std::string_view text, std::size_t max_bytes, bool backslash) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size() && i < max_bytes) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t n = printable_utf8_length(text, i);
      if (n > 0 && i + n <= max_bytes) {
        out.append(text.substr(i, n));
        i += n;
        continue;
      }
      if (n > 0) break;  // a character that would pass the limit is left out whole
    }
    switch (c) {
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\\':
        out += backslash ? "\\\\" : "\\";
        break;
      default:
        if (c < 0x20 || c >= 0x7f)
          out += fmt::format("\\x{:02x}", c);
        else
          out += char(c);
    }
    ++i;
  }
  if (i < text.size()) out += fmt::format("... ({} bytes in all)", text.size());
  return out;
}

}  // namespace

std::string quoted_input(std::string_view text, std::size_t max_chars) {
  return "'" + escaped(text, max_chars, true) + "'";
}

std::string printable_line(std::string_view text, std::size_t max_chars) {
  return escaped(text, max_chars, false);
}

}  // namespace granshock
