// Decoding for the scanner: character references (the five predefined entities and numeric
// references; nothing else is ever expanded) in text and attribute values, and the attribute
// store a start tag hands to its handler.

#include <string>
#include <string_view>
#include <vector>

#include "geo/utf8.hpp"
#include "track/io/xml_scanner.hpp"

namespace trailray::track::detail {

std::size_t decode_references(std::string_view in, std::string& out, std::string& error) {
  std::size_t i = 0;
  while (i < in.size()) {
    std::size_t amp = in.find('&', i);
    if (amp == std::string_view::npos) {
      out.append(in.substr(i));
      return std::string_view::npos;
    }
    out.append(in.substr(i, amp - i));
    std::size_t semi = in.find(';', amp);
    if (semi == std::string_view::npos || semi - amp > 12) {
      error = "'&' that starts no character reference";
      return amp;
    }
    std::string_view ref = in.substr(amp + 1, semi - amp - 1);
    if (ref == "lt")
      out.push_back('<');
    else if (ref == "gt")
      out.push_back('>');
    else if (ref == "amp")
      out.push_back('&');
    else if (ref == "apos")
      out.push_back('\'');
    else if (ref == "quot")
      out.push_back('"');
    else if (ref.size() >= 2 && ref[0] == '#') {
      unsigned long c = 0;
      bool hex = ref[1] == 'x';
      std::size_t k = hex ? 2 : 1;
      if (k >= ref.size()) {
        error = "empty character reference";
        return amp;
      }
      for (; k < ref.size(); ++k) {
        char d = ref[k];
        int v = d >= '0' && d <= '9'          ? d - '0'
                : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                              : -1;
        if (v < 0 || c > 0x10FFFF) {
          error = "bad character reference '&" + std::string(ref) + ";'";
          return amp;
        }
        c = c * (hex ? 16 : 10) + static_cast<unsigned long>(v);
      }
      if (c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
        error = "character reference '&" + std::string(ref) + ";' is not a character";
        return amp;
      }
      geo::append_utf8(out, static_cast<char32_t>(c));
    } else {
      error = "undefined entity '&" + std::string(ref.substr(0, 40)) + ";'";
      return amp;
    }
    i = semi + 1;
  }
  return std::string_view::npos;
}

bool XmlScanner::collect_attributes() {
  std::size_t need = 1;
  for (const Attribute& a : attrs_) need += a.name_len + a.value_len + 2;
  attr_store_.clear();
  attr_store_.reserve(need);
  attr_ptrs_.clear();
  std::vector<std::size_t>& offsets = attr_offsets_;
  offsets.clear();
  for (const Attribute& a : attrs_) {
    offsets.push_back(attr_store_.size());
    attr_store_.append(buf_.data() + a.name, a.name_len);
    attr_store_.push_back('\0');
    offsets.push_back(attr_store_.size());
    std::string_view raw(buf_.data() + a.value, a.value_len);
    if (raw.find('&') == std::string_view::npos) {
      attr_store_.append(raw);
    } else {
      std::string why;
      std::size_t bad = decode_references(raw, attr_store_, why);
      if (bad != std::string_view::npos) {
        error(why, a.value + bad);
        return false;
      }
    }
    attr_store_.push_back('\0');
  }
  for (std::size_t off : offsets) attr_ptrs_.push_back(attr_store_.data() + off);
  attr_ptrs_.push_back(nullptr);

  return true;
}

}  // namespace trailray::track::detail
