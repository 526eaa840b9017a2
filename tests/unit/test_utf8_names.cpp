// Names must be UTF-8 text (src/base/text.hpp, invalidUtf8Reason): the JSON writer stops at a byte
// that is not (issue 48, item 5). The cases follow RFC 3629, section 4 (the syntax of UTF-8).
#include <gtest/gtest.h>

#include <string>

#include "src/base/error.hpp"
#include "src/base/text.hpp"

namespace whirl {
namespace {

TEST(Utf8Names, ValidTextPasses) {
  EXPECT_EQ(invalidUtf8Reason("tower FA 1"), "");
  EXPECT_EQ(invalidUtf8Reason("Turm \xC3\xBC"), "");                  // ü, two bytes
  EXPECT_EQ(invalidUtf8Reason("\xE2\x82\xAC 1"), "");                 // €, three bytes
  EXPECT_EQ(invalidUtf8Reason("\xF0\x9F\x8C\x80"), "");               // U+1F300, four bytes
  EXPECT_EQ(invalidUtf8Reason("\xED\x9F\xBF \xF4\x8F\xBF\xBF"), "");  // U+D7FF, U+10FFFF: the edges
}

TEST(Utf8Names, EveryKindOfInvalidByteIsFoundWithItsPosition) {
  EXPECT_NE(invalidUtf8Reason("bad\xFFname").find("(0xFF) at byte 4"), std::string::npos);
  EXPECT_NE(invalidUtf8Reason("\x80").find("(0x80) at byte 1"), std::string::npos);      // lone continuation
  EXPECT_NE(invalidUtf8Reason("a\xC3").find("(0xC3) at byte 2"), std::string::npos);     // truncated
  EXPECT_NE(invalidUtf8Reason("\xC0\xAF").find("(0xC0) at byte 1"), std::string::npos);  // overlong '/'
  EXPECT_NE(invalidUtf8Reason("\xE0\x80\xAF").find("(0xE0)"), std::string::npos);        // overlong, 3 bytes
  EXPECT_NE(invalidUtf8Reason("\xED\xA0\x80").find("(0xED)"), std::string::npos);        // surrogate U+D800
  EXPECT_NE(invalidUtf8Reason("\xF4\x90\x80\x80").find("(0xF4)"), std::string::npos);    // above U+10FFFF
  EXPECT_NE(invalidUtf8Reason("\xE2\x82 x").find("(0xE2)"), std::string::npos);          // bad third byte
}

TEST(Utf8Names, RequirePrintableNamesFileLineAndKey) {
  try {
    requirePrintable("bad\xFFname", "t.yaml", 9, "name");
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.yaml:9: name: contains a byte that is not UTF-8 text (0xFF) at byte 4: names and titles must be "
              "UTF-8 text (save the file as UTF-8)");
  }
}

TEST(Utf8Names, MessagesEscapeBytesThatAreNotUtf8) {
  EXPECT_EQ(escapeControlCharacters("a\xFF\xC3\xBC\n"), "a\\xFF\xC3\xBC\\n");
}

}  // namespace
}  // namespace whirl
