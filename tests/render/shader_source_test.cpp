// Shader sources: the embedded files and their line maps, and driver logs mapped to files and
// lines (pure CPU; shader_program_test.cpp does the same against the real driver).

#include "render/gl/shader_source.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

std::string read_shader_file(const std::string& name) {
  std::ifstream in(std::filesystem::path(TRAILRAY_SOURCE_DIR) / "src/render/shaders" / name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The 1-based number of the line of `text` that contains `part`; 0 when none does.
int line_containing(std::string_view text, std::string_view part) {
  int line = 1;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (text.substr(start, end - start).find(part) != std::string_view::npos) return line;
    start = end + 1;
    ++line;
  }
  return 0;
}

// A source as the build makes it: top.frag's lines 1-2, then snippet.glsl's 1-3, then top.frag
// from line 4 (line 3 was the #include).
ShaderSource expanded_source() {
  ShaderSource source = shader_from_text("top.frag",
                                         "#version 300 es\n"
                                         "precision highp float;\n"
                                         "vec3 f() {\n"
                                         "  return vec3(1.0) +;\n"
                                         "}\n"
                                         "out vec4 c;\n"
                                         "void main() { c = vec4(f(), 1.0); }\n");
  source.line_map = {{1, 2, "top.frag", 1}, {3, 3, "snippet.glsl", 1}, {6, 2, "top.frag", 4}};
  return source;
}

TEST(ShaderSource, TheShaderFilesAreEmbeddedWithTheirStages) {
  const std::vector<std::string> names = embedded_shader_names();
  for (const char* name : {"fullscreen_triangle.vert", "solid_color.frag", "uv_gradient.frag", "encode_srgb.frag"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  // Snippets are included into stages, not embedded on their own.
  EXPECT_EQ(std::find(names.begin(), names.end(), "srgb.glsl"), names.end());
  EXPECT_EQ(embedded_shader("fullscreen_triangle.vert").stage, ShaderStage::vertex);
  EXPECT_EQ(embedded_shader("solid_color.frag").stage, ShaderStage::fragment);
  // A file without includes is embedded byte for byte.
  EXPECT_EQ(embedded_shader("solid_color.frag").text, read_shader_file("solid_color.frag"));
  EXPECT_EQ(embedded_shader("uv_gradient.frag").text, read_shader_file("uv_gradient.frag"));
}

TEST(ShaderSource, AnIncludeIsExpandedAndItsLinesMapBackToTheSnippet) {
  const ShaderSource& source = embedded_shader("encode_srgb.frag");
  const std::string top = read_shader_file("encode_srgb.frag");
  const std::string snippet = read_shader_file("srgb.glsl");
  EXPECT_EQ(source.text.find("#include"), std::string::npos);
  EXPECT_NE(source.text.find(snippet), std::string::npos);  // the snippet, whole
  EXPECT_EQ(line_containing(source.text, "#version"), 1);
  for (std::string_view part : {"vec3 linear_to_srgb(vec3 linear)", "vec3 srgb_to_linear(vec3 srgb)"}) {
    const ShaderLocation where = source.locate(line_containing(source.text, part));
    EXPECT_EQ(where.file, "srgb.glsl") << part;
    EXPECT_EQ(where.line, line_containing(snippet, part)) << part;
  }
  for (std::string_view part :
       {"#version 300 es", "precision highp float;", "uniform vec4 u_linear_color;", "void main()"}) {
    const ShaderLocation where = source.locate(line_containing(source.text, part));
    EXPECT_EQ(where.file, "encode_srgb.frag") << part;
    EXPECT_EQ(where.line, line_containing(top, part)) << part;
  }
}

TEST(ShaderSource, UnknownNamesAndStagesAreClearErrors) {
  try {
    embedded_shader("nope.frag");
    FAIL() << "an unknown shader was found";
  } catch (const RenderError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with("no embedded shader 'nope.frag' (embedded: ")) << message;
    EXPECT_NE(message.find("solid_color.frag"), std::string::npos) << message;
  }
  EXPECT_EQ(stage_from_file_name("a/b/sky.vert"), ShaderStage::vertex);
  EXPECT_EQ(stage_from_file_name("sky.frag"), ShaderStage::fragment);
  EXPECT_THROW(stage_from_file_name("sky.glsl"), RenderError);
  EXPECT_THROW(shader_from_text("sky.comp", "#version 310 es\n"), RenderError);
}

TEST(ShaderSource, LocateAndLineTextFollowTheLineMap) {
  const ShaderSource source = expanded_source();
  EXPECT_EQ(source.locate(1).file, "top.frag");
  EXPECT_EQ(source.locate(4).file, "snippet.glsl");
  EXPECT_EQ(source.locate(4).line, 2);
  EXPECT_EQ(source.locate(7).file, "top.frag");
  EXPECT_EQ(source.locate(7).line, 5);
  EXPECT_EQ(source.locate(99).file, "top.frag");  // past the map: the stage file, as counted
  EXPECT_EQ(source.line_text(4), "  return vec3(1.0) +;");
  EXPECT_EQ(source.line_text(8), "");
  EXPECT_EQ(source.line_text(0), "");
  const ShaderSource plain = shader_from_text("plain.vert", "a\nb\n");
  EXPECT_EQ(plain.locate(2).file, "plain.vert");
  EXPECT_EQ(plain.locate(2).line, 2);
}

TEST(ShaderSource, MesaLogsNameFileLineAndColumn) {
  const std::string mapped =
      map_info_log("0:4(22): error: syntax error, unexpected ';'\n0:7(19): error: `f' undeclared\n", expanded_source());
  EXPECT_EQ(mapped,
            "snippet.glsl:2:22: error: syntax error, unexpected ';'\n"
            "    2 |   return vec3(1.0) +;\n"
            "top.frag:5:19: error: `f' undeclared\n"
            "    5 | void main() { c = vec4(f(), 1.0); }");
}

TEST(ShaderSource, NvidiaAndGlslangLogsToo) {
  EXPECT_EQ(map_info_log("0(4) : error C0000: syntax error, unexpected ';'", expanded_source()),
            "snippet.glsl:2: error C0000: syntax error, unexpected ';'\n    2 |   return vec3(1.0) +;");
  EXPECT_EQ(map_info_log("ERROR: 0:6: 'c' : redefinition\nERROR: 1 compilation errors.  No code generated.",
                         expanded_source()),
            "top.frag:4: error: 'c' : redefinition\n    4 | out vec4 c;\n"
            "ERROR: 1 compilation errors.  No code generated.");
}

TEST(ShaderSource, LinesWithoutAPositionAreKept) {
  EXPECT_EQ(map_info_log("\nerror: linking failed\n\n", expanded_source()), "error: linking failed");
  // A line number no int holds is named as it is, not found in the source.
  EXPECT_EQ(map_info_log("0:99999999999999(1): error: x", expanded_source()), "top.frag:0:1: error: x");
}

}  // namespace
}  // namespace trailray::render
