// trailray._core.read_file: a path or bytes read by the command line's readers, without the GIL.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "python/bindings.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/format_detect.hpp"
#include "track/io/readers.hpp"

namespace trailray::python {
namespace {

std::optional<track::Format> format_named(const std::string& name) {
  for (track::Format f : {track::Format::Gpx, track::Format::Igc, track::Format::Tcx, track::Format::Fit,
                          track::Format::Kml, track::Format::Kmz, track::Format::GeoJson})
    if (name == track::format_name(f)) return f;
  return std::nullopt;
}

track::ReadResult read_source(track::ByteSource& source, const std::optional<track::Format>& forced,
                              const std::string& path, const track::ReadOptions& options) {
  track::ReadResult result;
  const std::string name = source.display_name();
  std::string_view head = source.peek(4096);
  if (head.empty()) {
    result.error = track::Diagnostic{
        name, {}, source.error().empty() ? "file is empty" : "cannot read: " + source.error()};
    return result;
  }
  std::optional<track::Format> format = forced ? forced : track::detect_format(head, path);
  if (!format) {
    result.error = track::Diagnostic{name, {1, 1, 0}, "not a GPX, IGC, TCX, FIT, KML, KMZ or GeoJSON file (unrecognised content)"};
    return result;
  }
  switch (*format) {
    case track::Format::Gpx:
      return track::read_gpx(source, options);
    case track::Format::Igc:
      return track::read_igc(source, options);
    case track::Format::Tcx:
      return track::read_tcx(source, options);
    case track::Format::Fit:
      return track::read_fit(source, options);
    case track::Format::Kml:
      return track::read_kml(source, options);
    case track::Format::Kmz:
      return track::read_kmz(source, options);
    case track::Format::GeoJson:
      return track::read_geojson(source, options);
  }
  return result;
}

py::tuple diagnostic_tuple(const track::Diagnostic& d) {
  return py::make_tuple(text(d.to_string()), text(d.file), d.position.line, d.position.column, text(d.message));
}

// (File or None, error or None, warnings); a diagnostic is (text, file, line, column, message).
py::tuple read_file(const py::object& source, const std::optional<std::string>& format, const std::string& igc_altitude,
                    bool strict) {
  track::ReadOptions options;
  options.strict = strict;
  if (igc_altitude == "auto")
    options.igc_altitude = track::ReadOptions::IgcAltitude::Auto;
  else if (igc_altitude == "gnss")
    options.igc_altitude = track::ReadOptions::IgcAltitude::Gnss;
  else if (igc_altitude == "pressure")
    options.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
  else
    throw py::value_error(fmt::format("igc_altitude '{}' is not one of auto, gnss, pressure", igc_altitude));
  std::optional<track::Format> forced;
  if (format) {
    forced = format_named(*format);
    if (!forced) throw py::value_error(fmt::format("format '{}' is not one of gpx, igc, tcx, fit, kml, kmz, geojson", *format));
  }
  const bool is_bytes = py::isinstance<py::bytes>(source);
  std::string path = is_bytes ? std::string("<bytes>") : source.cast<std::string>();
  std::string bytes = is_bytes ? source.cast<std::string>() : std::string();

  track::ReadResult result;
  {
    py::gil_scoped_release unlocked;
    std::unique_ptr<track::ByteSource> byte_source;
    std::string open_error;
    if (is_bytes)
      byte_source = track::ByteSource::from_memory(std::move(bytes), path);
    else
      byte_source = track::ByteSource::open(path, open_error);
    if (!byte_source)
      result.error = track::Diagnostic{path, {}, "cannot open: " + open_error};
    else
      result = read_source(*byte_source, forced, is_bytes ? std::string() : path, options);
  }
  py::list warnings;
  std::vector<std::string> texts;
  for (const track::Diagnostic& w : result.warnings) {
    warnings.append(diagnostic_tuple(w));
    texts.push_back(w.to_string());
  }
  if (result.error) return py::make_tuple(py::none(), diagnostic_tuple(*result.error), warnings);
  File file(make_file_data(path, std::move(result.file), std::move(texts), options.igc_altitude));
  return py::make_tuple(py::cast(std::move(file)), py::none(), warnings);
}

}  // namespace

void bind_reading(py::module_& m) {
  m.def("read_file", &read_file, py::arg("source"), py::arg("format"), py::arg("igc_altitude"), py::arg("strict"),
        "The reader behind trailray.read: (File or None, error or None, warnings).");
}

}  // namespace trailray::python
