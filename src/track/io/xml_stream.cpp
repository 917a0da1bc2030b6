// A streaming XML scanner for track files, written for speed: GPX and TCX are large,
// regular documents of small elements, and the benchmark target (10x gpsbabel, 40x gpxpy on a
// 100k-point GPX) is out of reach of expat (about 140 MB/s here, most of the budget). This
// scanner handles what XML 1.0 documents of that kind contain: elements, attributes in either
// quotes, text with the five predefined and numeric character references, CDATA, comments,
// processing instructions and a DOCTYPE. It refuses DTD entity declarations (so no entity is
// ever expanded), names each error's line and column, and keeps memory bounded by the largest
// single piece of markup. Text is handed out without copying when it is one piece.

#include "track/io/xml_stream.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "geo/utf8.hpp"
#include "track/io/xml_encoding.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kChunk = 1 << 20;
constexpr std::size_t kMaxToken = XmlStream::kMaxValueBytes + (64 << 10);

// Character classes by table: the scanner asks these for every byte of every name.
enum : unsigned char { kWs = 1, kNameStart = 2, kName = 4 };
constexpr std::array<unsigned char, 256> make_classes() {
  std::array<unsigned char, 256> t{};
  for (int c = 0; c < 256; ++c) {
    const bool start = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' || c >= 0x80;
    const bool name = start || (c >= '0' && c <= '9') || c == '-' || c == '.';
    t[static_cast<std::size_t>(c)] = static_cast<unsigned char>(
        (start ? kNameStart : 0) | (name ? kName : 0) | (c == ' ' || c == '\n' || c == '\t' || c == '\r' ? kWs : 0));
  }
  return t;
}
constexpr std::array<unsigned char, 256> kClass = make_classes();
inline bool is_ws(char c) { return kClass[static_cast<unsigned char>(c)] & kWs; }
inline bool is_name_start(char c) { return kClass[static_cast<unsigned char>(c)] & kNameStart; }
inline bool is_name_char(char c) { return kClass[static_cast<unsigned char>(c)] & kName; }

// Appends `in` to `out` with character references decoded; on a bad reference returns its
// offset in `in` and sets `error`.
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

struct Attribute {
  std::size_t name, name_len, value, value_len;  // offsets into the buffer
};

}  // namespace

class XmlScanner {
 public:
  XmlScanner(ByteSource& source, XmlHandler& handler) : src_(source), handler_(handler) { buf_.resize(kChunk); }

  // Starts inside a document (a later part): `start`'s elements are open, offsets absolute.
  void begin_part(const XmlPartStart& start);
  XmlEndState end_state();

  XmlParseOutcome run();
  SourcePosition position_of(std::int64_t absolute);
  SourcePosition event_position() { return position_of(event_abs_); }
  void stop(std::string message, std::int64_t absolute) {
    if (stopped_) return;
    stopped_ = true;
    out_.kind = XmlParseOutcome::Kind::Error;
    out_.message = std::move(message);
    out_.position = position_of(absolute);
  }

 private:
  enum class Step { Done, NeedMore };

  std::int64_t abs(std::size_t i) const { return base_ + static_cast<std::int64_t>(i); }
  bool fill(std::size_t keep_from);
  Step markup(std::size_t p);
  Step start_tag(std::size_t p);
  Step end_tag(std::size_t p);
  Step special(std::size_t p);
  bool collect_attributes();  // attrs_ -> attr_store_/attr_ptrs_; false on a bad reference
  void text(std::size_t from, std::size_t to);
  void materialize_text();
  void reset_text() {  // a new element starts, or one ended: its text is handed out
    text_.clear();
    text_view_ = {};
    text_owned_ = false;
  }
  void close_element() {  // pops the innermost open element
    names_.resize(starts_.back());
    starts_.pop_back();
    locals_.pop_back();
    if (--depth_ == 0) root_closed_ = true;
  }
  void error(const std::string& what, std::size_t at) {
    stop((saw_root_ ? "malformed XML: " : "not an XML document: ") + what, abs(at));
  }

  ByteSource& src_;
  XmlHandler& handler_;
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
  std::int64_t base_ = 0;  // absolute offset of buf_[0]
  bool eof_ = false;
  bool read_error_ = false;
  bool part_ = false;  // a later part of a document: no BOM, elements already open
  bool cut_inside_markup_ = false;

  // Line counting, lazily: newlines are counted up to counted_ when a position is asked for.
  std::int64_t counted_ = 0, line_ = 1, line_start_ = 0;

