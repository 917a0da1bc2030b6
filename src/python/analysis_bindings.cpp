// trailray._core's analysis: score, flight, Task, Airspaces and elevation, each through the report
// of its command (app/*_report), so Python gets the numbers of the command's --json.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/flight/airspace_check.hpp"
#include "app/flight/check_report.hpp"
#include "app/flight/flight_report.hpp"
#include "app/flight/score_report.hpp"
#include "app/flight/task_report.hpp"
#include "app/pictures/elevation_report.hpp"
#include "app/pictures/terrain_heights.hpp"
#include "python/bindings.hpp"
#include "python/json_objects.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"
#include "track/airspace/airspace_index.hpp"
#include "track/airspace/openair_reader.hpp"
#include "track/scoring/fixes.hpp"
#include "track/scoring/rules.hpp"
#include "track/scoring/score.hpp"
#include "track/task/task_distance.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::python {
namespace {

namespace sc = track::scoring;
namespace tt = track::task;
namespace as = track::airspace;

// trailray.ReadError(text, path, line, column), raised.
[[noreturn]] void raise_read_error(const std::string& message, const std::string& path, std::int64_t line = 0,
                                   std::int64_t column = 0) {
  py::object error = py::module_::import("trailray").attr("ReadError")(text(message), text(path), line, column);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw py::error_already_set();
}

[[noreturn]] void raise_read_error(const track::Diagnostic& d) {
  raise_read_error(d.to_string(), d.file, d.position.line, d.position.column);
}

// Warnings (reader's, terrain's) through Python's warnings module as TrailrayWarning.
void warn_all(const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  py::object category = py::module_::import("trailray").attr("TrailrayWarning");
  py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& line : lines) warn(text(line), category, 2);
}

// The fixes `score` optimises over: of an IGC file's B records as the command reads them, or of a
// track's timed points (an IGC track's GNSS and pressure altitudes; one fix per second, as the
// scorer keeps them).
sc::FixList fixes_of(const py::object& flight) {
  if (py::isinstance<Track>(flight)) return sc::fixes_of_track(flight.cast<const Track&>().model());
  const std::string path = py::str(py::module_::import("os").attr("fspath")(flight));
  py::gil_scoped_release unlocked;
  return sc::read_any_scoring_fixes(path);
}

py::dict score(const py::object& flight, const std::string& rules, const std::string& distance, bool trim,
               bool all_types) {
  const auto rule_set = sc::rule_set(rules);
  if (!rule_set)
    throw py::value_error(fmt::format("unknown rule set '{}' (one of: {})", rules, fmt::join(sc::rule_set_names(), ", ")));
  if (distance != "fcc" && distance != "geodesic")
    throw py::value_error(fmt::format("distance '{}' is not fcc or geodesic", distance));
  const sc::FixList list = fixes_of(flight);
  if (list.error) raise_read_error(*list.error, py::str(flight).cast<std::string>());
  if (list.fixes.size() < 5)
    throw py::value_error(fmt::format("{} valid fixes (of {} B records); scoring needs at least 5", list.fixes.size(),
                                      list.b_records));
  sc::ScoreOptions options;
  options.model = distance == "geodesic" ? sc::DistanceModel::Geodesic : sc::DistanceModel::Fcc;
  options.trim = trim;
  options.all_types = all_types;
  nlohmann::json j;
  {
    py::gil_scoped_release unlocked;
    j = app::score_json(sc::score_flight(list.fixes, *rule_set, options), list.fixes);
  }
  return to_python(j).cast<py::dict>();
}

py::dict flight(const Track& t) {
  app::FileFlights f;
  f.path = t.owner()->path;
  f.format = t.owner()->file.format;
  {
    py::gil_scoped_release unlocked;
    f.tracks.push_back({t.model().name, t.index(), track::flight::analyse_flights(t.model(), {}),
                        app::median_fix_interval(t.model())});
  }
  return to_python(app::flight_file_json(f)["tracks"][0]).cast<py::dict>();
}

