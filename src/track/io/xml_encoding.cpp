#include "track/io/xml_encoding.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "geo/utf8.hpp"

namespace trailray::track {

namespace {

// Converts chunks of `inner` with `convert`, keeping converted bytes not yet handed out.
class ConvertingSource : public ByteSource {
 public:
  explicit ConvertingSource(ByteSource& inner) : ByteSource(inner.path(), inner.display_name()), inner_(inner) {}

  std::ptrdiff_t read(char* out, std::size_t max) override {
    while (pending_pos_ >= pending_.size()) {
      pending_.clear();
      pending_pos_ = 0;
      char chunk[65536];
      std::ptrdiff_t n = inner_.next(chunk, sizeof chunk);
      if (n < 0) return -1;
      if (n == 0) {
        flush(pending_);
        if (pending_.empty()) return 0;
        break;
      }
      convert(chunk, static_cast<std::size_t>(n), pending_);
    }
    std::size_t k = std::min(max, pending_.size() - pending_pos_);
    std::memcpy(out, pending_.data() + pending_pos_, k);
    pending_pos_ += k;
    return static_cast<std::ptrdiff_t>(k);
  }
  std::string error() const override { return inner_.error(); }

 protected:
  virtual void convert(const char* in, std::size_t n, std::string& out) = 0;
  virtual void flush(std::string&) {}

 private:
  ByteSource& inner_;
  std::string pending_;
  std::size_t pending_pos_ = 0;
};

class Utf16Source final : public ConvertingSource {
 public:
  Utf16Source(ByteSource& inner, bool big_endian) : ConvertingSource(inner), big_(big_endian) {}

 protected:
  void convert(const char* in, std::size_t n, std::string& out) override {
    for (std::size_t i = 0; i < n; ++i) {
      bytes_[have_++] = static_cast<unsigned char>(in[i]);
      if (have_ < 2) continue;
      have_ = 0;
      char32_t unit = big_ ? (bytes_[0] << 8 | bytes_[1]) : (bytes_[1] << 8 | bytes_[0]);
      if (high_) {
        if (unit >= 0xDC00 && unit <= 0xDFFF) {
          geo::append_utf8(out, 0x10000 + ((high_ - 0xD800) << 10) + (unit - 0xDC00));
          high_ = 0;
          continue;
        }
        geo::append_utf8(out, 0xFFFD);  // unpaired high surrogate
        high_ = 0;
      }
      if (unit >= 0xD800 && unit <= 0xDBFF)
        high_ = unit;
      else if (unit >= 0xDC00 && unit <= 0xDFFF)
        geo::append_utf8(out, 0xFFFD);
      else
        geo::append_utf8(out, unit);
    }
  }
  void flush(std::string& out) override {
    if (high_ || have_) geo::append_utf8(out, 0xFFFD);
    high_ = 0;
    have_ = 0;
  }

 private:
  bool big_;
  unsigned char bytes_[2] = {0, 0};
  int have_ = 0;
  char32_t high_ = 0;
};

// ISO-8859-1 (and -15) and Windows-1252: one byte per character.
class SingleByteSource final : public ConvertingSource {
 public:
  SingleByteSource(ByteSource& inner, bool cp1252, bool latin9)
      : ConvertingSource(inner), cp1252_(cp1252), latin9_(latin9) {}

 protected:
  void convert(const char* in, std::size_t n, std::string& out) override {
    static constexpr char16_t kCp1252[32] = {0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,
                                             0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD,
                                             0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
                                             0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};
    out.reserve(out.size() + n + n / 8);
    for (std::size_t i = 0; i < n; ++i) {
      unsigned char b = static_cast<unsigned char>(in[i]);
      char32_t c = b;
      if (cp1252_ && b >= 0x80 && b < 0xA0) c = kCp1252[b - 0x80];
      if (latin9_) {
        switch (b) {  // the eight places where ISO-8859-15 differs from -1
          case 0xA4:
            c = 0x20AC;
            break;
          case 0xA6:
            c = 0x0160;
            break;
          case 0xA8:
            c = 0x0161;
            break;
          case 0xB4:
            c = 0x017D;
            break;
          case 0xB8:
            c = 0x017E;
            break;
          case 0xBC:
            c = 0x0152;
            break;
          case 0xBD:
            c = 0x0153;
            break;
          case 0xBE:
            c = 0x0178;
            break;
          default:
            break;
        }
      }
      geo::append_utf8(out, c);
    }
  }

