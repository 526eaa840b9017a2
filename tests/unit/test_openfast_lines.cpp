// Raw-line helpers of the OpenFAST readers: comment lines, words (quotes, commas, trailing '!'
// comments), rows of numbers, and the next line with content.
#include <gtest/gtest.h>

#include "src/io/openfast_lines.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using whirl::io::OpenFastLines;
using whirl::io::parse_number_row;
using whirl::io::split_words;

TEST(OpenFastLines, CommentAndBlankLines) {
  EXPECT_TRUE(whirl::io::is_comment_line("  ! Alpha Cl Cd"));
  EXPECT_TRUE(whirl::io::is_comment_line("# note"));
  EXPECT_TRUE(whirl::io::is_comment_line("%x"));
  EXPECT_FALSE(whirl::io::is_comment_line("  1  Re  ! Reynolds"));
  EXPECT_TRUE(whirl::io::is_blank_line(" \t\r"));
  EXPECT_FALSE(whirl::io::is_blank_line(" x"));
}

TEST(OpenFastLines, Words) {
  EXPECT_EQ(split_words("\"a b.dat\"   AFNames  - names"), (std::vector<std::string>{"\"a b.dat\"", "AFNames", "-", "names"}));
  EXPECT_EQ(split_words("TwrElev TwrDiam TwrCb !TwrTI used only"), (std::vector<std::string>{"TwrElev", "TwrDiam", "TwrCb"}));
  EXPECT_EQ(split_words("0, 0,0"), (std::vector<std::string>{"0", "0", "0"}));
  EXPECT_EQ(whirl::io::unquoted("\"x.dat\""), "x.dat");
  EXPECT_EQ(whirl::io::unquoted("x.dat"), "x.dat");
}

TEST(OpenFastLines, NumberRows) {
  EXPECT_EQ(parse_number_row("  -180.00  0.000  1.5D-2  +0.1 ! end"), (std::vector<double>{-180.0, 0.0, 0.015, 0.1}));
  EXPECT_FALSE(parse_number_row("").has_value());
  EXPECT_FALSE(parse_number_row("1.0  Re").has_value());
}

TEST(OpenFastLines, NextContentLineSkipsBlankAndCommentLines) {
  const OpenFastLines l = OpenFastLines::from_text("a\n\n! c\r\nb\n", "f.dat");
  EXPECT_EQ(l.count(), 4);
  EXPECT_EQ(l.line(3), "! c");
  EXPECT_EQ(l.next_content_line(1), std::optional<int>(4));
  EXPECT_FALSE(l.next_content_line(4).has_value());
  EXPECT_EQ(l.line(9), "");
  EXPECT_EQ(l.text_without_comments(), "a\n\n\nb\n");
  EXPECT_EQ(whirl::test::input_error_message([] { OpenFastLines::read("/no/such/file.dat"); }),
            "/no/such/file.dat: cannot open file");
}

}  // namespace
