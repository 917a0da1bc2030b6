#include "render/gl/shader_source.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <regex>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

std::vector<ShaderSource> load_embedded() {
  std::vector<ShaderSource> sources;
  for (const detail::EmbeddedShaderFile& file : detail::embedded_shader_files()) {
    ShaderSource source;
    source.name = file.name;
    source.stage = stage_from_file_name(source.name);
    source.text.assign(reinterpret_cast<const char*>(file.text), file.size);
    for (std::size_t i = 0; i < file.line_map_size; ++i) {
      const detail::EmbeddedLineSegment& segment = file.line_map[i];
      source.line_map.push_back({segment.first_line, segment.line_count, segment.file, segment.file_first_line});
    }
    sources.push_back(std::move(source));
  }
  std::sort(sources.begin(), sources.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return sources;
}

const std::vector<ShaderSource>& embedded() {
  static const std::vector<ShaderSource> sources = load_embedded();
  return sources;
}

// A log dialect: its pattern, and the groups holding the line, the column (0: none), the message
// and the kind ("ERROR"; 0: part of the message).
struct LogDialect {
  std::regex pattern;
  int line_group, column_group, message_group, kind_group;
};

const std::vector<LogDialect>& log_dialects() {
  static const std::vector<LogDialect> dialects = {
      // Mesa: "0:12(3): error: `foo' undeclared"
      {std::regex(R"(^\d+:(\d+)\((\d+)\): (.*)$)"), 1, 2, 3, 0},
      // NVIDIA: "0(12) : error C1008: undefined variable "foo""
      {std::regex(R"(^\d+\((\d+)\) : (.*)$)"), 1, 0, 2, 0},
      // ANGLE, glslang and several mobile drivers: "ERROR: 0:12: 'foo' : undeclared identifier"
      {std::regex(R"(^(ERROR|WARNING): \d+:(\d+): (.*)$)"), 2, 0, 3, 1},
  };
  return dialects;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// "file:line[:column]: message" plus the quoted source line, for one log line that names a line.
std::string mapped_line(const std::smatch& match, const LogDialect& dialect, const ShaderSource& source) {
  const std::string number = match[static_cast<std::size_t>(dialect.line_group)].str();
  int line = 0;  // stays 0 for a number too large for int: then the line is named, not found
  std::from_chars(number.data(), number.data() + number.size(), line);
  const ShaderLocation where = source.locate(line);
  std::string out = where.file + ":" + std::to_string(where.line);
  if (dialect.column_group) out += ":" + match[static_cast<std::size_t>(dialect.column_group)].str();
  out += ": ";
  if (dialect.kind_group) out += lower(match[static_cast<std::size_t>(dialect.kind_group)].str()) + ": ";
  out += match[static_cast<std::size_t>(dialect.message_group)].str();
  const std::string_view code = source.line_text(line);
  if (!code.empty()) out += "\n    " + std::to_string(where.line) + " | " + std::string(code);
  return out;
}

}  // namespace

std::string_view to_string(ShaderStage stage) { return stage == ShaderStage::vertex ? "vertex" : "fragment"; }

ShaderLocation ShaderSource::locate(int line) const {
  for (const ShaderLineSegment& segment : line_map)
    if (line >= segment.first_line && line < segment.first_line + segment.line_count)
      return {segment.file, segment.file_first_line + (line - segment.first_line)};
  // No map (a source written at run time), or a line past the map (the driver counted one more).
  return {name, line};
}

std::string_view ShaderSource::line_text(int line) const {
  if (line < 1) return {};
  std::string_view rest(text);
  for (int i = 1; i < line; ++i) {
    const std::size_t newline = rest.find('\n');
    if (newline == std::string_view::npos) return {};
    rest.remove_prefix(newline + 1);
  }
  return rest.substr(0, rest.find('\n'));
}

ShaderStage stage_from_file_name(std::string_view name) {
  if (name.ends_with(".vert")) return ShaderStage::vertex;
  if (name.ends_with(".frag")) return ShaderStage::fragment;
  throw RenderError("shader '" + std::string(name) + "': the name must end in .vert or .frag (its stage)");
}

ShaderSource shader_from_text(std::string name, std::string text) {
  ShaderSource source;
  source.stage = stage_from_file_name(name);
  source.name = std::move(name);
  source.text = std::move(text);
  return source;
}

const ShaderSource& embedded_shader(std::string_view name) {
  const std::vector<ShaderSource>& sources = embedded();
  const auto it = std::find_if(sources.begin(), sources.end(), [&](const ShaderSource& s) { return s.name == name; });
  if (it != sources.end()) return *it;
  std::string known;
  for (const ShaderSource& source : sources) known += (known.empty() ? "" : ", ") + source.name;
  throw RenderError("no embedded shader '" + std::string(name) + "' (embedded: " + known + ")");
}

std::vector<std::string> embedded_shader_names() {
  std::vector<std::string> names;
  for (const ShaderSource& source : embedded()) names.push_back(source.name);
  return names;
}

std::string map_info_log(std::string_view log, const ShaderSource& source) {
  std::string out;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string_view::npos) end = log.size();
    std::string line(log.substr(start, end - start));
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.find_first_not_of(" \t") == std::string::npos) continue;
    std::string rewritten = line;
    for (const LogDialect& dialect : log_dialects()) {
      std::smatch match;
      if (std::regex_match(line, match, dialect.pattern)) {
        rewritten = mapped_line(match, dialect, source);
        break;
      }
    }
    out += rewritten + "\n";
  }
  if (!out.empty()) out.pop_back();
  return out;
}

}  // namespace trailray::render
