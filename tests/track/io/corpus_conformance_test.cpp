// Every track file of the reference corpora (../shared/data/corpus: GPX, KML, FIT, TCX, IGC and
// GeoJSON from the test suites of gpsbabel, XCSoar, python-fitparse, togeojson and SkyLines) read
// by trailray and by the reference tools, run live:
//   - gpsbabel (Debian gpsbabel) for every format: its GPX output, read back, gives the same tracks
//     (each segment a line), routes and waypoints, points in order, positions to 1e-7 degree and
//     times to the millisecond where both have one. For IGC, gpsbabel writes the fixes twice (a
//     GNSS and a pressure altitude track): ours is compared with both, each altitude with its own;
//     its route of the declared task (less its LANDING point: a task has none) is compared with
//     the turnpoints trailray reads from the C records. gpsbabel adds a waypoint LAPnnn at each
//     lap's start (FIT, TCX), which no file holds: those are left out. A GeoJSON LineString is
//     neither a track nor a route: gpsbabel makes it a route, trailray a track, so for GeoJSON
//     both are compared as one list of lines.
//   - GDAL's OGR (python3-gdal, tests/conformance/ogr_kml_coordinates.py) for KML and GeoJSON: the
//     same lines and points, as sorted lists (OGR orders features by layer).
// Each file and reference is equal, differs or cannot be read, with why; the test prints the
// table. Where we differ on purpose, kKnown says why (and the tests named there pin our
// behaviour); any other outcome, or a known one that changed, fails: a reader that regresses on a
// real file is seen at once.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/task/task_reader.hpp"
#include "unique_temp_dir.hpp"

