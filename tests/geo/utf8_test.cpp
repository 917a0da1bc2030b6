// geo::append_utf8: the byte sequences of RFC 3629 at each length boundary, and U+FFFD for the
// values UTF-8 cannot carry.
#include <gtest/gtest.h>

#include <string>

#include "geo/utf8.hpp"

namespace trailray::geo {
namespace {

std::string utf8(char32_t c) {
  std::string out;
  append_utf8(out, c);
  return out;
}

TEST(Utf8, EachLengthAtItsBoundaries) {
  EXPECT_EQ(utf8(U'\0'), std::string(1, '\0'));
  EXPECT_EQ(utf8(0x7F), "\x7F");
  EXPECT_EQ(utf8(0x80), "\xC2\x80");
  EXPECT_EQ(utf8(0xE9), "\xC3\xA9");  // é
  EXPECT_EQ(utf8(0x7FF), "\xDF\xBF");
  EXPECT_EQ(utf8(0x800), "\xE0\xA0\x80");
  EXPECT_EQ(utf8(0x20AC), "\xE2\x82\xAC");  // €
  EXPECT_EQ(utf8(0xFFFF), "\xEF\xBF\xBF");
  EXPECT_EQ(utf8(0x10000), "\xF0\x90\x80\x80");
  EXPECT_EQ(utf8(0x1F3D4), "\xF0\x9F\x8F\x94");  // 🏔
  EXPECT_EQ(utf8(0x10FFFF), "\xF4\x8F\xBF\xBF");
}

TEST(Utf8, SurrogatesAndValuesBeyondUnicodeBecomeTheReplacementCharacter) {
  const std::string replacement = "\xEF\xBF\xBD";
  EXPECT_EQ(utf8(0xD800), replacement);
  EXPECT_EQ(utf8(0xDBFF), replacement);
  EXPECT_EQ(utf8(0xDC00), replacement);
  EXPECT_EQ(utf8(0xDFFF), replacement);
  EXPECT_EQ(utf8(0x110000), replacement);
  EXPECT_EQ(utf8(0xFFFFFFFF), replacement);
  EXPECT_EQ(utf8(0xD7FF), "\xED\x9F\xBF");  // just below the surrogates
  EXPECT_EQ(utf8(0xE000), "\xEE\x80\x80");  // just above
}

TEST(Utf8, AppendsToWhatIsThere) {
  std::string out = "ab";
  append_utf8(out, 0xE9);
  append_utf8(out, U'c');
  EXPECT_EQ(out, "ab\xC3\xA9" "c");
}

}  // namespace
}  // namespace trailray::geo
