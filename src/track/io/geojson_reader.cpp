// Placeholder until the GeoJSON reader lands (issue 14): every GeoJSON file is refused with a
// positioned error, like any unreadable file.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_geojson(ByteSource& source, const ReadOptions& /*options*/) {
  ReadResult result;
  result.file.format = Format::GeoJson;
  result.error = Diagnostic{source.display_name(), {}, "GeoJSON files are not read yet"};
  return result;
}

}  // namespace trailray::track
