// Input quoted in a message (docs/stability.md, "Messages"). A message that repeats what a
// user gave (a dump line, a key's value, a flag) shows at most kQuotedInputChars of it,
// with every byte a terminal would act on written as an escape, so that a 50 MB line does
// not make a 50 MB message and ESC or OSC bytes never reach the user's terminal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace granshock {

inline constexpr std::size_t kQuotedInputChars = 100;

// `text` between single quotes: control bytes, DEL, C1 controls and bytes that are not
// UTF-8 as \xNN (\n, \r, \t as such, a backslash doubled; printable UTF-8 stays), cut
// after `max_chars` bytes of the input with "... (N bytes in all)".
std::string quoted_input(std::string_view text, std::size_t max_chars = kQuotedInputChars);

// A whole message made safe to print as one line: the same escapes without the quotes and
// with backslashes as they are (a message may quote input escaped already), cut after
// max_chars bytes. The last guard before stderr (apps/granshock/main.cpp), for a
// message that quotes input without quoted_input.
std::string printable_line(std::string_view text, std::size_t max_chars = 4000);

}  // namespace granshock