  std::int64_t event_abs_ = 0;
  bool stopped_ = false;
  bool saw_root_ = false;
  bool root_closed_ = false;
  int depth_ = 0;
  std::string names_;                  // open element names, concatenated
  std::vector<std::uint32_t> starts_;  // where each open name starts in names_
  std::vector<std::uint32_t> locals_;  // where its local part (after any prefix) starts
  std::string text_;                   // owned text of the current element
  std::string_view text_view_;         // or a view into buf_ when it is one piece
  bool text_owned_ = false;
  std::vector<Attribute> attrs_;
  std::string attr_store_;
  std::vector<const char*> attr_ptrs_;
  std::vector<std::size_t> attr_offsets_;
  XmlParseOutcome out_;
};

namespace {
XmlScanner* scanner_of(void* context) { return static_cast<XmlScanner*>(context); }
}  // namespace

SourcePosition XmlHandler::position() const {
  return context_ ? scanner_of(context_)->event_position() : SourcePosition{};
}

void XmlHandler::fail(std::string message) {
  if (context_) {
    XmlScanner* s = scanner_of(context_);
    s->stop(std::move(message), s->event_position().byte_offset);
  }
}

const char* xml_attribute(const char** attrs, std::string_view local_name) {
  for (const char** a = attrs; *a; a += 2)
    if (xml_local_name(a[0]) == local_name) return a[1];
  return nullptr;
}

std::string_view xml_local_name(std::string_view q) {
  auto colon = q.rfind(':');
  return colon == std::string_view::npos ? q : q.substr(colon + 1);
}

SourcePosition XmlScanner::position_of(std::int64_t absolute) {
  // Count newlines between counted_ and `absolute`, as far as they are still in the buffer.
  std::int64_t from = std::max(counted_, base_);
  std::int64_t to = std::min(absolute, abs(end_));
  if (from < to) {
    const char* first = buf_.data() + (from - base_);
    const std::size_t len = static_cast<std::size_t>(to - from);
    // Counted in blocks of 255 with a byte-sized sum, which the compiler vectorises (a plain
    // std::count is not); memrchr finds where the last line starts.
    std::int64_t lines = 0;
    for (std::size_t at = 0; at < len;) {
      const std::size_t block = std::min<std::size_t>(255, len - at);
      unsigned char in_block = 0;
      for (std::size_t k = 0; k < block; ++k) in_block = static_cast<unsigned char>(in_block + (first[at + k] == '\n'));
      lines += in_block;
      at += block;
    }
    if (lines > 0) {
      line_ += lines;
      const char* last_nl = static_cast<const char*>(memrchr(first, '\n', len));
      line_start_ = from + (last_nl - first) + 1;
    }
  }
  counted_ = std::max(counted_, to);
  SourcePosition p;
  p.line = line_;
  p.column = std::max<std::int64_t>(1, absolute - line_start_ + 1);
  p.byte_offset = absolute;
  return p;
}

void XmlScanner::materialize_text() {
  if (!text_owned_) {
    text_.assign(text_view_);
    text_owned_ = true;
  }
}

bool XmlScanner::fill(std::size_t keep_from) {
  if (eof_) return false;
  position_of(abs(keep_from));  // count the lines we are about to drop
  if (!text_owned_ && !text_view_.empty()) materialize_text();
  if (keep_from > 0) {
    std::memmove(buf_.data(), buf_.data() + keep_from, end_ - keep_from);
    base_ += static_cast<std::int64_t>(keep_from);
    end_ -= keep_from;
    pos_ -= std::min(pos_, keep_from);
  }
  if (end_ == buf_.size()) buf_.resize(buf_.size() * 2);
  std::ptrdiff_t n = src_.next(buf_.data() + end_, buf_.size() - end_);
  if (n < 0) {
    read_error_ = true;
    eof_ = true;
    return false;
  }
  if (n == 0) {
    eof_ = true;
    return false;
  }
  end_ += static_cast<std::size_t>(n);
  return true;
}

void XmlScanner::text(std::size_t from, std::size_t to) {
  std::string_view piece(buf_.data() + from, to - from);
  if (depth_ == 0) {
    for (std::size_t i = 0; i < piece.size(); ++i)
      if (!is_ws(piece[i])) {
        error(root_closed_ ? "junk after document element" : "syntax error", from + i);
        return;
      }
    return;
  }
  if (piece.find('&') != std::string_view::npos) {
    materialize_text();
    std::string why;
    std::size_t bad = decode_references(piece, text_, why);
    if (bad != std::string_view::npos) {
      error(why, from + bad);
      return;
    }
  } else if (!text_owned_ && text_view_.empty()) {
    text_view_ = piece;
  } else {
    materialize_text();
    text_.append(piece);
  }
  if (text_owned_ && text_.size() > XmlStream::kMaxValueBytes) error("text value longer than 1 MiB", to);
}

