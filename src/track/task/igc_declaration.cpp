// IGC task declarations (IGC specification, C records): a first C record
//   C DDMMYY HHMMSS FDDMMYY NNNN TT [text]   (declared, flight date, task number, TT turnpoints)
// then TT + 4 records C DDMMmmm[NS] DDDMMmmm[EW] [name]: take-off, start, the TT turnpoints,
// finish, landing. A position of all zeros means "not given" (XCTrack writes its take-off and
// landing so). Radii are not part of the format: every cylinder gets kDefaultRadiusM; the
// start is an exit cylinder without gates, the finish a goal cylinder.

#include <cstdint>
#include <string>

#include "track/io/parse_util.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {

namespace {

bool all_digits(std::string_view s, std::size_t from, std::size_t count) {
  if (from + count > s.size()) return false;
  for (std::size_t i = from; i < from + count; ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

// At most 9 digits: no overflow.
bool digits(std::string_view s, std::size_t from, std::size_t count, long long& out) {
  if (count > 9) return false;
  if (from + count > s.size()) return false;
  out = 0;
  for (std::size_t i = from; i < from + count; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    out = out * 10 + (s[i] - '0');
  }
  return true;
}

struct DeclaredPoint {
  std::int64_t line = 0;
  bool given = false;  // false: all zeros
  double lat = 0.0, lon = 0.0;
  std::string name;
};

// "C DDMMmmm N DDDMMmmm E name": the column of the first bad character, or 0 when it parses.
std::size_t parse_point(std::string_view s, DeclaredPoint& p) {
  long long lat_d = 0, lat_m = 0, lon_d = 0, lon_m = 0;
  if (!digits(s, 1, 2, lat_d) || !digits(s, 3, 5, lat_m)) return 2;
  if (s.size() < 9 || (s[8] != 'N' && s[8] != 'S')) return 9;
  if (!digits(s, 9, 3, lon_d) || !digits(s, 12, 5, lon_m)) return 10;
  if (s.size() < 18 || (s[17] != 'E' && s[17] != 'W')) return 18;
  if (lat_m >= 60000 || lon_m >= 60000) return 4;
  p.lat = (static_cast<double>(lat_d) + static_cast<double>(lat_m) / 60000.0) * (s[8] == 'S' ? -1.0 : 1.0);
  p.lon = (static_cast<double>(lon_d) + static_cast<double>(lon_m) / 60000.0) * (s[17] == 'W' ? -1.0 : 1.0);
  if (p.lat < -90.0 || p.lat > 90.0) return 2;
  if (p.lon < -180.0 || p.lon > 180.0) return 10;
  p.given = lat_d != 0 || lat_m != 0 || lon_d != 0 || lon_m != 0;
  p.name = std::string(trim(s.substr(18)));
  return 0;
}

}  // namespace

TaskReadResult read_igc_declaration(std::string_view text, const std::string& file) {
  TaskReadResult result;
  std::vector<DeclaredPoint> points;
  std::int64_t header_line = 0;
  long long declared_count = -1;
  std::int64_t line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line[0] != 'C') continue;
    if (header_line == 0) {
      // The header is 25 characters of digits; a position record has N/S at column 9.
      if (line.size() >= 25 && all_digits(line, 1, 24)) {
        header_line = line_number;
        digits(line, 23, 2, declared_count);
        continue;
      }
      result.warnings.push_back(
          Diagnostic{file, {line_number, 1, -1}, "C record before the declaration's first record: read as a point"});
      header_line = -1;
    }
    DeclaredPoint p;
    p.line = line_number;
    if (const std::size_t column = parse_point(line, p); column != 0) {
      result.error = Diagnostic{file,
                                {line_number, static_cast<std::int64_t>(column), -1},
                                "C record: expected DDMMmmmN DDDMMmmmE and a name"};
      return result;
    }
    points.push_back(std::move(p));
  }
  if (points.empty()) {
    result.error = Diagnostic{file, {}, "no task declaration (IGC C records)"};
    return result;
  }
  if (declared_count >= 0 && static_cast<long long>(points.size()) != declared_count + 4)
    result.warnings.push_back(Diagnostic{file,
                                         {header_line, 24, -1},
                                         "the declaration names " + std::to_string(declared_count) +
                                             " turnpoints but has " + std::to_string(points.size()) +
                                             " points (take-off, start, turnpoints, finish, landing expected)"});

  // Roles by place: the first is the take-off, the second the start, the last the landing and
  // the one before it the finish; with fewer than 4 points, start and finish only.
  const std::size_t n = points.size();
  Task task;
  task.format = TaskFormat::IgcDeclaration;
  for (std::size_t i = 0; i < n; ++i) {
    Role role = Role::Turnpoint;
    if (n >= 4) {
      if (i == 0)
        role = Role::Takeoff;
      else if (i == 1)
        role = Role::Sss;
      else if (i == n - 2)
        role = Role::Goal;
      else if (i == n - 1)
        continue;  // the landing is not part of the task
    } else {
      if (i == 0)
        role = Role::Sss;
      else if (i == n - 1)
        role = Role::Goal;
    }
    const DeclaredPoint& p = points[i];
    if (!p.given) {
      if (role != Role::Takeoff)
        result.warnings.push_back(Diagnostic{
            file, {p.line, 2, -1}, std::string("the ") + role_name(role) + " has no position (zeros): left out"});
      continue;
    }
    Turnpoint tp;
    tp.name = p.name.empty() ? "C" + std::to_string(p.line) : p.name;
    tp.lat = p.lat;
    tp.lon = p.lon;
    tp.role = role;
    tp.radius_m = role == Role::Takeoff ? 0.0 : kDefaultRadiusM;
    task.turnpoints.push_back(std::move(tp));
  }
  if (task.turnpoints.empty()) {
    result.error = Diagnostic{file, {header_line > 0 ? header_line : 0, 0, -1}, "the declaration has no positions"};
    return result;
  }
  if (task.sss_index() >= 0) task.sss = StartSection{SssType::ElapsedTime, Direction::Exit, {}};
  result.task = std::move(task);
  return result;
}

}  // namespace trailray::track::task
