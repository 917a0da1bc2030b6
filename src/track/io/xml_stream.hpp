#pragma once
// A streaming XML reader for the GPX and TCX readers (a scanner of our own, see
// xml_scanner.cpp for why): memory stays bounded by the largest single piece of markup, not the
// file, and every event knows its line and column. Input may be UTF-8, UTF-16, ISO-8859-1/15 or
// Windows-1252 (xml_encoding.hpp); handlers always see UTF-8.
//
// Element names are given without their namespace prefix ("gpxtpx:hr" -> "hr"), so default,
// prefixed and missing namespaces read alike. Hardened against hostile input: any DTD entity
// declaration is rejected (no entity expansion at all), nesting deeper than kMaxDepth and
// values longer than kMaxValueBytes are errors.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/io/byte_source.hpp"

namespace trailray::track {

class XmlHandler {
 public:
  virtual ~XmlHandler() = default;
  // `attrs` is a null-terminated name/value array (names with their prefix, values decoded).
  virtual void start_element(std::string_view local_name, const char** attrs) = 0;
  // `text` is the character data since the element (or its last child) started, untrimmed.
  virtual void end_element(std::string_view local_name, std::string_view text) = 0;
  // A piece of the text of an element that stream_text() was called for, references decoded.
  // Pieces split the text anywhere, even inside a number or a UTF-8 character.
  virtual void text_piece(std::string_view /*piece*/) {}

  // Position of the current event (inside a callback), for warnings.
  SourcePosition position() const;
  // Stops parsing with an error at the current position (inside a callback).
  void fail(std::string message);
  // Inside start_element: the text of the element just started (its own, not its children's)
  // goes to text_piece() as it is read, and end_element gets none. For values with no bound on
  // their length, such as KML's <coordinates>: not collected, they are not limited to
  // XmlStream::kMaxValueBytes.
  void stream_text();

 private:
  friend class XmlStream;
  void* context_ = nullptr;  // the running scanner
};

// Value of the attribute with this local name, nullptr if absent.
const char* xml_attribute(const char** attrs, std::string_view local_name);
// "prefix:name" -> "name".
std::string_view xml_local_name(std::string_view qualified);

struct XmlParseOutcome {
  enum class Kind {
    Complete,   // the document ended properly
    Truncated,  // the input ended inside the document (a cut file): events so far are valid
    Error       // malformed, hostile or unreadable
  } kind = Kind::Complete;
  SourcePosition position;  // where the error or the cut was found
  std::string message;      // what was wrong (empty when Complete)
  bool saw_root = false;    // at least one element started
};

// The common end of the XML readers: a cut file keeps its `complete_points` with a warning
// naming the cut, an error becomes the result's error.
void record_xml_outcome(const XmlParseOutcome& outcome, std::size_t complete_points, ReadResult& result,
                        WarningCollector& warnings);

// For parsing a big document in parts: where a later part starts, with the elements that are
// open there (qualified names, outermost first). Its positions come out with absolute byte
// offsets, and lines and columns counted from the part's first byte (line 1, column 1).
struct XmlPartStart {
  std::int64_t byte_offset = 0;
  std::vector<std::string> open_elements;
};

// The state a parse ended in, for joining it to the next part.
struct XmlEndState {
  std::vector<std::string> open_elements;  // qualified names, outermost first
  bool inside_markup = false;              // the input ended inside a tag, comment, ...
  SourcePosition end;                      // the position just past the last byte
};

class XmlStream {
 public:
  static constexpr int kMaxDepth = 256;
  static constexpr std::size_t kMaxValueBytes = 1 << 20;

  // Parses the whole source, calling `handler`. Never throws.
  static XmlParseOutcome parse(ByteSource& source, XmlHandler& handler);

  // Parses one part of a UTF-8 document (no encoding conversion): from `start` when given
  // (else from the document's start), reporting the end state into `end` when given.
  static XmlParseOutcome parse_part(ByteSource& source, XmlHandler& handler, const XmlPartStart* start,
                                    XmlEndState* end);
};

}  // namespace trailray::track