XmlScanner::Step XmlScanner::special(std::size_t p) {
  auto rest = std::string_view(buf_.data() + p, end_ - p);
  auto need = [&](std::string_view prefix) {
    return rest.size() < prefix.size() && prefix.substr(0, rest.size()) == rest;
  };
  if (rest.substr(0, 4) == "<!--") {
    auto close = rest.find("-->", 4);
    if (close == std::string_view::npos) return Step::NeedMore;
    pos_ = p + close + 3;
    return Step::Done;
  }
  if (rest.substr(0, 9) == "<![CDATA[") {
    auto close = rest.find("]]>", 9);
    if (close == std::string_view::npos) return Step::NeedMore;
    if (depth_ == 0) {
      error("CDATA outside the document element", p);
      return Step::Done;
    }
    materialize_text();
    text_.append(rest.substr(9, close - 9));
    if (text_.size() > XmlStream::kMaxValueBytes) error("text value longer than 1 MiB", p);
    pos_ = p + close + 3;
    return Step::Done;
  }
  if (rest.substr(0, 9) == "<!DOCTYPE") {
    // Skip to the closing '>', past an internal subset in brackets; refuse entity declarations.
    std::size_t i = 9;
    char quote = 0;
    int bracket = 0;
    for (; i < rest.size(); ++i) {
      char c = rest[i];
      if (quote) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '[') {
        ++bracket;
      } else if (c == ']') {
        --bracket;
      } else if (c == '<' && bracket > 0 && rest.substr(i, 8) == "<!ENTITY") {
        std::size_t n = i + 8;
        while (n < rest.size() && is_ws(rest[n])) ++n;
        std::size_t e = n;
        while (e < rest.size() && (is_name_char(rest[e]) || rest[e] == '%')) ++e;
        if (e == rest.size()) return Step::NeedMore;
        stop("DTD entity declaration '" + std::string(rest.substr(n, std::min<std::size_t>(e - n, 40))) +
                 "' rejected (entity expansion is not allowed in track files)",
             abs(p + i));
        return Step::Done;
      } else if (c == '>' && bracket <= 0) {
        break;
      }
    }
    if (i >= rest.size()) return Step::NeedMore;
    pos_ = p + i + 1;
    return Step::Done;
  }
  if (need("<!--") || need("<![CDATA[") || need("<!DOCTYPE")) return Step::NeedMore;
  error("syntax error", p);
  return Step::Done;
}

