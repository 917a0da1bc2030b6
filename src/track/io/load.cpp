#include "track/io/load.hpp"

#include "track/io/byte_source.hpp"
#include "track/io/format_detect.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {

void finish_read(ReadResult& result, const WarningCollector& warnings, const ReadOptions& options) {
  result.warnings = warnings.diagnostics();
  if (options.strict && !result.error && !result.warnings.empty()) {
    result.error = result.warnings.front();
    result.error->message += " (--strict)";
  }
}

ReadResult load_track_file(const std::string& path, const ReadOptions& options) {
  std::string open_error;
  auto source = ByteSource::open(path, open_error);
  if (!source) {
    ReadResult result;
    result.error = Diagnostic{path == "-" ? "<stdin>" : path, {}, "cannot open: " + open_error};
    return result;
  }
  return read_track_source(*source, path, options);
}

ReadResult read_track_source(ByteSource& source, const std::string& path, const ReadOptions& options,
                             std::optional<Format> format) {
  ReadResult result;
  const std::string& name = source.display_name();
  std::string_view head = source.peek(4096);
  if (head.empty()) {
    result.error = Diagnostic{name, {}, source.error().empty() ? "file is empty" : "cannot read: " + source.error()};
    return result;
  }
  if (!format) format = detect_format(head, path);
  if (!format) {
    result.error =
        Diagnostic{name, {1, 1, 0}, "not a GPX, IGC, TCX, FIT, KML, KMZ or GeoJSON file (unrecognised content)"};
    return result;
  }
  switch (*format) {
    case Format::Gpx:
      return read_gpx(source, options);
    case Format::Igc:
      return read_igc(source, options);
    case Format::Tcx:
      return read_tcx(source, options);
    case Format::Fit:
      return read_fit(source, options);
    case Format::Kml:
      return read_kml(source, options);
    case Format::Kmz:
      return read_kmz(source, options);
    case Format::GeoJson:
      return read_geojson(source, options);
  }
  return result;
}

}  // namespace trailray::track