class Task {
 public:
  static Task read(const py::object& path_like) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
    tt::TaskReadResult r;
    {
      py::gil_scoped_release unlocked;
      r = tt::read_task_file(path);
    }
    std::vector<std::string> warnings;
    for (const auto& w : r.warnings) warnings.push_back(w.to_string());
    warn_all(warnings);
    if (r.error) raise_read_error(*r.error);
    Task t;
    t.path_ = path;
    t.task_ = std::make_shared<tt::Task>(std::move(*r.task));
    t.distances_ = tt::measure_task(*t.task_);
    return t;
  }

  py::dict info() const { return to_python(app::task_json(path_, *task_, distances_, {})).cast<py::dict>(); }
  const std::string& path() const { return path_; }

  py::dict check(const Track& t, double tolerance_percent) const {
    if (!(tolerance_percent >= 0.0 && tolerance_percent <= 100.0))
      throw py::value_error(fmt::format("tolerance {} is not a percentage in 0..100", tolerance_percent));
    app::TaskFlightReport report;
    {
      py::gil_scoped_release unlocked;
      report = app::task_flight_report(t.owner()->path, t.as_file(), *task_, distances_, tolerance_percent / 100.0);
    }
    if (report.error) throw py::value_error(*report.error);
    return to_python(app::task_flight_json(*task_, report)).cast<py::dict>();
  }

 private:
  std::string path_;
  std::shared_ptr<const tt::Task> task_;
  tt::TaskDistances distances_;
};

class Airspaces {
 public:
  static Airspaces read(const py::object& path_like, bool strict) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
    track::ReadOptions options;
    options.strict = strict;
    auto r = std::make_shared<as::AirspaceReadResult>();
    {
      py::gil_scoped_release unlocked;
      *r = as::load_openair_file(path, options);
    }
    std::vector<std::string> warnings;
    for (const auto& w : r->warnings) warnings.push_back(w.to_string());
    warn_all(warnings);
    if (r->error) raise_read_error(*r->error);
    Airspaces a;
    a.path_ = path;
    a.read_ = r;
    a.index_ = std::make_shared<as::AirspaceIndex>(r->file);
    return a;
  }

  std::size_t size() const { return read_->file.airspaces.size(); }
  const std::string& path() const { return path_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& a : read_->file.airspaces) out.push_back(a.name);
    return out;
  }

  // The track's entry of `check --json`: points, how altitudes were taken, infringements.
  py::dict check(const Track& t, const std::optional<std::string>& terrain) const {
    scene::CollectedDiagnostics diagnostics;  // handed to Python after the work (no GIL meanwhile)
    app::CheckReport report{path_, &read_->file, terrain.has_value(), {}};
    {
      py::gil_scoped_release unlocked;
      app::CheckedPoints checked = app::checked_points(t.owner()->path, t.as_file(), t.owner()->igc_altitude);
      std::vector<app::CheckSegments> tracks{std::move(checked.segments)};
      app::TerrainOptions options;
      if (terrain) options.terrain = *terrain;
      app::add_ground_heights(options, diagnostics, true, tracks);
      checked.track.infringements = as::find_infringements(*index_, tracks.front());
      report.tracks.push_back(std::move(checked.track));
    }
    warn_all(diagnostics.warnings);
    return to_python(app::check_json(report)["tracks"][0]).cast<py::dict>();
  }

 private:
  std::string path_;
  std::shared_ptr<const as::AirspaceReadResult> read_;
  std::shared_ptr<const as::AirspaceIndex> index_;
};

