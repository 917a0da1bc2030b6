// XmlStream's entry points and the handler's view of the running scanner (xml_scanner.hpp).

#include "track/io/xml_stream.hpp"

#include <memory>
#include <string>

#include "track/io/xml_encoding.hpp"
#include "track/io/xml_scanner.hpp"

namespace trailray::track {

using detail::XmlScanner;

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

void XmlHandler::stream_text() {
  if (context_) scanner_of(context_)->stream_current_element();
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
