// trailray._core.read_file: a path or bytes read by the command line's readers, without the GIL.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "app/common/track_arguments.hpp"
#include "python/bindings.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"

namespace trailray::python {
namespace {

std::optional<track::Format> format_named(const std::string& name) {
  for (track::Format f : {track::Format::Gpx, track::Format::Igc, track::Format::Tcx, track::Format::Fit,
                          track::Format::Kml, track::Format::Kmz, track::Format::GeoJson})
    if (name == track::format_name(f)) return f;
  return std::nullopt;
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
      result = track::read_track_source(*byte_source, is_bytes ? std::string() : path, options, forced);
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
  // The command line's TRACK arguments (folders, patterns) for the functions that take many files.
  m.def("expand_track_arguments", &app::expand_track_arguments, py::arg("arguments"));
  py::register_local_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const app::TrackArgumentError& e) {
      PyErr_SetString(PyExc_FileNotFoundError, e.what());  // a pattern or a folder that names no track file
    }
  });
}

}  // namespace trailray::python
