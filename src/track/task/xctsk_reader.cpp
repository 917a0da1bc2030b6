// XCTrack task files. Version 1 is the documented JSON (turnpoints[].waypoint, sss, goal,
// earthModel); version 2 is the compact form of the QR codes ("t" turnpoints with "z" a
// polyline of lon, lat, altitude, radius; "s" and "g" with numeric codes; "T":"W" a plain
// waypoint list). Unknown keys are ignored, as XCTrack ignores them.

#include <nlohmann/json.hpp>

#include <cmath>

#include "track/io/parse_util.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {

namespace {

using json = nlohmann::json;

// Far beyond any task's cylinder, and short of the antipode, where a circle stops being one.
constexpr double kMaxRadiusM = 1.0e6;

// Records the first syntax error's byte offset and message (nlohmann's SAX interface reports it
// without an exception).
struct SyntaxErrorFinder : nlohmann::json_sax<json> {
  std::size_t position = 0;
  std::string message;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& ex) override {
    position = pos;
    message = ex.what();
    return false;
  }
};

SourcePosition line_column(std::string_view text, std::size_t offset) {
  SourcePosition p;
  p.line = 1;
  p.column = 1;
  p.byte_offset = static_cast<std::int64_t>(offset);
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

std::string describe_syntax_error(std::string m) {
  const auto colon = m.find(": ");
  if (m.starts_with("[json.exception") && colon != std::string::npos) m = m.substr(colon + 2);
  if (m.size() > 200) m = m.substr(0, 200) + "...";
  return "invalid JSON: " + m;
}

// The reading of one document: the first error wins, named by its JSON path.
class Reader {
 public:
  Reader(std::string file, TaskReadResult& result) : file_(std::move(file)), result_(result) {}

  bool fail(const std::string& path, const std::string& message) {
    if (!result_.error) result_.error = Diagnostic{file_, {}, path + ": " + message};
    return false;
  }
  void warn(const std::string& path, const std::string& message) {
    result_.warnings.push_back(Diagnostic{file_, {}, path + ": " + message});
  }

  const json* member(const json& object, const char* key) const {
    const auto it = object.find(key);
    return it == object.end() || it->is_null() ? nullptr : &*it;
  }
  bool number(const json& object, const char* key, const std::string& path, double& out, bool required) {
    const json* v = member(object, key);
    if (v == nullptr) return required ? fail(path + "." + key, "missing") : true;
    if (!v->is_number()) return fail(path + "." + key, "expected a number");
    out = v->get<double>();
    if (!std::isfinite(out)) return fail(path + "." + key, "not a finite number");
    return true;
  }
  bool text(const json& object, const char* key, const std::string& path, std::string& out) {
    const json* v = member(object, key);
    if (v == nullptr) return true;
    if (!v->is_string()) return fail(path + "." + key, "expected a string");
    out = v->get<std::string>();
    return true;
  }
  // "HH:MM:SSZ" (XCTrack writes UTC with a Z; "HH:MM" and no Z are accepted).
  bool time_of_day(const json& v, const std::string& path, double& out) {
    if (!v.is_string()) return fail(path, "expected a time \"HH:MM:SSZ\"");
    std::string s = v.get<std::string>();
    if (!s.empty() && (s.back() == 'Z' || s.back() == 'z')) s.pop_back();
    int parts[3] = {0, 0, 0};
    int count = 0;
    std::size_t i = 0;
    while (count < 3) {
      const std::size_t start = i;
      int value = 0;
      while (i < s.size() && i - start < 2 && s[i] >= '0' && s[i] <= '9') value = value * 10 + (s[i++] - '0');
      if (i == start) break;
      parts[count++] = value;
      if (i < s.size() && s[i] == ':')
        ++i;
      else
        break;
    }
    if (count < 2 || i != s.size() || parts[0] > 24 || parts[1] > 59 || parts[2] > 60)
      return fail(path, "expected a time \"HH:MM:SSZ\", got \"" + v.get<std::string>().substr(0, 40) + "\"");
    out = parts[0] * 3600.0 + parts[1] * 60.0 + parts[2];
    return true;
  }
  bool latlon(double lat, double lon, const std::string& path) {
    if (std::abs(lat) > 90.0) return fail(path, "latitude out of range");
    if (std::abs(lon) > 180.0) return fail(path, "longitude out of range");
    return true;
  }

  bool version1(const json& doc, Task& task);
  bool version2(const json& doc, Task& task);

 private:
  bool gates(const json& list, const std::string& path, std::vector<double>& out) {
    if (!list.is_array()) return fail(path, "expected an array of times");
    for (std::size_t i = 0; i < list.size(); ++i) {
      double t = 0.0;
      if (!time_of_day(list[i], path + "[" + std::to_string(i) + "]", t)) return false;
      out.push_back(t);
    }
    return true;
  }
  bool earth_model(const json& doc, Task& task) {
    std::string model;
    if (!text(doc, "earthModel", "", model)) return false;
    if (model.empty()) return true;
    task.earth_stated = true;
    if (model == "FAI_SPHERE")
      task.earth = EarthModel::FaiSphere;
    else if (model != "WGS84")
      warn("earthModel", "unknown earth model \"" + model.substr(0, 40) + "\": WGS84 used");
    return true;
  }
  // The last turnpoint of a task is its goal.
  static void mark_goal(Task& task) {
    if (task.turnpoints.size() >= 2 && task.turnpoints.back().role == Role::Turnpoint)
      task.turnpoints.back().role = Role::Goal;
  }

  std::string file_;
  TaskReadResult& result_;
};

bool Reader::version1(const json& doc, Task& task) {
  task.format = TaskFormat::XctskJson;
  std::string type;
  if (!text(doc, "taskType", "", type)) return false;
  if (!type.empty() && type != "CLASSIC") warn("taskType", "\"" + type.substr(0, 40) + "\" read as CLASSIC");
  if (!earth_model(doc, task)) return false;
  const json* tps = member(doc, "turnpoints");
  if (tps == nullptr) return fail("turnpoints", "missing");
  if (!tps->is_array()) return fail("turnpoints", "expected an array");
  for (std::size_t i = 0; i < tps->size(); ++i) {
    const std::string path = "turnpoints[" + std::to_string(i) + "]";
    const json& t = (*tps)[i];
    if (!t.is_object()) return fail(path, "expected an object");
    Turnpoint tp;
    if (!number(t, "radius", path, tp.radius_m, true)) return false;
    if (tp.radius_m < 0.0 || tp.radius_m > kMaxRadiusM) return fail(path + ".radius", "out of range (0 to 1000 km)");
    std::string role;
    if (!text(t, "type", path, role)) return false;
    if (role == "TAKEOFF")
      tp.role = Role::Takeoff;
    else if (role == "SSS")
      tp.role = Role::Sss;
    else if (role == "ESS")
      tp.role = Role::Ess;
    else if (!role.empty())
      warn(path + ".type", "unknown type \"" + role.substr(0, 40) + "\": read as a turnpoint");
    const json* w = member(t, "waypoint");
    if (w == nullptr) return fail(path + ".waypoint", "missing");
    if (!w->is_object()) return fail(path + ".waypoint", "expected an object");
    const std::string wpath = path + ".waypoint";
    if (!number(*w, "lat", wpath, tp.lat, true) || !number(*w, "lon", wpath, tp.lon, true)) return false;
    if (!latlon(tp.lat, tp.lon, wpath)) return false;
    if (!number(*w, "altSmoothed", wpath, tp.altitude_m, false)) return false;
    if (!text(*w, "name", wpath, tp.name) || !text(*w, "description", wpath, tp.description)) return false;
    task.turnpoints.push_back(std::move(tp));
  }
  if (const json* sss = member(doc, "sss")) {
    if (!sss->is_object()) return fail("sss", "expected an object");
    StartSection s;
    std::string v;
    if (!text(*sss, "type", "sss", v)) return false;
    if (v == "ELAPSED-TIME")
      s.type = SssType::ElapsedTime;
    else if (!v.empty() && v != "RACE")
      warn("sss.type", "unknown start type \"" + v.substr(0, 40) + "\": RACE used");
    v.clear();
    if (!text(*sss, "direction", "sss", v)) return false;
    if (v == "ENTER") s.direction = Direction::Enter;
    if (const json* g = member(*sss, "timeGates"); g != nullptr && !gates(*g, "sss.timeGates", s.gates_s)) return false;
    task.sss = std::move(s);
  }
  if (const json* goal = member(doc, "goal")) {
    if (!goal->is_object()) return fail("goal", "expected an object");
    std::string v;
    if (!text(*goal, "type", "goal", v)) return false;
    if (v == "LINE")
      task.goal_type = GoalType::Line;
    else if (!v.empty() && v != "CYLINDER")
      warn("goal.type", "unknown goal type \"" + v.substr(0, 40) + "\": CYLINDER used");
    if (const json* d = member(*goal, "deadline"); d != nullptr && !time_of_day(*d, "goal.deadline", task.deadline_s))
      return false;
  }
  mark_goal(task);
  return true;
}

bool Reader::version2(const json& doc, Task& task) {
  task.format = TaskFormat::XctskQr;
  std::string kind;
  if (const json* t = member(doc, "T")) {
    if (!t->is_string()) return fail("T", "expected a string");
    kind = t->get<std::string>();
  }
  task.waypoints_only = kind == "W";
  if (const json* e = member(doc, "e")) {
    if (!e->is_number_integer()) return fail("e", "expected 0 (WGS84) or 1 (FAI sphere)");
    task.earth_stated = true;
    if (e->get<long long>() == 1) task.earth = EarthModel::FaiSphere;
  }
  const json* tps = member(doc, "t");
  if (tps == nullptr) return fail("t", "missing");
  if (!tps->is_array()) return fail("t", "expected an array");
  for (std::size_t i = 0; i < tps->size(); ++i) {
    const std::string path = "t[" + std::to_string(i) + "]";
    const json& t = (*tps)[i];
    if (!t.is_object()) return fail(path, "expected an object");
    Turnpoint tp;
    if (!text(t, "n", path, tp.name) || !text(t, "d", path, tp.description)) return false;
    const json* z = member(t, "z");
    if (z == nullptr) return fail(path + ".z", "missing");
    if (!z->is_string()) return fail(path + ".z", "expected a string");
    const auto values = decode_polyline_values(z->get<std::string>());
    if (!values || values->size() < 2)
      return fail(path + ".z", "not a polyline of longitude, latitude[, altitude, radius]");
    tp.lon = static_cast<double>((*values)[0]) * 1e-5;
    tp.lat = static_cast<double>((*values)[1]) * 1e-5;
    if (!latlon(tp.lat, tp.lon, path + ".z")) return false;
    if (values->size() >= 3) tp.altitude_m = static_cast<double>((*values)[2]);
    if (values->size() >= 4) tp.radius_m = static_cast<double>((*values)[3]);
    if (task.waypoints_only) tp.radius_m = 0.0;
    if (tp.radius_m < 0.0 || tp.radius_m > kMaxRadiusM) return fail(path + ".z", "radius out of range (0 to 1000 km)");
    if (const json* type = member(t, "t")) {
      if (!type->is_number_integer()) return fail(path + ".t", "expected 2 (SSS) or 3 (ESS)");
      const long long code = type->get<long long>();
      if (code == 2)
        tp.role = Role::Sss;
      else if (code == 3)
        tp.role = Role::Ess;
      else if (code != 0)
        warn(path + ".t", "unknown type " + std::to_string(code) + ": read as a turnpoint");
    }
    task.turnpoints.push_back(std::move(tp));
  }
  if (task.waypoints_only) return true;
  // The QR form has no code for the take-off (XCTrack leaves it out of "t"): a first turnpoint
  // before the SSS is the take-off, as in the task the code was made from.
  const int sss_at = task.sss_index();
  if (sss_at > 0) task.turnpoints.front().role = Role::Takeoff;
  if (const json* s = member(doc, "s")) {
    if (!s->is_object()) return fail("s", "expected an object");
    StartSection start;
    if (const json* type = member(*s, "t"); type != nullptr && type->is_number_integer() && type->get<long long>() == 2)
      start.type = SssType::ElapsedTime;
    if (const json* d = member(*s, "d"); d != nullptr && d->is_number_integer() && d->get<long long>() == 1)
      start.direction = Direction::Enter;
    if (const json* g = member(*s, "g"); g != nullptr && !gates(*g, "s.g", start.gates_s)) return false;
    task.sss = std::move(start);
  }
  if (const json* g = member(doc, "g")) {
    if (!g->is_object()) return fail("g", "expected an object");
    if (const json* type = member(*g, "t"); type != nullptr && type->is_number_integer() && type->get<long long>() == 1)
      task.goal_type = GoalType::Line;
    if (const json* d = member(*g, "d"); d != nullptr && !time_of_day(*d, "g.d", task.deadline_s)) return false;
  }
  mark_goal(task);
  return true;
}

}  // namespace

