#pragma once
// Input encodings of XML track files, normalised to UTF-8 before scanning: UTF-8 (with or
// without BOM), US-ASCII, UTF-16 LE/BE (BOM or the "<?" pattern), ISO-8859-1/15 and
// Windows-1252 (from the XML declaration). Conversion is streaming, chunk by chunk.

#include <memory>
#include <string>
#include <string_view>

#include "track/io/byte_source.hpp"

namespace trailray::track {

// True when a document starting with `head` is read as it is (UTF-8, ASCII, or no declared
// encoding): no conversion, so it can be read in independent parts.
bool is_utf8_document(std::string_view head);

// A UTF-8 view of `source`: nullptr when it already is UTF-8 (nothing to convert). Sets
// `error` (and returns nullptr) for an encoding that is declared but not supported.
std::unique_ptr<ByteSource> utf8_view(ByteSource& source, std::string& error);

}  // namespace trailray::track
