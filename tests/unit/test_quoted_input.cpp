// Input quoted in messages (core/quoted_input.hpp): cut to its limit with the length it
// had, and every byte a terminal acts on escaped, so that no message carries a control
// sequence or megabytes of a user's file.
#include <gtest/gtest.h>

#include <string>

#include "core/quoted_input.hpp"

using namespace granshock;

TEST(QuotedInput, PrintableTextIsQuotedAsItIs) {
  EXPECT_EQ(quoted_input("ITEM: TIMESTEP"), "'ITEM: TIMESTEP'");
  EXPECT_EQ(quoted_input(""), "''");
  EXPECT_EQ(quoted_input("aluminium \xc3\xa9t\xc3\xa9 \xe2\x80\x94 \xcf\x86"),
            "'aluminium \xc3\xa9t\xc3\xa9 \xe2\x80\x94 \xcf\x86'");  // UTF-8 stays
}

TEST(QuotedInput, ControlBytesAndC1ControlsAreEscaped) {
  // ESC ] 0 ; title BEL (an OSC that retitles the terminal), CSI 2 J (clear), a NUL, DEL.
  EXPECT_EQ(quoted_input(std::string("\x1b]0;t\x07\x1b[2J\0\x7f", 12)),
            "'\\x1b]0;t\\x07\\x1b[2J\\x00\\x7f'");
  EXPECT_EQ(quoted_input("a\nb\rc\td\\e"), "'a\\nb\\rc\\td\\\\e'");
  // U+009B (CSI as a C1 control, encoded c2 9b) and a lone 0x9b byte, and invalid UTF-8.
  EXPECT_EQ(quoted_input("\xc2\x9b"
                         "2J"),
            "'\\xc2\\x9b2J'");
  EXPECT_EQ(quoted_input("\x9b"
                         "2J"),
            "'\\x9b2J'");
  EXPECT_EQ(quoted_input("\xc3"), "'\\xc3'");
  EXPECT_EQ(quoted_input("\xed\xa0\x80"), "'\\xed\\xa0\\x80'");  // a UTF-16 surrogate
}

TEST(QuotedInput, LongInputIsCutWithItsLength) {
  const std::string line(50'000'000, 'x');
  const std::string q = quoted_input(line);
  EXPECT_EQ(q, "'" + std::string(kQuotedInputChars, 'x') + "... (50000000 bytes in all)'");
  // A character that would cross the limit is left out whole, not cut in its bytes.
  const std::string accented = std::string(99, 'a') + "\xc3\xa9" + "b";
  EXPECT_EQ(quoted_input(accented), "'" + std::string(99, 'a') + "... (102 bytes in all)'");
  EXPECT_EQ(quoted_input(std::string(100, 'a')), "'" + std::string(100, 'a') + "'");
}

TEST(QuotedInput, PrintableLineEscapesWithoutQuotes) {
  EXPECT_EQ(printable_line("granshock: error: \x1b[31mred"), "granshock: error: \\x1b[31mred");
  EXPECT_EQ(printable_line(std::string(5000, 'y')).size(),
            4000 + std::string("... (5000 bytes in all)").size());
}

// A message that quotes input escaped already (the scene reader's show()) keeps its escapes.
TEST(QuotedInput, PrintableLineKeepsBackslashes) {
  EXPECT_EQ(printable_line("= \"st\\neel\""), "= \"st\\neel\"");
  EXPECT_EQ(printable_line("a\nb"), "a\\nb");
}
