// Raw-line helpers of the OpenFAST readers: comment lines, words (quotes, commas, trailing '!'
// comments), rows of numbers, and the next line with content.
#include <gtest/gtest.h>

#include "src/io/openfast/openfast_lines.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using whirl::io::OpenFastLines;
using whirl::io::parseNumberRow;
using whirl::io::splitWords;

TEST(OpenFastLines, CommentAndBlankLines) {
  EXPECT_TRUE(whirl::io::isCommentLine("  ! Alpha Cl Cd"));
  EXPECT_TRUE(whirl::io::isCommentLine("# note"));
  EXPECT_TRUE(whirl::io::isCommentLine("%x"));
  EXPECT_FALSE(whirl::io::isCommentLine("  1  Re  ! Reynolds"));
  EXPECT_TRUE(whirl::io::isBlankLine(" \t\r"));
  EXPECT_FALSE(whirl::io::isBlankLine(" x"));
}

TEST(OpenFastLines, Words) {
  EXPECT_EQ(splitWords("\"a b.dat\"   AFNames  - names"),
            (std::vector<std::string>{"\"a b.dat\"", "AFNames", "-", "names"}));
  EXPECT_EQ(splitWords("TwrElev TwrDiam TwrCb !TwrTI used only"),
            (std::vector<std::string>{"TwrElev", "TwrDiam", "TwrCb"}));
  EXPECT_EQ(splitWords("0, 0,0"), (std::vector<std::string>{"0", "0", "0"}));
  EXPECT_EQ(whirl::io::unquoted("\"x.dat\""), "x.dat");
  EXPECT_EQ(whirl::io::unquoted("x.dat"), "x.dat");
}

TEST(OpenFastLines, NumberRows) {
  EXPECT_EQ(parseNumberRow("  -180.00  0.000  1.5D-2  +0.1 ! end"), (std::vector<double>{-180.0, 0.0, 0.015, 0.1}));
  EXPECT_FALSE(parseNumberRow("").has_value());
  EXPECT_FALSE(parseNumberRow("1.0  Re").has_value());
}

TEST(OpenFastLines, NextContentLineSkipsBlankAndCommentLines) {
  const OpenFastLines l = OpenFastLines::fromText("a\n\n! c\r\nb\n", "f.dat");
  EXPECT_EQ(l.count(), 4);
  EXPECT_EQ(l.line(3), "! c");
  EXPECT_EQ(l.nextContentLine(1), std::optional<int>(4));
  EXPECT_FALSE(l.nextContentLine(4).has_value());
  EXPECT_EQ(l.line(9), "");
  EXPECT_EQ(l.textWithoutComments(), "a\n\n\nb\n");
  EXPECT_EQ(whirl::test::inputErrorMessage([] { OpenFastLines::read("/no/such/file.dat"); }),
            "/no/such/file.dat: cannot open file");
}

}  // namespace
