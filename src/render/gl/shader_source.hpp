#pragma once
// GLSL ES 3.00 sources: the shader files under src/render/shaders/, embedded into the binary at
// build time (cmake/EmbedShaders.cmake: `#include "snippet.glsl"` expanded, checked by
// glslangValidator), and sources made at run time (tests). Each carries a line map, so a
// driver's error on line 57 of an expanded shader is reported as "srgb.glsl:9".

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace trailray::render {

enum class ShaderStage { vertex, fragment };
std::string_view to_string(ShaderStage stage);  // "vertex", "fragment"

// Lines [first_line, first_line + line_count) of an expanded source are lines
// [file_first_line, ...) of `file` (1-based, like every compiler's line numbers).
struct ShaderLineSegment {
  int first_line = 1, line_count = 0;
  std::string file;
  int file_first_line = 1;
};

struct ShaderLocation {
  std::string file;
  int line = 0;
};

struct ShaderSource {
  std::string name;  // the stage file's name, e.g. "fullscreen_triangle.vert"
  ShaderStage stage = ShaderStage::vertex;
  std::string text;
  std::vector<ShaderLineSegment> line_map;  // empty: every line is the named file's own

  // Where line `line` (1-based) of `text` was written.
  ShaderLocation locate(int line) const;
  // Line `line` of `text` without its newline; empty when out of range.
  std::string_view line_text(int line) const;
};

// The stage a file name says: ".vert" -> vertex, ".frag" -> fragment; throws RenderError for
// any other name.
ShaderStage stage_from_file_name(std::string_view name);

// A source written at run time, named like a file ("broken.frag") for its stage and messages.
ShaderSource shader_from_text(std::string name, std::string text);

// An embedded shader by file name ("fullscreen_triangle.vert"); throws RenderError listing the
// embedded names when there is none by that name. Thread-safe; the reference stays valid.
const ShaderSource& embedded_shader(std::string_view name);
std::vector<std::string> embedded_shader_names();  // sorted

// Rewrites the lines of a driver's info log that point into the source ("0:12(3): error: ...",
// Mesa; "0(12) : error C0000: ...", NVIDIA; "ERROR: 0:12: ...", ANGLE and glslang) as
// "file.frag:12:3: error: ...", with the file and line through the source's line map, and
// quotes the offending source line under each. Other lines are kept as they are.
std::string map_info_log(std::string_view log, const ShaderSource& source);

namespace detail {
// The layout of the build-generated embedded_shaders.cpp (cmake/EmbedShaders.cmake).
struct EmbeddedLineSegment {
  int first_line, line_count;
  const char* file;
  int file_first_line;
};
struct EmbeddedShaderFile {
  const char* name;
  const unsigned char* text;  // NUL-terminated; `size` bytes before it
  std::size_t size;
  const EmbeddedLineSegment* line_map;
  std::size_t line_map_size;
};
std::span<const EmbeddedShaderFile> embedded_shader_files();
}  // namespace detail

}  // namespace trailray::render
