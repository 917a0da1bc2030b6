#pragma once
// The scanner behind XmlStream, internal to the XML readers: its character classes, limits and
// state. xml_scanner.cpp is the tokenizer (markup, text, the parse loop), xml_scanner_input.cpp
// the input side (buffer refills, line counting, parts), xml_decode.cpp the decoding of
// character references and attributes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "track/io/xml_stream.hpp"

namespace trailray::track::detail {

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
inline constexpr std::array<unsigned char, 256> kClass = make_classes();
inline bool is_ws(char c) { return kClass[static_cast<unsigned char>(c)] & kWs; }
inline bool is_name_start(char c) { return kClass[static_cast<unsigned char>(c)] & kNameStart; }
inline bool is_name_char(char c) { return kClass[static_cast<unsigned char>(c)] & kName; }

// Appends `in` to `out` with character references decoded; on a bad reference returns its
// offset in `in` and sets `error`.
std::size_t decode_references(std::string_view in, std::string& out, std::string& error);

struct Attribute {
  std::size_t name, name_len, value, value_len;  // offsets into the buffer
};

class XmlScanner {
 public:
  XmlScanner(ByteSource& source, XmlHandler& handler) : src_(source), handler_(handler) { buf_.resize(kChunk); }

  // Starts inside a document (a later part): `start`'s elements are open, offsets absolute.
  void begin_part(const XmlPartStart& start);
  XmlEndState end_state();

  XmlParseOutcome run();
  SourcePosition position_of(std::int64_t absolute);
  SourcePosition event_position() { return position_of(event_abs_); }
  void stream_current_element() { stream_depth_ = depth_; }
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
  void stream_piece(std::string_view piece, std::size_t from);  // text of a streamed element
  void materialize_text();
  std::size_t before_cut_reference(std::size_t end) const;  // where text may be handed out up to
  void reset_text() {  // a new element starts, or one ended: its text is handed out
    text_.clear();
    text_view_ = {};
    text_owned_ = false;
  }
  void close_element() {  // pops the innermost open element
    if (depth_ == stream_depth_) stream_depth_ = 0;
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
  int stream_depth_ = 0;  // the depth of the element whose text is streamed; 0 when none
  std::string stream_decoded_;
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

}  // namespace trailray::track::detail
