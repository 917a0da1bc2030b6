// Placeholder until the KML reader lands (issue 14): every KML file is refused with a
// positioned error, like any unreadable file.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_kml(ByteSource& source, const ReadOptions& /*options*/) {
  ReadResult result;
  result.file.format = Format::Kml;
  result.error = Diagnostic{source.display_name(), {}, "KML files are not read yet"};
  return result;
}

}  // namespace trailray::track
