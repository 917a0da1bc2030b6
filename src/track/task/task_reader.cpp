#include "track/task/task_reader.hpp"

#include <fstream>
#include <sstream>

#include "track/io/parse_util.hpp"

namespace trailray::track::task {

TaskReadResult read_task_file(const std::string& path) {
  TaskReadResult result;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    result.error = Diagnostic{path, {}, "cannot open the task file"};
    return result;
  }
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxTaskBytes) {
      result.error =
          Diagnostic{path, {}, "bigger than " + std::to_string(kMaxTaskBytes >> 20) + " MiB: not a task file"};
      return result;
    }
  }
  if (in.bad()) {
    result.error = Diagnostic{path, {}, "read error"};
    return result;
  }
  return read_task_text(text, path);
}

TaskReadResult read_task_text(std::string_view text, const std::string& file) {
  std::string_view body = trim(text);
  if (body.starts_with("\xEF\xBB\xBF")) body = trim(body.substr(3));
  if (body.starts_with("{") || body.starts_with("XCTSK:")) return read_xctsk(text, file);
  if (body.starts_with("<")) return read_xcsoar_task(text, file);  // XML: XCSoar's <Task>
  // An IGC file: records are one letter at the start of a line; C records hold the task.
  if (body.starts_with("A") || body.starts_with("H") || body.starts_with("C")) return read_igc_declaration(text, file);
  TaskReadResult result;
  result.error = Diagnostic{file, {1, 1, -1}, "not a task: expected an XCTrack task (JSON or XCTSK:), an XCSoar task (.tsk) or an IGC file"};
  return result;
}

}  // namespace trailray::track::task
