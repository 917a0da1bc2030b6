// KML reader: one KML document (kml_document.cpp) is the whole file.
#include "track/io/kml_document.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_kml(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Kml;
  WarningCollector warnings(source.display_name());
  KmlDocumentRead read = read_kml_document(source, result.file, warnings);
  record_xml_outcome(read.outcome, read.complete_points, result, warnings);
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
