// A streaming XML scanner for track files, written for speed: GPX and TCX are large,
// regular documents of small elements, and the benchmark target (10x gpsbabel, 40x gpxpy on a
// 100k-point GPX) is out of reach of expat (about 140 MB/s here, most of the budget). This
// scanner handles what XML 1.0 documents of that kind contain: elements, attributes in either
// quotes, text with the five predefined and numeric character references, CDATA, comments,
// processing instructions and a DOCTYPE. It refuses DTD entity declarations (so no entity is
// ever expanded), names each error's line and column, and keeps memory bounded by the largest
// single piece of markup. Text is handed out without copying when it is one piece.

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>

#include "track/io/xml_scanner.hpp"

namespace trailray::track::detail {

void XmlScanner::materialize_text() {
  if (!text_owned_) {
    text_.assign(text_view_);
    text_owned_ = true;
  }
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
  if (depth_ == stream_depth_) {
    stream_piece(piece, from);
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

void XmlScanner::stream_piece(std::string_view piece, std::size_t from) {
  if (piece.find('&') == std::string_view::npos) {
    handler_.text_piece(piece);
    return;
  }
  stream_decoded_.clear();
  std::string why;
  std::size_t bad = decode_references(piece, stream_decoded_, why);
  if (bad != std::string_view::npos) {
    error(why, from + bad);
    return;
  }
  handler_.text_piece(stream_decoded_);
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
    if (depth_ == stream_depth_) {
      handler_.text_piece(rest.substr(9, close - 9));
    } else {
      materialize_text();
      text_.append(rest.substr(9, close - 9));
      if (text_.size() > XmlStream::kMaxValueBytes) error("text value longer than 1 MiB", p);
    }
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

std::size_t XmlScanner::before_cut_reference(std::size_t end) const {
  // A character reference is at most 12 bytes after its '&' (decode_references' limit): one
  // that the buffer's end cuts waits for the rest of the input.
  if (eof_) return end;
  const std::size_t tail = end - std::min<std::size_t>(end - pos_, 12);
  const void* amp = memrchr(buf_.data() + tail, '&', end - tail);
  if (!amp) return end;
  const std::size_t at = static_cast<std::size_t>(static_cast<const char*>(amp) - buf_.data());
  return std::memchr(buf_.data() + at, ';', end - at) ? end : at;
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
      if (!lt) stop_at = before_cut_reference(stop_at);
      if (stop_at > pos_) {
        text(pos_, stop_at);
        pos_ = stop_at;
      } else if (!fill(pos_)) {
        // The input ends inside a reference: a cut file (inside the document) or junk after it.
        if (depth_ == 0) text(pos_, end_);
        pos_ = end_;
      }
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

}  // namespace trailray::track::detail