py::dict elevation(const Track& t, const std::string& terrain, std::optional<int> zoom,
                   const std::optional<std::string>& surface_source) {
  app::TerrainOptions options;
  options.terrain = terrain;
  if (zoom) options.terrain_zoom = *zoom;
  if (surface_source) options.surface = *surface_source;
  scene::CollectedDiagnostics diagnostics;  // handed to Python after the work (no GIL meanwhile)
  app::ElevationReport report;
  {
    py::gil_scoped_release unlocked;
    std::vector<geo::LatLon> where;
    where.reserve(t.points().size());
    for (const track::Segment& s : t.model().segments)
      for (const track::TrackPoint& p : s.points) where.push_back({p.lat, p.lon});
    const app::TerrainHeights sampled = app::terrain_heights(where, options, diagnostics, t.owner()->path);
    const app::TerrainHeights surface = app::surface_heights(where, options, diagnostics, t.owner()->path);
    report.surface = surface.source_name;
    report.path = t.owner()->path;
    report.terrain = sampled.source_name;
    std::size_t k = 0;
    for (std::size_t s = 0; s < t.model().segments.size(); ++s)
      for (const track::TrackPoint& p : t.model().segments[s].points) {
        app::ElevationPoint point{t.index(), s, p.lat, p.lon, p.ele, sampled.heights[k]};
        if (surface_source) point.surface_m = surface.heights[k];
        ++k;
        report.points.push_back(point);
      }
    report.summary = app::summarize(report.points);
  }
  warn_all(diagnostics.warnings);
  py::array_t<double> ground(static_cast<py::ssize_t>(report.points.size()));
  py::array_t<double> agl(static_cast<py::ssize_t>(report.points.size()));
  for (std::size_t i = 0; i < report.points.size(); ++i) {
    ground.mutable_data()[i] = report.points[i].terrain_m;
    agl.mutable_data()[i] = report.points[i].agl_m();
  }
  py::dict out;
  out["terrain"] = ground;
  out["agl"] = agl;
  out["source"] = text(report.terrain);
  if (surface_source) {
    // Per point: the surface, the canopy above the ground, and the class as a name (None: no class).
    py::array_t<double> surface(static_cast<py::ssize_t>(report.points.size()));
    py::array_t<double> canopy(static_cast<py::ssize_t>(report.points.size()));
    py::list cover;
    for (std::size_t i = 0; i < report.points.size(); ++i) {
      surface.mutable_data()[i] = report.points[i].surface_m;
      canopy.mutable_data()[i] = report.points[i].canopy_m();
      const std::optional<track::Cover> c = report.points[i].cover();
      cover.append(c ? py::object(text(std::string(track::cover_name(*c)))) : py::object(py::none()));
    }
    out["surface"] = surface;
    out["canopy"] = canopy;
    out["cover"] = cover;
    out["surface_source"] = text(report.surface);
  }
  out["summary"] = to_python(app::elevation_summary_json(report.summary, surface_source.has_value()));
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("score", &score, py::arg("flight"), py::arg("rules"), py::arg("distance"), py::arg("trim"),
        py::arg("all_types"));
  m.def("flight", &flight, py::arg("track"));
  m.def("elevation", &elevation, py::arg("track"), py::arg("terrain"), py::arg("terrain_zoom"), py::arg("surface"));
  py::class_<Task>(m, "Task", "A competition task (XCTrack .xctsk, its XCTSK: QR text, or an IGC C-record declaration).")
      .def_static("read", &Task::read, py::arg("path"), "Reads a task file; ReadError naming the file and the place.")
      .def_property_readonly("path", [](const Task& t) { return text(t.path()); })
      .def("info", &Task::info,
           "The task as `trailray task --json` gives it: turnpoints, radii, roles, distances through the centres "
           "and optimised")
      .def("check", &Task::check, py::arg("track"), py::arg("tolerance") = 0.0,
           "The turnpoints the track reached and when, as a flight of `trailray task --json` (tolerance: percent of "
           "a radius)")
      .def("__repr__", [](const Task& t) { return text(fmt::format("<trailray.Task '{}'>", t.path())); });
  py::class_<Airspaces>(m, "Airspaces", "Airspaces of an OpenAir file, indexed for checking tracks.")
      .def_static("read", &Airspaces::read, py::arg("path"), py::arg("strict") = false,
                  "Reads an OpenAir file; ReadError naming the file and the line.")
      .def_property_readonly("path", [](const Airspaces& a) { return text(a.path()); })
      .def_property_readonly("names", [](const Airspaces& a) { return texts(a.names()); })
      .def("__len__", &Airspaces::size)
      .def("check", &Airspaces::check, py::arg("track"), py::arg("terrain") = py::none(),
           "The track's infringements as `trailray check --json` gives them (terrain: a source for AGL limits)")
      .def("__repr__",
           [](const Airspaces& a) { return text(fmt::format("<trailray.Airspaces '{}': {} airspaces>", a.path(), a.size())); });
}

}  // namespace trailray::python
