// geo::append_utf8: the byte sequences of RFC 3629 at each length boundary, and U+FFFD for the
// values UTF-8 cannot carry. geo::next_utf8: each length decoded, and what is not UTF-8 (stray
// continuation and impossible bytes, overlong forms, surrogates, values above U+10FFFF, cut
// sequences) reported with the length to resume after.
#include <gtest/gtest.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>

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
  EXPECT_EQ(out,
            "ab\xC3\xA9"
            "c");
}

struct Step {
  char32_t code_point;
  std::size_t length;
  bool valid;
};

Step step(std::string_view s) {
  const Utf8Step r = next_utf8(s);
  return {r.code_point, r.length, r.valid};
}

bool operator==(const Step& a, const Step& b) {
  return a.code_point == b.code_point && a.length == b.length && a.valid == b.valid;
}

std::ostream& operator<<(std::ostream& o, const Step& s) {
  return o << "U+" << std::hex << static_cast<unsigned long>(s.code_point) << std::dec << " length " << s.length
           << (s.valid ? " valid" : " invalid");
}

const Step kBad1{kReplacementCharacter, 1, false};

TEST(NextUtf8, DecodesEveryLengthAndWhatFollowsDoesNotMatter) {
  for (char32_t c : {char32_t{0}, char32_t{0x41}, char32_t{0x7F}, char32_t{0x80}, char32_t{0xE9}, char32_t{0x7FF},
                     char32_t{0x800}, char32_t{0x20AC}, char32_t{0xD7FF}, char32_t{0xE000}, char32_t{0xFFFD},
                     char32_t{0xFFFF}, char32_t{0x10000}, char32_t{0x1F3D4}, char32_t{0x10FFFF}}) {
    const std::string bytes = utf8(c);
    EXPECT_EQ(step(bytes), (Step{c, bytes.size(), true}));
    EXPECT_EQ(step(bytes + "x\x80"), (Step{c, bytes.size(), true}));
  }
}

TEST(NextUtf8, BytesThatCannotStartASequenceAreOneByteLong) {
  for (const char* s : {"\x80", "\xBF", "\xC0\x80", "\xC1\xBF", "\xF5\x80\x80\x80", "\xF8", "\xFE", "\xFF"})
    EXPECT_EQ(step(s), kBad1) << static_cast<int>(static_cast<unsigned char>(s[0]));
}

TEST(NextUtf8, OverlongFormsAreInvalidWholeSequences) {
  EXPECT_EQ(step("\xE0\x80\x80"), (Step{kReplacementCharacter, 3, false}));  // U+0000 in 3 bytes
  EXPECT_EQ(step("\xE0\x9F\xBF"), (Step{kReplacementCharacter, 3, false}));  // U+07FF in 3 bytes
  EXPECT_EQ(step("\xF0\x80\x80\x80"), (Step{kReplacementCharacter, 4, false}));
  EXPECT_EQ(step("\xF0\x8F\xBF\xBF"), (Step{kReplacementCharacter, 4, false}));  // U+FFFF in 4 bytes
}

TEST(NextUtf8, SurrogatesAreInvalid) {
  EXPECT_EQ(step("\xED\xA0\x80"), (Step{kReplacementCharacter, 3, false}));  // U+D800
  EXPECT_EQ(step("\xED\xBF\xBF"), (Step{kReplacementCharacter, 3, false}));  // U+DFFF
  EXPECT_EQ(step("\xED\x9F\xBF"), (Step{0xD7FF, 3, true}));
}

TEST(NextUtf8, ValuesAboveU10FFFFAreInvalid) {
  EXPECT_EQ(step("\xF4\x90\x80\x80"), (Step{kReplacementCharacter, 4, false}));  // U+110000
  EXPECT_EQ(step("\xF4\xBF\xBF\xBF"), (Step{kReplacementCharacter, 4, false}));
}

TEST(NextUtf8, CutSequencesEndWhereTheyBreak) {
  EXPECT_EQ(step("\xC3"), kBad1);  // text ends
  EXPECT_EQ(step("\xC3"
                 "A"),
            kBad1);                                                      // no continuation
  EXPECT_EQ(step("\xE2\x82"), (Step{kReplacementCharacter, 2, false}));  // € cut
  EXPECT_EQ(step("\xE2\x82"
                 "A"),
            (Step{kReplacementCharacter, 2, false}));
  EXPECT_EQ(step("\xF0\x9F\x8F"), (Step{kReplacementCharacter, 3, false}));  // 🏔 cut
  EXPECT_EQ(step("\xF0\x9F\xC3\xA9"), (Step{kReplacementCharacter, 2, false}));
}

TEST(IsValidUtf8, WholeTexts) {
  EXPECT_TRUE(is_valid_utf8(""));
  EXPECT_TRUE(is_valid_utf8("Amisb\xC3\xBChl \xE2\x82\xAC \xF0\x9F\x8F\x94"));
  EXPECT_FALSE(is_valid_utf8("Amisb\xFChl"));  // Latin-1
  EXPECT_FALSE(is_valid_utf8("ab\xE2\x82"));   // cut at the end
  EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));
  EXPECT_FALSE(is_valid_utf8("\xE0\x80\x80"));
  EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));
  EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));
}

}  // namespace
}  // namespace trailray::geo