XmlScanner::Step XmlScanner::end_tag(std::size_t p) {
  std::size_t i = p + 2, n = i;
  while (n < end_ && is_name_char(buf_[n])) ++n;
  std::size_t name_end = n;
  while (n < end_ && is_ws(buf_[n])) ++n;
  if (n >= end_) return Step::NeedMore;
  if (name_end == i || buf_[n] != '>' || !is_name_start(buf_[i])) {
    error("not well-formed (invalid token)", name_end == i ? i : n);
    return Step::Done;
  }
  std::string_view name(buf_.data() + i, name_end - i);
  if (depth_ == 0 || std::string_view(names_).substr(starts_.back()) != name) {
    error("mismatched tag", i);
    return Step::Done;
  }
  event_abs_ = abs(p);
  std::string_view body = text_owned_ ? std::string_view(text_) : text_view_;
  handler_.end_element(std::string_view(names_).substr(locals_.back()), body);
  reset_text();
  close_element();
  pos_ = n + 1;
  return Step::Done;
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

XmlScanner::Step XmlScanner::start_tag(std::size_t p) {
  std::size_t i = p + 1, n = i;
  while (n < end_ && is_name_char(buf_[n])) ++n;
  if (n >= end_) return Step::NeedMore;
  std::size_t name_end = n;
  attrs_.clear();
  bool empty = false;
  for (;;) {
    std::size_t ws = n;
    while (n < end_ && is_ws(buf_[n])) ++n;
    if (n >= end_) return Step::NeedMore;
    char c = buf_[n];
    if (c == '>') break;
    if (c == '/') {
      if (n + 1 >= end_) return Step::NeedMore;
      if (buf_[n + 1] != '>') {
        error("not well-formed (invalid token)", n);
        return Step::Done;
      }
      empty = true;
      ++n;
      break;
    }
    if (n == ws || !is_name_start(c)) {
      error("not well-formed (invalid token)", n);
      return Step::Done;
    }
    Attribute a{};
    a.name = n;
    while (n < end_ && is_name_char(buf_[n])) ++n;
    a.name_len = n - a.name;
    while (n < end_ && is_ws(buf_[n])) ++n;
    if (n >= end_) return Step::NeedMore;
    if (buf_[n] != '=') {
      error("not well-formed (invalid token)", n);
      return Step::Done;
    }
    ++n;
    while (n < end_ && is_ws(buf_[n])) ++n;
    if (n >= end_) return Step::NeedMore;
    char q = buf_[n];
    if (q != '"' && q != '\'') {
      error("not well-formed (invalid token)", n);
      return Step::Done;
    }
    const char* close = static_cast<const char*>(std::memchr(buf_.data() + n + 1, q, end_ - n - 1));
    if (!close) {
      if (end_ - n > XmlStream::kMaxValueBytes) {
        stop("attribute '" + std::string(buf_.data() + a.name, std::min<std::size_t>(a.name_len, 40)) +
                 "' longer than 1 MiB",
             abs(p));
        return Step::Done;
      }
      return Step::NeedMore;
    }
    a.value = n + 1;
    a.value_len = static_cast<std::size_t>(close - (buf_.data() + n + 1));
    if (a.value_len > XmlStream::kMaxValueBytes) {
      stop("attribute '" + std::string(buf_.data() + a.name, std::min<std::size_t>(a.name_len, 40)) +
               "' longer than 1 MiB",
           abs(p));
      return Step::Done;
    }
    if (std::memchr(buf_.data() + a.value, '<', a.value_len)) {
      error("not well-formed ('<' in an attribute value)", a.value);
      return Step::Done;
    }
    attrs_.push_back(a);
    n = a.value + a.value_len + 1;
    if (n < end_ && !is_ws(buf_[n]) && buf_[n] != '>' && buf_[n] != '/') {
      error("not well-formed (invalid token)", n);
      return Step::Done;
    }
  }
  // The whole tag is in the buffer: [p, n].
  if (root_closed_) {
    error("junk after document element", p);
    return Step::Done;
  }
  if (depth_ >= XmlStream::kMaxDepth) {
    stop("elements nested deeper than " + std::to_string(XmlStream::kMaxDepth) + " levels", abs(p));
    return Step::Done;
  }
  saw_root_ = true;
  std::string_view name(buf_.data() + i, name_end - i);

  // Attribute names and decoded values, NUL-terminated, in one store that never reallocates.
  static const char* const kNoAttributes[] = {nullptr};
  const char** attributes = const_cast<const char**>(kNoAttributes);
  if (!attrs_.empty()) {
    if (!collect_attributes()) return Step::Done;
    attributes = attr_ptrs_.data();
  }

  event_abs_ = abs(p);
  std::string_view local = xml_local_name(name);
  starts_.push_back(static_cast<std::uint32_t>(names_.size()));
  locals_.push_back(static_cast<std::uint32_t>(names_.size() + (local.data() - name.data())));
  names_.append(name);
  ++depth_;
  reset_text();
  handler_.start_element(local, attributes);
  if (empty && !stopped_) {
    handler_.end_element(local, {});
    close_element();
  }
  pos_ = n + 1;
  return Step::Done;
}

XmlScanner::Step XmlScanner::markup(std::size_t p) {
  if (p + 1 >= end_) return Step::NeedMore;
  char c = buf_[p + 1];
  if (c == '/') return end_tag(p);
  if (c == '!') return special(p);
  if (c == '?') {
    const char* q = static_cast<const char*>(std::memchr(buf_.data() + p + 2, '>', end_ - p - 2));
    while (q && q[-1] != '?') q = static_cast<const char*>(std::memchr(q + 1, '>', buf_.data() + end_ - q - 1));
    if (!q) return Step::NeedMore;
    pos_ = static_cast<std::size_t>(q - buf_.data()) + 1;
    return Step::Done;
  }
  if (!is_name_start(c)) {
    error(saw_root_ ? "not well-formed (invalid token)" : "syntax error", p + 1);
    return Step::Done;
  }
  return start_tag(p);
}

void XmlScanner::begin_part(const XmlPartStart& start) {
  part_ = true;
  base_ = counted_ = line_start_ = start.byte_offset;
  for (const std::string& name : start.open_elements) {
    starts_.push_back(static_cast<std::uint32_t>(names_.size()));
    locals_.push_back(static_cast<std::uint32_t>(names_.size() + name.size() - xml_local_name(name).size()));
    names_ += name;
  }
  depth_ = static_cast<int>(start.open_elements.size());
  saw_root_ = depth_ > 0;
}

XmlEndState XmlScanner::end_state() {
  XmlEndState e;
  for (std::size_t k = 0; k < starts_.size(); ++k) {
    const std::size_t until = k + 1 < starts_.size() ? starts_[k + 1] : names_.size();
    e.open_elements.emplace_back(names_, starts_[k], until - starts_[k]);
  }
  e.inside_markup = cut_inside_markup_;
  e.end = position_of(abs(end_));
  return e;
}

XmlParseOutcome XmlScanner::run() {
  fill(0);
  if (!part_ && end_ >= 3 && std::memcmp(buf_.data(), "\xEF\xBB\xBF", 3) == 0) pos_ = 3;
  bool& cut_inside_markup = cut_inside_markup_;
  while (!stopped_) {
    if (pos_ >= end_) {
      if (!fill(pos_)) break;
      continue;
    }
    if (buf_[pos_] != '<') {
      const char* lt = static_cast<const char*>(std::memchr(buf_.data() + pos_, '<', end_ - pos_));
      std::size_t stop_at = lt ? static_cast<std::size_t>(lt - buf_.data()) : end_;
      text(pos_, stop_at);
      pos_ = stop_at;
      continue;
    }
    if (markup(pos_) == Step::Done) continue;
    // The markup at pos_ is not complete in the buffer.
    if (end_ - pos_ > kMaxToken) {
      stop("markup longer than 1 MiB", abs(pos_));
      break;
    }
    std::size_t before = end_ - pos_;
    if (!fill(pos_) && end_ - pos_ == before) {
      cut_inside_markup = true;
      break;
    }
  }
  out_.saw_root = saw_root_;
  if (stopped_) return out_;
  if (read_error_) {
    out_.kind = XmlParseOutcome::Kind::Error;
    out_.message = "read error: " + src_.error();
    out_.position = position_of(abs(end_));
    return out_;
  }
  if (!saw_root_) {
    out_.kind = XmlParseOutcome::Kind::Error;
    out_.message = cut_inside_markup ? "not an XML document: unclosed token" : "not an XML document: no element found";
    out_.position = position_of(abs(cut_inside_markup ? pos_ : end_));
    return out_;
  }
  if (depth_ > 0 || cut_inside_markup) {
    out_.kind = XmlParseOutcome::Kind::Truncated;
    out_.message = "file ends inside the document (cut short?)";
    out_.position = position_of(abs(end_));
    return out_;
  }
  out_.kind = XmlParseOutcome::Kind::Complete;
  return out_;
}

void record_xml_outcome(const XmlParseOutcome& outcome, std::size_t complete_points, ReadResult& result,
                        WarningCollector& warnings) {
  switch (outcome.kind) {
    case XmlParseOutcome::Kind::Complete:
      break;
    case XmlParseOutcome::Kind::Truncated:
      warnings.add_single(outcome.position, outcome.message + "; kept the " + std::to_string(complete_points) +
                                                " complete points before the cut");
      break;
    case XmlParseOutcome::Kind::Error:
      result.error = Diagnostic{warnings.file(), outcome.position, outcome.message};
      break;
  }
}

XmlParseOutcome XmlStream::parse_part(ByteSource& source, XmlHandler& handler, const XmlPartStart* start,
                                      XmlEndState* end) {
  XmlScanner scanner(source, handler);
  if (start) scanner.begin_part(*start);
  handler.context_ = &scanner;
  XmlParseOutcome out = scanner.run();
  handler.context_ = nullptr;
  if (end) *end = scanner.end_state();
  return out;
}

XmlParseOutcome XmlStream::parse(ByteSource& source, XmlHandler& handler) {
  std::string encoding_error;
  std::unique_ptr<ByteSource> utf8 = utf8_view(source, encoding_error);
  if (!encoding_error.empty()) {
    XmlParseOutcome out;
    out.kind = XmlParseOutcome::Kind::Error;
    out.message = encoding_error;
    out.position = {1, 1, 0};
    return out;
  }
  XmlScanner scanner(utf8 ? *utf8 : source, handler);
  handler.context_ = &scanner;
  XmlParseOutcome out = scanner.run();
  handler.context_ = nullptr;
  return out;
}

}  // namespace trailray::track
