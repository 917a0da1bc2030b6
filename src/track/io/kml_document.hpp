#pragma once
// One KML document read into a TrackFile: the KML reader reads one, the KMZ reader one for each
// KML entry of its archive.

#include <cstddef>

#include "track/diagnostics.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/xml_stream.hpp"

namespace trailray::track {

struct KmlDocumentRead {
  XmlParseOutcome outcome;
  std::size_t complete_points = 0;  // track points and waypoints kept
};

// Appends the document's tracks and waypoints to `file`, and fills its metadata's name and
// description where they are still empty. After a cut, the complete points before it are kept.
KmlDocumentRead read_kml_document(ByteSource& source, TrackFile& file, WarningCollector& warnings);

}  // namespace trailray::track