 private:
  bool cp1252_, latin9_;
};

// The encoding="..." of an XML declaration at the start of `head`, lower-cased ("" if none).
std::string declared_encoding(std::string_view head) {
  if (head.substr(0, 5) != "<?xml") return "";
  auto end = head.find("?>");
  std::string_view decl = head.substr(0, end);
  auto at = decl.find("encoding");
  if (at == std::string_view::npos) return "";
  std::size_t p = at + 8;
  while (p < decl.size() && (decl[p] == ' ' || decl[p] == '=' || decl[p] == '\t' || decl[p] == '\r' || decl[p] == '\n'))
    ++p;
  if (p >= decl.size() || (decl[p] != '"' && decl[p] != '\'')) return "";
  char q = decl[p++];
  std::string enc;
  while (p < decl.size() && decl[p] != q && enc.size() < 40)
    enc.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(decl[p++]))));
  return enc;
}

}  // namespace

namespace {

enum class Encoding { Utf8, Utf16Le, Utf16BomLe, Utf16Be, Utf16BomBe, Latin1, Latin9, Cp1252, Unsupported };

// How a document starting with `head` is read; `declared` is its XML declaration's encoding.
Encoding classify(std::string_view head, std::string& declared) {
  auto byte = [&](std::size_t i) { return i < head.size() ? static_cast<unsigned char>(head[i]) : 0u; };
  if (byte(0) == 0xFF && byte(1) == 0xFE) return Encoding::Utf16BomLe;
  if (byte(0) == 0xFE && byte(1) == 0xFF) return Encoding::Utf16BomBe;
  if (byte(0) == '<' && byte(1) == 0 && byte(2) == '?' && byte(3) == 0) return Encoding::Utf16Le;
  if (byte(0) == 0 && byte(1) == '<' && byte(2) == 0 && byte(3) == '?') return Encoding::Utf16Be;
  if (head.substr(0, 3) == "\xEF\xBB\xBF") return Encoding::Utf8;  // UTF-8 BOM: the scanner skips it
  declared = declared_encoding(head);
  const std::string& enc = declared;
  if (enc.empty() || enc == "utf-8" || enc == "utf8" || enc == "us-ascii" || enc == "ascii") return Encoding::Utf8;
  if (enc == "utf-16" || enc == "utf-16le" || enc == "utf-16be") return Encoding::Utf8;  // declared, yet 8-bit
  if (enc == "iso-8859-1" || enc == "latin1" || enc == "latin-1" || enc == "iso8859-1" || enc == "l1")
    return Encoding::Latin1;
  if (enc == "iso-8859-15" || enc == "latin9" || enc == "latin-9") return Encoding::Latin9;
  if (enc == "windows-1252" || enc == "cp1252") return Encoding::Cp1252;
  return Encoding::Unsupported;
}

}  // namespace

bool is_utf8_document(std::string_view head) {
  std::string declared;
  return classify(head, declared) == Encoding::Utf8;
}

std::unique_ptr<ByteSource> utf8_view(ByteSource& source, std::string& error) {
  std::string declared;
  const Encoding encoding = classify(source.peek(512), declared);
  char bom[2];
  switch (encoding) {
    case Encoding::Utf8:
      return nullptr;
    case Encoding::Utf16BomLe:
      source.next(bom, 2);
      return std::make_unique<Utf16Source>(source, false);
    case Encoding::Utf16BomBe:
      source.next(bom, 2);
      return std::make_unique<Utf16Source>(source, true);
    case Encoding::Utf16Le:
      return std::make_unique<Utf16Source>(source, false);
    case Encoding::Utf16Be:
      return std::make_unique<Utf16Source>(source, true);
    case Encoding::Latin1:
      return std::make_unique<SingleByteSource>(source, false, false);
    case Encoding::Latin9:
      return std::make_unique<SingleByteSource>(source, false, true);
    case Encoding::Cp1252:
      return std::make_unique<SingleByteSource>(source, true, false);
    case Encoding::Unsupported:
      break;
  }
  error = "unsupported XML encoding '" + declared + "' (UTF-8, UTF-16, ISO-8859-1/15 and Windows-1252 are read)";
  return nullptr;
}

}  // namespace trailray::track
