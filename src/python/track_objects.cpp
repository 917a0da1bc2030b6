#include "python/track_objects.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>

#include "app/tracks/stats_report.hpp"
#include "python/json_objects.hpp"
#include "python/text.hpp"
#include "track/clean.hpp"
#include "track/color_values.hpp"
#include "track/metrics.hpp"
#include "track/summary.hpp"

namespace trailray::python {

std::shared_ptr<const FileData> make_file_data(std::string path, track::TrackFile file,
                                               std::vector<std::string> warnings,
                                               track::ReadOptions::IgcAltitude igc_altitude) {
  auto data = std::make_shared<FileData>();
  data->igc_altitude = igc_altitude;
  data->path = std::move(path);
  data->warnings = std::move(warnings);
  for (track::Route& r : file.routes) {
    track::Track t;
    t.name = r.name;
    t.segments.push_back(track::Segment{std::move(r.points)});
    data->routes.push_back(std::move(t));
  }
  file.routes.clear();
  data->file = std::move(file);
  return data;
}

namespace {

std::vector<std::span<const track::TrackPoint>> parts_of(const track::Track& t) {
  std::vector<std::span<const track::TrackPoint>> parts;
  for (const track::Segment& s : t.segments) parts.emplace_back(s.points);
  return parts;
}

// A track alone in a file of its own (a cleaned copy).
std::shared_ptr<const FileData> alone(track::Track t, const std::string& path,
                                      track::ReadOptions::IgcAltitude igc_altitude) {
  auto data = std::make_shared<FileData>();
  data->path = path;
  data->file.tracks.push_back(std::move(t));
  data->igc_altitude = igc_altitude;
  return data;
}

}  // namespace

Segment::Segment(std::shared_ptr<const FileData> owner, const track::Segment& segment)
    : arrays_(std::move(owner), {std::span<const track::TrackPoint>(segment.points)}) {}

Track::Track(std::shared_ptr<const FileData> owner, const track::Track& track, bool is_route)
    : owner_(owner), track_(&track), is_route_(is_route), arrays_(owner, parts_of(track)) {}

std::vector<Segment> Track::segments() const {
  std::vector<Segment> out;
  for (const track::Segment& s : track_->segments) out.emplace_back(owner_, s);
  return out;
}

std::size_t Track::index() const {
  const auto& list = is_route_ ? owner_->routes : owner_->file.tracks;
  for (std::size_t i = 0; i < list.size(); ++i)
    if (&list[i] == track_) return i;
  return 0;
}

track::TrackFile Track::as_file() const {
  track::TrackFile f;
  f.format = owner_->file.format;
  f.metadata = owner_->file.metadata;
  f.tracks.push_back(*track_);
  return f;
}

namespace {

template <typename T>
py::list cached_list(py::object& cache, const std::function<std::vector<T>()>& make) {
  if (!cache) cache = py::tuple(py::cast(make()));
  return py::list(cache);
}

}  // namespace

py::list File::track_list() const {
  return cached_list<Track>(tracks_, [this] { return tracks(); });
}
py::list File::route_list() const {
  return cached_list<Track>(routes_, [this] { return routes(); });
}
py::list Track::segment_list() const {
  return cached_list<Segment>(segments_, [this] { return segments(); });
}

std::vector<Track> File::tracks() const {
  std::vector<Track> out;
  for (const track::Track& t : data_->file.tracks) out.emplace_back(data_, t, false);
  return out;
}

std::vector<Track> File::routes() const {
  std::vector<Track> out;
  for (const track::Track& t : data_->routes) out.emplace_back(data_, t, true);
  return out;
}

namespace {

track::CleanOptions cleaning(double min_distance, bool smooth, int smooth_width, double smooth_sigma) {
  // The ranges of the command line's --min-distance, --smooth-width and --smooth-sigma.
  if (!(min_distance >= 0.0 && min_distance <= 1000.0))
    throw py::value_error(fmt::format("min_distance {} is not in 0..1000 metres", min_distance));
  if (smooth_width < 1 || smooth_width > 100)
    throw py::value_error(fmt::format("smooth_width {} is not in 1..100 points", smooth_width));
  if (!(smooth_sigma >= 0.1 && smooth_sigma <= 100.0))
    throw py::value_error(fmt::format("smooth_sigma {} is not in 0.1..100 points", smooth_sigma));
  track::CleanOptions o;
  o.min_distance_m = min_distance;
  o.smooth = smooth;
  o.smooth_half_width = smooth_width;
  o.smooth_sigma = smooth_sigma;
  return o;
}

// One array over every point of the track from per-segment vectors.
template <typename T, typename U>
py::array_t<T> joined(const std::vector<std::vector<U>>& per_segment) {
  std::size_t n = 0;
  for (const auto& s : per_segment) n += s.size();
  py::array_t<T> out(static_cast<py::ssize_t>(n));
  T* to = out.mutable_data();
  for (const auto& s : per_segment)
    for (const U& v : s) *to++ = static_cast<T>(v);
  return out;
}

py::dict metrics_of(const track::Track& t) {
  track::TrackMetrics m;
  std::vector<std::vector<std::vector<float>>> values;
  std::vector<track::ColorMetric> which;
  for (std::string_view name : track::color_metric_names()) {
    const track::ColorMetric metric = *track::parse_color_metric(name);
    // solid has no values, agl needs terrain (trailray.elevation), phase the flight analysis
    // (trailray.flight), density and thermals every track at once.
    if (metric == track::ColorMetric::solid || metric == track::ColorMetric::agl ||
        metric == track::ColorMetric::phase || track::counts_neighbours(metric))
      continue;
    which.push_back(metric);
  }
  {
    py::gil_scoped_release unlocked;
    m = track::compute_metrics(t);
    for (track::ColorMetric metric : which) values.push_back(track::color_values(t, m, metric));
  }
  py::dict out;
  std::vector<std::vector<double>> distance, distance_3d, elapsed, glide;
  for (const auto& s : m.segments) {
    distance.push_back(s.distance_m);
    distance_3d.push_back(s.distance_3d_m);
    elapsed.push_back(s.elapsed_s);
    glide.push_back(s.glide_ratio);
  }
  for (std::size_t i = 0; i < which.size(); ++i)
    out[py::str(std::string(track::color_metric_name(which[i])))] = joined<double>(values[i]);
  out["distance"] = joined<double>(distance);
  out["distance_3d"] = joined<double>(distance_3d);
  out["elapsed"] = joined<double>(elapsed);
  out["glide_ratio"] = joined<double>(glide);
  return out;
}

py::dict stats_of(const track::Track& t, const track::CleanOptions& clean) {
  track::TrackSummary s;
  {
    py::gil_scoped_release unlocked;
    track::AnalysisOptions options;
    options.clean = clean;
    s = track::summarize_track(t, options);
  }
  nlohmann::json segments = nlohmann::json::array();
  for (const auto& seg : s.segments)
    segments.push_back({{"raw", app::statistics_json(seg.raw)}, {"clean", app::statistics_json(seg.clean)}});
  // The track's entry of `stats --json`, key for key.
  const nlohmann::json j = {{"name", t.name},
                            {"raw", app::statistics_json(s.raw)},
                            {"clean", app::statistics_json(s.clean)},
                            {"segments", std::move(segments)}};
  return to_python(j).cast<py::dict>();
}

py::object time_or_none(double seconds) {
  if (!std::isfinite(seconds)) return py::none();
  return py::module_::import("numpy").attr("datetime64")(static_cast<std::int64_t>(std::llround(seconds * 1000.0)),
                                                          "ms");
}

py::object number_or_none(double v) { return std::isnan(v) ? py::none() : py::object(py::float_(v)); }

const char* track_doc = R"(A track (or a route) of a file: its points as NumPy arrays in file order.

Arrays cover every point of every segment in order; a segment boundary is a gap (see
``segments``). Where the track has one segment the arrays are read-only views on the reader's
memory (no copy); otherwise each is joined once and kept. ``ele`` is NaN and ``time`` NaT where
a point has none. The recorded channels (``hr``, ``cadence``, ``power``, ``temperature``,
``recorded_speed``, an IGC flight's ``gnss_alt`` and ``pressure_alt``) are float32 arrays, or
None when the track did not record them; ``channels`` names those present.)";

}  // namespace

void bind_track_objects(py::module_& m) {
  py::class_<Segment>(m, "Segment", "One segment of a track: a stretch recorded without a gap.")
      .def_property_readonly("lat", [](const Segment& s) { return s.points().lat(); }, "Latitudes, degrees (WGS84)")
      .def_property_readonly("lon", [](const Segment& s) { return s.points().lon(); }, "Longitudes, degrees (WGS84)")
      .def_property_readonly("ele", [](const Segment& s) { return s.points().ele(); }, "Elevations, metres (NaN: none)")
      .def_property_readonly("time", [](const Segment& s) { return s.points().time(); }, "Times, datetime64[ms] UTC")
      .def_property_readonly("channels", [](const Segment& s) { return s.points().channels(); })
      .def("channel", [](const Segment& s, const std::string& name) { return s.points().channel(name); },
           py::arg("name"), "A recorded channel by name (hr, cadence, ...), or None")
      .def("__len__", [](const Segment& s) { return s.points().size(); })
      .def("__repr__", [](const Segment& s) { return fmt::format("<trailray.Segment of {} points>", s.points().size()); });

  py::class_<Track> track(m, "Track", track_doc);
  track.def_property_readonly("name", [](const Track& t) { return text(t.model().name); })
      .def_property_readonly("description", [](const Track& t) { return text(t.model().description); })
      .def_property_readonly("type", [](const Track& t) { return text(t.model().type); },
                             "The activity type as the device wrote it ('running', '9', ...)")
      .def_property_readonly("is_route", &Track::is_route, "A planned route (GPX rte), not a recording")
      .def_property_readonly("segments", &Track::segment_list)
      .def_property_readonly("lat", [](const Track& t) { return t.points().lat(); }, "Latitudes, degrees (WGS84)")
      .def_property_readonly("lon", [](const Track& t) { return t.points().lon(); }, "Longitudes, degrees (WGS84)")
      .def_property_readonly("ele", [](const Track& t) { return t.points().ele(); }, "Elevations, metres (NaN: none)")
      .def_property_readonly("time", [](const Track& t) { return t.points().time(); },
                             "Times, datetime64[ms] UTC (NaT: none)")
      .def_property_readonly("channels", [](const Track& t) { return t.points().channels(); },
                             "Names of the recorded channels present")
      .def("channel", [](const Track& t, const std::string& name) { return t.points().channel(name); },
           py::arg("name"), "A recorded channel by name (hr, cadence, ...), or None");
  for (const ChannelField& f : channel_fields()) {
    const std::string name = f.name;
    track.def_property_readonly(
        f.name, [name](const Track& t) { return t.points().channel(name); },
        ("The recorded channel '" + name + "' (float32), or None").c_str());
  }
  track.def("__len__", [](const Track& t) { return t.points().size(); })
      .def("__repr__",
           [](const Track& t) {
             return text(fmt::format("<trailray.{} '{}': {} points, {} segment{}>", t.is_route() ? "Track (route)" : "Track",
                                t.model().name, t.points().size(), t.model().segments.size(),
                                t.model().segments.size() == 1 ? "" : "s"));
           })
      .def(
          "cleaned",
          [](const Track& t, double min_distance, bool smooth, int smooth_width, double smooth_sigma) {
            const track::CleanOptions o = cleaning(min_distance, smooth, smooth_width, smooth_sigma);
            track::Track cleaned;
            {
              py::gil_scoped_release unlocked;
              track::CleanReport report;
              cleaned = track::clean_track(t.model(), o, report);
            }
            auto data = alone(std::move(cleaned), t.owner()->path, t.owner()->igc_altitude);
            return Track(data, data->file.tracks.front(), t.is_route());
          },
          py::arg("min_distance") = 3.0, py::arg("smooth") = true, py::arg("smooth_width") = 5,
          py::arg("smooth_sigma") = 1.0,
          R"(A cleaned copy, as the command line cleans before it measures or draws.

Drops invalid coordinates, exact repeats and backward timestamps, then points closer than
``min_distance`` metres to the last kept one, then smooths elevations with a Gaussian of
``smooth_sigma`` points over 2 * ``smooth_width`` + 1 points (not across a pause). The segments
stay as they are.)")
      .def(
          "metrics", [](const Track& t) { return metrics_of(t.model()); },
          R"(Per-point values over every point (float64 arrays, NaN where undefined), of this track
as it is (call ``cleaned()`` first for the values the pictures use): the ``--color-by`` names
``speed`` (km/h), ``vspeed`` (m/s), ``slope`` (%), ``altitude`` (m), ``hr``, ``cadence``,
``power``, ``time`` (seconds since the first timestamp), and ``distance`` and ``distance_3d``
(metres along the track), ``elapsed`` (s) and ``glide_ratio``.)")
      .def(
          "stats",
          [](const Track& t, double min_distance, bool smooth, int smooth_width, double smooth_sigma) {
            return stats_of(t.model(), cleaning(min_distance, smooth, smooth_width, smooth_sigma));
          },
          py::arg("min_distance") = 3.0, py::arg("smooth") = true, py::arg("smooth_width") = 5,
          py::arg("smooth_sigma") = 1.0,
          R"(Statistics as ``trailray stats --json`` gives them for this track: ``"raw"`` (as recorded)
and ``"clean"`` (after cleaning with these options), each with points, distance_2d_m,
distance_3d_m, duration_s, moving_time_s, elevation_gain_m, ... (None where unknown), and the same
per segment under ``"segments"``.)");

  py::class_<File>(m, "File", "A track file as read: its tracks, routes, waypoints, metadata and the reader's warnings.")
      .def_property_readonly("path", [](const File& f) { return text(f.data().path); })
      .def_property_readonly("format", [](const File& f) { return std::string(track::format_name(f.data().file.format)); },
                             "gpx, igc, tcx, fit, kml, kmz or geojson")
      .def_property_readonly("tracks", &File::track_list)
      .def_property_readonly("routes", &File::route_list, "Routes (GPX rte) as tracks of one segment, is_route True")
      .def_property_readonly(
          "waypoints",
          [](const File& f) {
            py::list out;
            py::object waypoint = py::module_::import("trailray").attr("Waypoint");
            for (const track::Waypoint& w : f.data().file.waypoints)
              out.append(waypoint(text(w.name), w.point.lat, w.point.lon, number_or_none(w.point.ele),
                                  time_or_none(w.point.time), text(w.description), text(w.symbol)));
            return out;
          },
          "Waypoints (name, lat, lon, ele, time, description, symbol)")
      .def_property_readonly("warnings", [](const File& f) { return texts(f.data().warnings); },
                             "The reader's warnings, 'file:line:column: message'")
      .def_property_readonly(
          "metadata",
          [](const File& f) {
            const track::Metadata& md = f.data().file.metadata;
            py::dict out;
            out["name"] = text(md.name);
            out["description"] = text(md.description);
            out["creator"] = text(md.creator);
            out["activity_type"] = text(md.activity_type);
            out["time"] = time_or_none(md.time);
            py::dict fields;
            for (const auto& [k, v] : md.fields) fields[text(k)] = text(v);
            out["fields"] = fields;
            return out;
          },
          "name, description, creator, activity_type, time and the format's header fields (an IGC "
          "file's pilot, glider, ...)")
      .def("__repr__", [](const File& f) {
        return text(fmt::format("<trailray.File '{}' ({}): {} tracks, {} routes, {} waypoints>", f.data().path,
                           track::format_name(f.data().file.format), f.data().file.tracks.size(),
                           f.data().routes.size(), f.data().file.waypoints.size()));
      });
}

}  // namespace trailray::python