std::optional<std::vector<long long>> decode_polyline_values(std::string_view text) {
  std::vector<long long> out;
  std::size_t i = 0;
  while (i < text.size()) {
    unsigned long long value = 0;
    int shift = 0;
    while (true) {
      if (i >= text.size() || shift > 60) return std::nullopt;
      const int c = static_cast<unsigned char>(text[i++]) - 63;
      if (c < 0 || c > 63) return std::nullopt;
      value |= static_cast<unsigned long long>(c & 0x1f) << shift;
      shift += 5;
      if (c < 0x20) break;
    }
    const long long half = static_cast<long long>(value >> 1);
    out.push_back((value & 1) != 0 ? ~half : half);
  }
  return out;
}

TaskReadResult read_xctsk(std::string_view text, const std::string& file) {
  TaskReadResult result;
  std::string_view body = trim(text);
  if (body.starts_with("\xEF\xBB\xBF")) body = trim(body.substr(3));
  const bool qr = body.starts_with("XCTSK:");
  if (qr) body = trim(body.substr(6));
  json doc = json::parse(body.begin(), body.end(), nullptr, false);
  if (doc.is_discarded()) {
    SyntaxErrorFinder finder;
    json::sax_parse(body.begin(), body.end(), &finder);
    const std::size_t offset =
        static_cast<std::size_t>(body.data() - text.data()) + (finder.position > 0 ? finder.position - 1 : 0);
    result.error = Diagnostic{file, line_column(text, offset), describe_syntax_error(finder.message)};
    return result;
  }
  Reader reader(file, result);
  if (!doc.is_object()) {
    reader.fail("$", "expected a JSON object (an XCTrack task)");
    return result;
  }
  Task task;
  long long version = 0;
  for (const char* key : {"version", "V"}) {
    const auto it = doc.find(key);
    if (it != doc.end() && it->is_number_integer()) version = it->get<long long>();
  }
  // Version 2 is the QR form, which has "t" where version 1 has "turnpoints".
  const bool v2 = version == 2 || (version == 0 && doc.contains("t") && !doc.contains("turnpoints"));
  if (version != 0 && version != 1 && version != 2)
    reader.warn("version", "unknown version " + std::to_string(version) + ": read as " + (v2 ? "2" : "1"));
  const bool ok = v2 ? reader.version2(doc, task) : reader.version1(doc, task);
  if (!ok) return result;
  if (qr) task.format = TaskFormat::XctskQr;
  if (task.turnpoints.empty()) {
    reader.fail(v2 ? "t" : "turnpoints", "no turnpoints");
    return result;
  }
  result.task = std::move(task);
  return result;
}

}  // namespace trailray::track::task
