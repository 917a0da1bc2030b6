// IGC flight recorder reader (FAI IGC technical specification, appendix A): one Track with
// one Segment of B-record fixes in file order, the H-record headers as metadata fields.
//
// Records read: A (recorder -> metadata.creator), H (headers, HFDTE flight date), I (B-record
// extensions; LAD/LOD extra coordinate digits are applied, the others are checked but not
// kept: the model has no channel for them and TAS/GSP units differ between recorders), B
// (fixes). Every other record type (C, D, E, F, G, J, K, L, ...) is ignored.
//
// Elevation rule (ReadOptions::igc_altitude), decided per file after reading every fix:
//   A channel whose value is 0 on every kept fix is "absent": XCTrack and other phone apps
//   write pressure altitude 00000 when there is no barometer, some recorders write GNSS
//   altitude 00000. A single 0 in a channel that is present elsewhere is kept as 0 (sea level
//   is real; dropouts are left to cleaning).
//   Auto:     GNSS altitude on 'A' (3D) fixes when the GNSS channel is present; otherwise
//             (a 'V' fix, or no GNSS channel) pressure altitude when that channel is present;
//             otherwise no elevation. Note that a file mixing 'A' and 'V' fixes with both
//             channels present then switches channel (GNSS is ellipsoid/geoid based, pressure
//             is ISA based: they can differ by tens of metres).
//   Gnss:     GNSS altitude on every fix, except 'V' fixes whose GNSS altitude is 0 (no 3D
//             solution); no elevation at all, with a warning, when the channel is absent.
//   Pressure: pressure altitude on every fix; no elevation, with a warning, when absent.
// Whichever of these `ele` gets, every fix also keeps its pressure altitude in
// TrackPoint::pressure_altitude when the pressure channel is present (NaN when absent), and its
// GNSS altitude in TrackPoint::gnss_altitude by the Gnss rule above (NaN when the channel is
// absent, or on a 'V' fix whose GNSS altitude is 0), so the viewer can show both altitudes.
//
// Time rule: B times are UTC time of day on the HFDTE flight date. A time more than 12 hours
// earlier than the previous fix's is a UTC midnight rollover (next day); smaller backward
// steps are kept as recorded (cleaning deals with them). Without a readable HFDTE record the
// times are kept as time of day on 1970-01-01, with the warning "no HFDTE date record".

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "track/io/igc_fields.hpp"
#include "track/io/igc_parser.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kMaxLine = 4096;  // IGC lines are at most 76 characters (+ L comments)

}  // namespace

namespace detail {

void IgcParser::long_line(std::int64_t line_no, std::int64_t offset) {
  warnings_.add("long-line", SourcePosition{line_no, 1, offset},
                "line longer than " + std::to_string(kMaxLine) + " bytes ignored (not an IGC record)");
}

bool IgcParser::finish(ReadResult& result, const std::string& name) {
  if (!seen_a_ && !seen_h_ && points().empty()) {
    result.error =
        Diagnostic{name, SourcePosition{1, 1, 0}, "not an IGC file: no A record, no H records and no valid B records"};
    file_.tracks.clear();
    return false;
  }
  file_.metadata.activity_type = "flight";
  if (b_lines_ == 0) warnings_.add_single({}, "no B records: the file has no fixes");

  const double base = date_days_ ? static_cast<double>(*date_days_) * 86400.0 : 0.0;
  if (date_days_) {
    file_.metadata.time = base;
  } else if (!points().empty()) {
    warnings_.add_single({}, "no HFDTE date record: times have no date (kept as time of day on 1970-01-01)");
  }
  for (TrackPoint& p : points()) p.time += base;
  assign_elevation();
  return true;
}

void IgcParser::assign_elevation() {
  using Mode = ReadOptions::IgcAltitude;
  auto& pts = points();
  if (pts.empty()) return;
  const Mode mode = options_.igc_altitude;
  if (mode == Mode::Gnss && !gnss_present_)
    warnings_.add_single({}, "GNSS altitude is 0 on every fix (not recorded): points have no elevation");
  if (mode == Mode::Pressure && !pressure_present_)
    warnings_.add_single({}, "pressure altitude is 0 on every fix (no barometer): points have no elevation");
  if (mode == Mode::Auto && !gnss_present_ && !pressure_present_)
    warnings_.add_single({}, "GNSS and pressure altitude are 0 on every fix: points have no elevation");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const RawAltitude& a = altitudes_[i];
    double ele = kMissing;
    switch (mode) {
      case Mode::Auto:
        if (a.fix_3d && gnss_present_)
          ele = a.gnss;
        else if (pressure_present_)
          ele = a.pressure;
        break;
      case Mode::Gnss:
        if (gnss_present_ && (a.fix_3d || a.gnss != 0)) ele = a.gnss;
        break;
      case Mode::Pressure:
        if (pressure_present_) ele = a.pressure;
        break;
    }
    pts[i].ele = ele;
    if (pressure_present_) pts[i].pressure_altitude = static_cast<float>(a.pressure);
    if (gnss_present_ && (a.fix_3d || a.gnss != 0)) pts[i].gnss_altitude = static_cast<float>(a.gnss);
  }
}

}  // namespace detail

using detail::IgcParser;

namespace {

// A site header that names no site: loggers write placeholders ("HFSITSite: None", "HOSITSite:?",
// "NIL") where the pilot entered none. The metadata keeps it as written; the name leaves it out.
bool placeholder_site(std::string_view site) {
  while (!site.empty() && (site.front() == ' ' || site.front() == '\t')) site.remove_prefix(1);
  while (!site.empty() && (site.back() == ' ' || site.back() == '\t')) site.remove_suffix(1);
  if (site.find_first_not_of("?-_.*/ ") == std::string_view::npos) return true;  // also empty
  std::string lower(site);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* p : {"none", "nil", "null", "n/a", "na", "unknown", "not set", "undefined"})
    if (lower == p) return true;
  return false;
}

// "Flight 2024-07-14 from Amisbühl": the date and take-off site, never the pilot (IGC headers
// carry personal data), so tables and legends can tell flights apart.
void name_flight(TrackFile& file) {
  if (file.tracks.empty()) return;
  std::string date, site;
  for (const auto& [key, value] : file.metadata.fields) {
    if (key == "date" && date.empty()) date = value;
    if (key == "site" && site.empty()) site = value;
  }
  std::string name = "Flight";
  if (!date.empty()) name += " " + date;
  if (!placeholder_site(site)) name += " from " + site;
  file.tracks.front().name = name;
}

}  // namespace

ReadResult read_igc(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Igc;
  WarningCollector warnings(source.display_name());
  try {
    result.file.tracks.emplace_back();
    result.file.tracks.front().segments.emplace_back();
    IgcParser parser(result, warnings, options);
    LineReader reader(source, kMaxLine);
    std::string_view line;
    while (reader.next(line)) {
      if (reader.last_line_cut()) {
        parser.long_line(reader.line_number(), reader.line_offset());
        continue;
      }
      parser.line(line, reader.line_number(), reader.line_offset(), reader.last_line_unterminated());
    }
    if (reader.read_failed()) {
      warnings.add_single(SourcePosition{reader.line_number() + 1, 0, -1},
                          "read error: " + source.error() + "; kept the " + std::to_string(parser.points().size()) +
                              " complete points before it");
    }
    parser.finish(result, source.display_name());
    name_flight(result.file);
  } catch (const std::bad_alloc&) {
    result.file.tracks.clear();
    result.error = Diagnostic{source.display_name(), {}, "out of memory while reading the IGC file"};
  }
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