namespace trailray::track {
namespace {

using nlohmann::json;
using test::run_command;
using test::shell_quote;

struct Point {
  double lat = 0.0, lon = 0.0, time = kMissing, ele = kMissing;
};
using Line = std::vector<Point>;

struct Lines {
  std::vector<Line> tracks;  // each non-empty segment of each track
  std::vector<Line> routes;
  Line waypoints;
};

Point point_of(const TrackPoint& p, double ele) { return {p.lat, p.lon, p.time, ele}; }

bool is_lap_marker(const Waypoint& w) {
  return w.name.size() == 6 && w.name.rfind("LAP", 0) == 0 &&
         std::all_of(w.name.begin() + 3, w.name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// `gpsbabel_output`: leave out the waypoints gpsbabel makes of laps.
Lines lines_of(const TrackFile& f, bool gpsbabel_output = false) {
  Lines out;
  for (const Track& t : f.tracks)
    for (const Segment& s : t.segments) {
      if (s.points.empty()) continue;
      Line& line = out.tracks.emplace_back();
      for (const TrackPoint& p : s.points) line.push_back(point_of(p, p.ele));
    }
  for (const Route& r : f.routes) {
    Line& line = out.routes.emplace_back();
    for (const TrackPoint& p : r.points) line.push_back(point_of(p, p.ele));
  }
  for (const Waypoint& w : f.waypoints)
    if (!gpsbabel_output || !is_lap_marker(w)) out.waypoints.push_back(point_of(w.point, w.point.ele));
  return out;
}

std::size_t points_in(const std::vector<Line>& lines) {
  std::size_t n = 0;
  for (const Line& l : lines) n += l.size();
  return n;
}

// Why two lists of lines differ ("" when they do not): counts, then each point's position (1e-7
// degree), time (1 ms, where both have one) and, with `elevations`, altitude (1 mm). Points timed
// by one side only are named after the rest is found equal.
std::string compare(const std::string& what, const std::vector<Line>& ours, const std::vector<Line>& theirs,
                    const std::string& reference, bool elevations = false) {
  if (ours.size() != theirs.size() || points_in(ours) != points_in(theirs))
    return fmt::format("{}: {} ({} points) against {} ({} points)", what, ours.size(), points_in(ours), theirs.size(),
                       points_in(theirs));
  std::size_t only_ours = 0, only_theirs = 0;
  for (std::size_t l = 0; l < ours.size(); ++l) {
    if (ours[l].size() != theirs[l].size())
      return fmt::format("{} {}: {} points against {}", what, l + 1, ours[l].size(), theirs[l].size());
    for (std::size_t i = 0; i < ours[l].size(); ++i) {
      const Point &a = ours[l][i], &b = theirs[l][i];
      const std::string where = fmt::format("{} {} point {}", what, l + 1, i + 1);
      if (std::fabs(a.lat - b.lat) > 1e-7 || std::fabs(a.lon - b.lon) > 1e-7)
        return fmt::format("{}: {:.7f},{:.7f} against {:.7f},{:.7f}", where, a.lat, a.lon, b.lat, b.lon);
      if (!std::isnan(a.time) && !std::isnan(b.time) && std::fabs(a.time - b.time) > 1e-3)
        return fmt::format("{}: time {:.3f} against {:.3f}", where, a.time, b.time);
      only_ours += !std::isnan(a.time) && std::isnan(b.time);
      only_theirs += std::isnan(a.time) && !std::isnan(b.time);
      if (elevations && (std::isnan(a.ele) != std::isnan(b.ele) || std::fabs(a.ele - b.ele) > 1e-3))
        return fmt::format("{}: altitude {} against {}", where, a.ele, b.ele);
    }
  }
  if (only_theirs > 0) return fmt::format("{}: {} points timed by {} only", what, only_theirs, reference);
  if (only_ours > 0) return fmt::format("{}: {} points timed by trailray only", what, only_ours);
  return "";
}

// The same lines in any order, positions only (what OGR's features give).
std::string compare_unordered(const std::string& what, std::vector<Line> ours, std::vector<Line> theirs) {
  const auto by_position = [](const Line& a, const Line& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), [](const Point& p, const Point& q) {
      return std::array{p.lon, p.lat} < std::array{q.lon, q.lat};
    });
  };
  std::sort(ours.begin(), ours.end(), by_position);
  std::sort(theirs.begin(), theirs.end(), by_position);
  for (auto* lines : {&ours, &theirs})
    for (Line& l : *lines)
      for (Point& p : l) p.time = kMissing;
  return compare(what, ours, theirs, "OGR");
}

struct Outcome {
  std::string file;       // folder/name under corpus/
  std::string reference;  // "gpsbabel", "gpsbabel task", "OGR"
  std::string status;     // "equal", "differs", "cannot read: trailray", "cannot read: REFERENCE"
  std::string why;
};

// Where we differ from a reference on purpose: the file, the reference, the outcome, and why.
struct Known {
  const char* file;
  const char* reference;
  const char* status;
  const char* why;
};

constexpr Known kKnown[] = {
    // gpsbabel stops at the first CRC or header error and writes nothing; trailray keeps what it
    // read before the fault and warns (FitFiles tests pin the points kept).
    {"fit/fitparse_activity-activity-filecrc.fit", "gpsbabel", "cannot read: gpsbabel",
     "two chained activities, the second's CRC bad: gpsbabel refuses the file, trailray keeps both activities' "
     "points and warns"},
    {"fit/fitparse_activity-filecrc.fit", "gpsbabel", "cannot read: gpsbabel",
     "file CRC wrong: gpsbabel refuses the file, trailray keeps the data (warned)"},
    {"fit/fitparse_activity-settings-corruptheader.fit", "gpsbabel", "cannot read: gpsbabel",
     "the chained second file's header is corrupt: gpsbabel refuses, trailray keeps the activity before it (warned)"},
    {"fit/fitparse_activity-unexpected-eof.fit", "gpsbabel", "cannot read: gpsbabel",
     "truncated by one byte: gpsbabel refuses, trailray keeps the records before the end (warned)"},
    {"fit/fitparse_activity-large-fenxi2-multisport.fit", "gpsbabel", "differs",
     "a multisport activity: trailray makes a track of each session (run, transition, bike, ...) with its sport "
     "(FitModel.EachSessionIsATrackWithItsSport), gpsbabel one track of the same points"},
    {"fit/gpsbabel_track_fitwrite-track.fit", "gpsbabel", "differs",
     "a course's course points: trailray reads them as waypoints (the 12 of the GPX the file was written from, "
     "FitModel.CoursePointsBecomeWaypoints), gpsbabel leaves them out"},
    {"fit/fitparse_nick.fit", "gpsbabel", "cannot read: gpsbabel",
     "file CRC wrong: gpsbabel refuses the file, trailray keeps the data (warned)"},
    {"fit/fitparse_strava-android-app-201.10-b1218918.fit", "gpsbabel", "cannot read: gpsbabel",
     "a chained second file is cut short: gpsbabel refuses, trailray keeps the activity (warned)"},
    // Not GeoJSON: Google Takeout's location history (gpsbabel reads it with its own
    // googletakeout format). Read as GeoJSON, gpsbabel finds nothing; trailray says why.
    {"geojson/gpsbabel_googletakeout_2013_JUNE.json", "gpsbabel", "cannot read: trailray",
     "Google Takeout JSON, not GeoJSON: gpsbabel's geojson reader finds nothing in it, trailray refuses it "
     "(no \"type\")"},
    {"geojson/gpsbabel_googletakeout_2013_MAY.json", "gpsbabel", "cannot read: trailray",
     "Google Takeout JSON, not GeoJSON: gpsbabel's geojson reader finds nothing in it, trailray refuses it "
     "(no \"type\")"},
    // togeojson writes a LineString's times as the feature's coordTimes (or coordinateProperties
    // .times) property: trailray reads them (GeoJsonReader tests), gpsbabel does not.
    {"geojson/togeojson_empty_ele.gpx.geojson", "gpsbabel", "differs",
     "togeojson's coordTimes: trailray reads the times, gpsbabel does not"},
    {"geojson/togeojson_gxtrack.kml.geojson", "gpsbabel", "differs",
     "togeojson's coordTimes: trailray reads the times, gpsbabel does not"},
    {"geojson/togeojson_multitrackgpx.gpx.geojson", "gpsbabel", "differs",
     "togeojson's coordTimes: trailray reads the times, gpsbabel does not"},
    {"geojson/togeojson_non_gx_multitrack.kml.geojson", "gpsbabel", "differs",
     "togeojson's coordTimes: trailray reads the times, gpsbabel does not"},
    {"geojson/togeojson_osm.gpx.geojson", "gpsbabel", "differs",
     "togeojson's coordTimes: trailray reads the times, gpsbabel does not"},
    {"geojson/togeojson_gdal.gpx.geojson", "gpsbabel", "differs",
     "a Point feature's \"time\" property: trailray reads it as the waypoint's time, gpsbabel does not"},
    // An IGC fix whose altitudes are 00000 among fixes that have altitudes: a real 0 (sea level)
    // to trailray (IgcReader.AutoUsesGnssOnValidFixesAndPressureOtherwise), none to gpsbabel.
    {"igc/gpsbabel_igc1.expected-3d.igc", "gpsbabel", "differs",
     "the last fix's altitudes are 00000: kept as 0 m (as any other value; cleaning judges it), gpsbabel drops "
     "every 0"},
    // OGR's LIBKML driver reads an empty <gx:coord/> as 0,0 (Null Island); trailray drops it with a
    // warning, as gpsbabel does.
    {"kml/gpsbabel_track_opentracks.kml", "OGR", "differs",
     "two empty <gx:coord/>: OGR reads them as 0,0, trailray and gpsbabel drop them (warned)"},
    {"kml/togeojson_multigeometry_discrete.kml", "gpsbabel", "differs",
     "a MultiGeometry's Point: trailray and OGR read it as a waypoint, gpsbabel leaves it out"},
    {"kml/togeojson_non_gx_multitrack.kml", "OGR", "differs",
     "a MultiTrack written without its gx: prefix (Google My Tracks): trailray, gpsbabel and togeojson read its "
     "gx:Track, OGR's LIBKML skips it"},
    // A MultiLineString inside a GeometryCollection is a track's lines: gpsbabel's geojson reader
    // skips geometry collections, OGR reads them as trailray does.
    {"geojson/togeojson_multigeometry.kml.geojson", "gpsbabel", "differs",
     "a GeometryCollection's lines: trailray and OGR read them, gpsbabel skips the collection"},
    {"geojson/togeojson_multigeometry_discrete.kml.geojson", "gpsbabel", "differs",
     "a GeometryCollection's line: trailray and OGR read it, gpsbabel skips the collection"},
    // A polygon is an area, not a way travelled: trailray (like OGR's lines) leaves it out and
    // warns; gpsbabel reads its outer ring as a track (KML) or a route (GeoJSON).
    {"geojson/togeojson_timespan.kml.geojson", "gpsbabel", "differs",
     "a Polygon: gpsbabel reads its ring as a route, trailray leaves areas out (warned)"},
    {"kml/togeojson_style_url.kml", "gpsbabel", "differs",
     "Polygons: gpsbabel reads their rings as tracks, trailray leaves areas out (warned)"},
    {"kml/togeojson_timespan.kml", "gpsbabel", "differs",
     "a Polygon: gpsbabel reads its ring as a track, trailray leaves areas out (warned)"},
};

const Known* known(const Outcome& o) {
  for (const Known& k : kKnown)
    if (o.file == k.file && o.reference == k.reference) return &k;
  return nullptr;
}

const std::map<std::string, std::string> kGpsbabelFormat = {{"gpx", "gpx"}, {"kml", "kml"},    {"fit", "garmin_fit"},
                                                              {"tcx", "gtrnctr"}, {"igc", "igc"}, {"geojson", "geojson"}};

std::string last_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const std::size_t nl = text.rfind('\n');
  return nl == std::string::npos ? text : text.substr(nl + 1);
}

// An IGC file as gpsbabel writes it: the fixes twice, with the pressure and with the GNSS altitude
// (tracks PRESALTTRK and GNSSALTTRK), and the declared task as a route.
std::string compare_igc(const TrackFile& ours, const TrackFile& theirs) {
  Lines mine = lines_of(ours);
  std::string why;
  std::size_t compared = 0;
  for (const Track& t : theirs.tracks) {
    const bool gnss = t.name == "GNSSALTTRK", pressure = t.name == "PRESALTTRK";
    if (!gnss && !pressure) return "gpsbabel wrote a track named '" + t.name + "'";
    std::vector<Line> with_altitude = mine.tracks;
    std::size_t flat = 0;
    std::vector<TrackPoint> points;
    for (const Track& o : ours.tracks)
      for (const Segment& s : o.segments) points.insert(points.end(), s.points.begin(), s.points.end());
    for (Line& l : with_altitude)
      for (Point& p : l) {
        const float alt = gnss ? points[flat].gnss_altitude : points[flat].pressure_altitude;
        p.ele = std::isnan(alt) ? kMissing : static_cast<double>(alt);
        ++flat;
      }
    TrackFile one;
    one.tracks.push_back(t);
    why = compare(t.name, with_altitude, lines_of(one).tracks, "gpsbabel", true);
    if (!why.empty()) return why;
    ++compared;
  }
  if (compared == 0 && points_in(mine.tracks) > 0) return "gpsbabel wrote no track";
  return "";
}

// gpsbabel's route of the declared task (C records; take-off and landing at 0,0 left out) against
// the task trailray reads from the same records.
Outcome compare_igc_task(const std::string& name, const std::filesystem::path& file, const TrackFile& theirs) {
  Outcome o{name, "gpsbabel task", "equal", ""};
  Line their_points;
  for (const Route& r : theirs.routes)
    for (const TrackPoint& p : r.points) their_points.push_back({p.lat, p.lon, kMissing, kMissing});
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  // The last C record is the landing (IGC specification A3.5): gpsbabel writes it unless it is
  // at 0,0; a task has no landing. "C4544124N00722044E": DDMMmmm, DDDMMmmm.
  std::string landing;
  for (std::string line; std::getline(text, line);)
    if (line.size() >= 18 && line[0] == 'C' && (line[8] == 'N' || line[8] == 'S')) landing = line;
  text.clear();
  text.seekg(0);
  if (!landing.empty() && landing.substr(1, 7) != "0000000" && !their_points.empty()) {
    const double lat = (std::stoi(landing.substr(1, 2)) + std::stoi(landing.substr(3, 5)) / 60000.0) *
                       (landing[8] == 'S' ? -1 : 1);
    if (std::fabs(their_points.back().lat - lat) < 1e-6) their_points.pop_back();
  }
  const task::TaskReadResult task = task::read_igc_declaration(text.str(), file.string());
  Line our_points;
  if (task.task)
    for (const task::Turnpoint& t : task.task->turnpoints)
      if (t.lat != 0.0 || t.lon != 0.0) our_points.push_back({t.lat, t.lon, kMissing, kMissing});
  if (!task.task && their_points.empty()) return o;  // no task on either side
  if (!task.task) return {name, o.reference, "cannot read: trailray", task.error->to_string()};
  o.why = compare("turnpoints", {our_points}, {their_points}, "gpsbabel");
  if (!o.why.empty()) o.status = "differs";
  return o;
}

Outcome with_gpsbabel(const std::string& folder, const std::filesystem::path& file, const ReadResult& ours,
                      const std::filesystem::path& scratch, std::vector<Outcome>& extra) {
  const std::string name = folder + "/" + file.filename().string();
  const std::filesystem::path out = scratch / "gpsbabel.gpx";
  std::filesystem::remove(out);
  std::string said;
  const bool ran = run_command("gpsbabel -t -r -w -i " + kGpsbabelFormat.at(folder) + " -f " + shell_quote(file) +
                                   " -o gpx -F " + shell_quote(out) + " 2>&1",
                               said);
  if (!ran) return {name, "gpsbabel", "cannot read: gpsbabel", last_line(said)};
  const ReadResult theirs = load_track_file(out.string());
  if (!theirs.ok()) return {name, "gpsbabel", "cannot read: gpsbabel", "its GPX: " + theirs.error->to_string()};
  if (folder == "igc") extra.push_back(compare_igc_task(name, file, theirs.file));
  if (!ours.ok()) {
    const Lines l = lines_of(theirs.file);
    const std::size_t points = points_in(l.tracks) + points_in(l.routes) + l.waypoints.size();
    if (points == 0) return {name, "gpsbabel", "cannot read: trailray", "(gpsbabel finds nothing) " + ours.error->message};
    return {name, "gpsbabel", "cannot read: trailray", ours.error->message};
  }
  std::string why;
  if (folder == "igc") {
    why = compare_igc(ours.file, theirs.file);
  } else {
    Lines a = lines_of(ours.file), b = lines_of(theirs.file, folder == "fit" || folder == "tcx");
    if (folder == "geojson")
      for (Lines* l : {&a, &b}) {
        l->tracks.insert(l->tracks.end(), l->routes.begin(), l->routes.end());
        l->routes.clear();
      }
    why = compare(folder == "geojson" ? "lines" : "tracks", a.tracks, b.tracks, "gpsbabel");
    if (why.empty()) why = compare("routes", a.routes, b.routes, "gpsbabel");
    if (why.empty()) why = compare("waypoints", {a.waypoints}, {b.waypoints}, "gpsbabel");
  }
  return {name, "gpsbabel", why.empty() ? "equal" : "differs", why};
}

// OGR's reading of every KML and GeoJSON file, by path: one process for all of them.
std::map<std::string, json> ogr_readings(const std::vector<std::filesystem::path>& files) {
  std::string command =
      "/usr/bin/python3 " + shell_quote(std::string(TRAILRAY_SOURCE_DIR) + "/tests/conformance/ogr_kml_coordinates.py");
  for (const auto& f : files) command += " " + shell_quote(f.string());
  std::string out;
  EXPECT_TRUE(run_command(command + " 2>/dev/null", out))
      << "the OGR script failed (is python3-gdal installed? run scripts/setup.sh)";
  std::map<std::string, json> readings;
  std::istringstream lines(out);
  for (std::string text; std::getline(lines, text);) {
    if (text.empty() || text.front() != '{') continue;
    json j = json::parse(text);
    const std::string path = j.value("path", "");
    readings[path] = std::move(j);
  }
  return readings;
}

Outcome with_ogr(const std::string& name, const ReadResult& ours, const json* theirs) {
  if (theirs == nullptr || !(*theirs)["ok"].get<bool>()) {
    if (!ours.ok()) return {name, "OGR", "equal", "neither reads it"};
    return {name, "OGR", "cannot read: OGR", theirs == nullptr ? "no answer" : theirs->value("error", "not opened")};
  }
  if (!ours.ok()) return {name, "OGR", "cannot read: trailray", ours.error->message};
  const Lines a = lines_of(ours.file);
  std::vector<Line> our_lines = a.tracks, their_lines, our_points, their_points;
  our_lines.insert(our_lines.end(), a.routes.begin(), a.routes.end());
  for (const json& l : (*theirs)["lines"]) {
    Line& line = their_lines.emplace_back();
    for (const json& p : l) line.push_back({p[1].get<double>(), p[0].get<double>()});
  }
  for (const Point& p : a.waypoints) our_points.push_back({p});
  for (const json& p : (*theirs)["points"]) their_points.push_back({{p[1].get<double>(), p[0].get<double>()}});
  std::string why = compare_unordered("lines", our_lines, their_lines);
  if (why.empty()) why = compare_unordered("points", our_points, their_points);
  return {name, "OGR", why.empty() ? "equal" : "differs", why};
}

void print_table(const std::vector<Outcome>& outcomes) {
  std::size_t width = 4;
  for (const Outcome& o : outcomes) width = std::max(width, o.file.size());
  std::cout << fmt::format("{:<{}}  {:<13}  {:<22}  why\n", "file", width, "reference", "outcome");
  for (const Outcome& o : outcomes) {
    const Known* k = known(o);
    const std::string why = o.status == "equal" ? o.why : k != nullptr ? o.why + " [on purpose: " + k->why + "]" : o.why;
    std::cout << fmt::format("{:<{}}  {:<13}  {:<22}  {}\n", o.file, width, o.reference, o.status, why);
  }
  std::map<std::string, std::map<std::string, int>> totals;
  for (const Outcome& o : outcomes) ++totals[o.reference][o.status];
  for (const auto& [reference, by_status] : totals) {
    std::cout << reference << ":";
    for (const auto& [status, n] : by_status) std::cout << " " << n << " " << status << ";";
    std::cout << "\n";
  }
}

TEST(CorpusConformance, EveryTrackFileReadsAsTheReferenceToolsReadIt) {
  TRAILRAY_REQUIRE_DATA(corpus, "corpus");
  ASSERT_EQ(std::system("gpsbabel -V >/dev/null 2>&1"), 0)
      << "gpsbabel is missing: it is a declared dependency (scripts/setup.sh installs it)";
  const std::filesystem::path scratch = test::make_unique_temp_dir("trailray-corpus-");

  std::vector<std::pair<std::string, std::filesystem::path>> files;  // folder, file
  for (const auto& [folder, format] : kGpsbabelFormat) {
    if (!std::filesystem::is_directory(corpus / folder)) continue;
    for (const auto& e : std::filesystem::directory_iterator(corpus / folder))
      if (e.is_regular_file()) files.emplace_back(folder, e.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 100u) << "the corpus holds about 150 track files";

  std::vector<std::filesystem::path> for_ogr;
  for (const auto& [folder, file] : files)
    if (folder == "kml" || folder == "geojson") for_ogr.push_back(file);
  const std::map<std::string, json> ogr = ogr_readings(for_ogr);

  std::vector<Outcome> outcomes;
  for (const auto& [folder, file] : files) {
    SCOPED_TRACE(file.string());
    const ReadResult ours = load_track_file(file.string());
    std::vector<Outcome> extra;
    outcomes.push_back(with_gpsbabel(folder, file, ours, scratch, extra));
    outcomes.insert(outcomes.end(), extra.begin(), extra.end());
    if (folder == "kml" || folder == "geojson") {
      const auto it = ogr.find(file.string());
      outcomes.push_back(with_ogr(folder + "/" + file.filename().string(), ours, it == ogr.end() ? nullptr : &it->second));
    }
  }
  std::filesystem::remove_all(scratch);
  print_table(outcomes);

  for (const Outcome& o : outcomes) {
    const Known* k = known(o);
    if (o.status == "equal") {
      EXPECT_EQ(k, nullptr) << o.file << " (" << o.reference
                            << ") now reads as the reference does: take it out of kKnown";
    } else if (k == nullptr) {
      ADD_FAILURE() << o.file << " (" << o.reference << "): " << o.status << ": " << o.why;
    } else {
      EXPECT_EQ(o.status, k->status) << o.file << " (" << o.reference << "): " << o.why;
    }
  }
  for (const Known& k : kKnown)
    EXPECT_TRUE(std::any_of(outcomes.begin(), outcomes.end(),
                            [&](const Outcome& o) { return o.file == k.file && o.reference == k.reference; }))
        << k.file << " (" << k.reference << ") is in kKnown but not in the corpus";
}

}  // namespace
}  // namespace trailray::track
