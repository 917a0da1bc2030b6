#include "track/io/xml_stream.hpp"

#include <expat.h>

#include <cstring>
#include <vector>

namespace trailray::track {
namespace {

struct Context {
  XML_Parser parser = nullptr;
  XmlHandler* handler = nullptr;
  std::string text;
  int depth = 0;
  bool saw_root = false;
  std::string stop_reason;  // set when we stop the parser ourselves
  SourcePosition stop_position;
};

SourcePosition position_of(XML_Parser p) {
  SourcePosition pos;
  pos.line = static_cast<std::int64_t>(XML_GetCurrentLineNumber(p));
  pos.column = static_cast<std::int64_t>(XML_GetCurrentColumnNumber(p)) + 1;  // expat: 0-based
  pos.byte_offset = static_cast<std::int64_t>(XML_GetCurrentByteIndex(p));
  return pos;
}

void stop(Context& c, std::string reason) {
  if (c.stop_reason.empty()) {
    c.stop_reason = std::move(reason);
    c.stop_position = position_of(c.parser);
  }
  XML_StopParser(c.parser, XML_FALSE);
}

void XMLCALL on_start(void* data, const XML_Char* name, const XML_Char** attrs) {
  auto& c = *static_cast<Context*>(data);
  c.saw_root = true;
  if (++c.depth > XmlStream::kMaxDepth) {
    stop(c, "elements nested deeper than " + std::to_string(XmlStream::kMaxDepth) + " levels");
    return;
  }
  for (const XML_Char** a = attrs; *a; a += 2) {
    if (std::strlen(a[1]) > XmlStream::kMaxValueBytes) {
      stop(c, std::string("attribute '") + a[0] + "' longer than 1 MiB");
      return;
    }
  }
  c.text.clear();
  c.handler->start_element(xml_local_name(name), attrs);
}

void XMLCALL on_end(void* data, const XML_Char* name) {
  auto& c = *static_cast<Context*>(data);
  --c.depth;
  c.handler->end_element(xml_local_name(name), c.text);
  c.text.clear();
}

void XMLCALL on_text(void* data, const XML_Char* s, int len) {
  auto& c = *static_cast<Context*>(data);
  if (c.text.size() + static_cast<std::size_t>(len) > XmlStream::kMaxValueBytes) {
    stop(c, "text value longer than 1 MiB");
    return;
  }
  c.text.append(s, static_cast<std::size_t>(len));
}

void XMLCALL on_entity_decl(void* data, const XML_Char* name, int, const XML_Char*, int,
                            const XML_Char*, const XML_Char*, const XML_Char*, const XML_Char*) {
  auto& c = *static_cast<Context*>(data);
  stop(c, std::string("DTD entity declaration '") + (name ? name : "") +
              "' rejected (entity expansion is not allowed in track files)");
}

bool is_cut_error(XML_Error e) {
  return e == XML_ERROR_NO_ELEMENTS || e == XML_ERROR_UNCLOSED_TOKEN || e == XML_ERROR_PARTIAL_CHAR ||
         e == XML_ERROR_UNCLOSED_CDATA_SECTION;
}

}  // namespace

const char* xml_attribute(const char** attrs, std::string_view local_name) {
  for (const char** a = attrs; *a; a += 2)
    if (xml_local_name(a[0]) == local_name) return a[1];
  return nullptr;
}

std::string_view xml_local_name(std::string_view q) {
  auto colon = q.rfind(':');
  return colon == std::string_view::npos ? q : q.substr(colon + 1);
}

SourcePosition XmlHandler::position() const {
  return context_ ? position_of(static_cast<Context*>(context_)->parser) : SourcePosition{};
}

void XmlHandler::fail(std::string message) {
  if (context_) stop(*static_cast<Context*>(context_), std::move(message));
}

XmlParseOutcome XmlStream::parse(ByteSource& source, XmlHandler& handler) {
  XmlParseOutcome out;
  Context c;
  c.handler = &handler;
  c.parser = XML_ParserCreate(nullptr);  // encoding from BOM / declaration (UTF-8, UTF-16, Latin-1)
  if (!c.parser) {
    out.kind = XmlParseOutcome::Kind::Error;
    out.message = "out of memory creating the XML parser";
    return out;
  }
  XML_SetUserData(c.parser, &c);
  XML_SetElementHandler(c.parser, on_start, on_end);
  XML_SetCharacterDataHandler(c.parser, on_text);
  XML_SetEntityDeclHandler(c.parser, on_entity_decl);
  XML_SetParamEntityParsing(c.parser, XML_PARAM_ENTITY_PARSING_NEVER);
  handler.context_ = &c;

  std::vector<char> buf(256 * 1024);
  bool done = false;
  std::int64_t total = 0;
  while (!done) {
    std::ptrdiff_t n = source.next(buf.data(), buf.size());
    if (n < 0) {
      out.kind = XmlParseOutcome::Kind::Error;
      out.message = "read error: " + source.error();
      out.position.byte_offset = total;
      break;
    }
    total += n;
    done = n == 0;
    if (XML_Parse(c.parser, buf.data(), static_cast<int>(n), done ? XML_TRUE : XML_FALSE) == XML_STATUS_OK)
      continue;
    XML_Error e = XML_GetErrorCode(c.parser);
    if (!c.stop_reason.empty()) {
      out.kind = XmlParseOutcome::Kind::Error;
      out.message = c.stop_reason;
      out.position = c.stop_position;
    } else if (done && is_cut_error(e) && c.saw_root) {
      out.kind = XmlParseOutcome::Kind::Truncated;
      out.message = "file ends inside the document (cut short?)";
      out.position = position_of(c.parser);
    } else if (done && c.saw_root && c.depth > 0 && e == XML_ERROR_SYNTAX) {
      out.kind = XmlParseOutcome::Kind::Truncated;
      out.message = "file ends inside the document (cut short?)";
      out.position = position_of(c.parser);
    } else {
      out.kind = XmlParseOutcome::Kind::Error;
      out.message = std::string(c.saw_root ? "malformed XML: " : "not an XML document: ") + XML_ErrorString(e);
      out.position = position_of(c.parser);
    }
    break;
  }
  out.saw_root = c.saw_root;
  handler.context_ = nullptr;
  XML_ParserFree(c.parser);
  return out;
}

}  // namespace trailray::track
