#pragma once
// UTF-8 encoding and decoding of code points (RFC 3629). Not geodesy: it lives in geo/ because geo is the one layer
// that both track/ (XML character references, UTF-16 documents) and render/ (text on images) build on.

#include <cstddef>
#include <string>
#include <string_view>

namespace trailray::geo {

inline constexpr char32_t kReplacementCharacter = 0xFFFD;

// Appends `c` to `out` as UTF-8; a surrogate or a value above U+10FFFF, which UTF-8 cannot
// carry, becomes U+FFFD.
inline void append_utf8(std::string& out, char32_t c) {
  if (c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = kReplacementCharacter;
  if (c < 0x80) {
    out.push_back(static_cast<char>(c));
  } else if (c < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (c >> 6)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  } else if (c < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (c >> 12)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (c >> 18)));
    out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  }
}

// One step of decoding: the code point at the start of some text and its length in bytes.
struct Utf8Step {
  char32_t code_point = kReplacementCharacter;  // U+FFFD when not valid
  std::size_t length = 1;                       // bytes used, at least 1 (resume after them)
  bool valid = false;
};

// Decodes the code point that `s` (not empty) starts with. Valid: the shortest form of a Unicode
// scalar value (no overlong forms, no surrogates, nothing above U+10FFFF). Not valid: a byte that
// cannot start a sequence (a continuation byte, C0, C1, F5..FF) has length 1; a sequence cut
// short (a byte that is no continuation, or the end of the text) has the length up to where it
// breaks; a complete sequence that is overlong, a surrogate or above U+10FFFF has its length.
// A decoder that replaces what is broken by U+FFFD resumes after `length`; one that replaces
// byte by byte resumes after 1.
inline Utf8Step next_utf8(std::string_view s) {
  const auto lead = static_cast<unsigned char>(s[0]);
  if (lead < 0x80) return Utf8Step{lead, 1, true};
  const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                             : lead >= 0xE0 && lead <= 0xEF ? 3
                             : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                            : 0;
  if (length == 0) return Utf8Step{};
  char32_t value = lead & (0x7F >> length);
  std::size_t used = 1;
  for (; used < length && used < s.size(); ++used) {
    const auto next = static_cast<unsigned char>(s[used]);
    if ((next & 0xC0) != 0x80) break;
    value = (value << 6) | (next & 0x3F);
  }
  const bool valid = used == length && !(length == 3 && value < 0x800) && !(length == 4 && value < 0x10000) &&
                     !(value >= 0xD800 && value <= 0xDFFF) && value <= 0x10FFFF;
  return valid ? Utf8Step{value, length, true} : Utf8Step{kReplacementCharacter, used, false};
}

// Whether all of `s` is valid UTF-8 (next_utf8 valid at every step).
inline bool is_valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const Utf8Step step = next_utf8(s.substr(i));
    if (!step.valid) return false;
    i += step.length;
  }
  return true;
}

}  // namespace trailray::geo
