// Compiling and linking against the real driver: errors name the file and line; uniforms.

#include "render/gl/shader_program.hpp"

#include <gtest/gtest.h>

#include "gl_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

constexpr const char* kBrokenFragment =
    "#version 300 es\n"
    "precision highp float;\n"
    "out vec4 frag_color;\n"
    "\n"
    "void main() {\n"
    "  frag_color = colour;\n"
    "}\n";

class ShaderProgramTest : public GlTest {};

TEST_F(ShaderProgramTest, EmbeddedShadersCompileAndLink) {
  for (const char* fragment : {"solid_color.frag", "uv_gradient.frag", "encode_srgb.frag"}) {
    const ShaderProgram program = ShaderProgram::from_embedded("fullscreen_triangle.vert", fragment);
    EXPECT_TRUE(glIsProgram(program.id()));
    EXPECT_EQ(program.name(), std::string("fullscreen_triangle.vert + ") + fragment);
  }
}

TEST_F(ShaderProgramTest, ACompileErrorNamesTheFileAndLineAndQuotesIt) {
  try {
    ShaderProgram(embedded_shader("fullscreen_triangle.vert"), shader_from_text("broken.frag", kBrokenFragment));
    FAIL() << "a broken shader compiled";
  } catch (const ShaderError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with("shader broken.frag (fragment) does not compile:\nbroken.frag:6")) << message;
    EXPECT_TRUE(contains(message, "colour")) << message;
    EXPECT_TRUE(contains(message, "\n    6 |   frag_color = colour;")) << message;
  }
}

TEST_F(ShaderProgramTest, AnErrorInAnIncludedSnippetNamesTheSnippet) {
  // As the build expands `#include "tone.glsl"` on line 3 of post.frag (see shader_source.hpp).
  ShaderSource source = shader_from_text("post.frag",
                                         "#version 300 es\n"
                                         "precision highp float;\n"
                                         "vec3 tone(vec3 c) {\n"
                                         "  return c * exposure;\n"
                                         "}\n"
                                         "out vec4 frag_color;\n"
                                         "void main() { frag_color = vec4(tone(vec3(1.0)), 1.0); }\n");
  source.line_map = {{1, 2, "post.frag", 1}, {3, 3, "tone.glsl", 1}, {6, 2, "post.frag", 4}};
  try {
    ShaderProgram(embedded_shader("fullscreen_triangle.vert"), source);
    FAIL() << "a broken shader compiled";
  } catch (const ShaderError& error) {
    EXPECT_TRUE(contains(error.what(), "\ntone.glsl:2")) << error.what();
    EXPECT_TRUE(contains(error.what(), "exposure")) << error.what();
  }
}

TEST_F(ShaderProgramTest, ALinkErrorNamesBothShaders) {
  // The fragment shader reads a varying the vertex shader never writes.
  const ShaderSource fragment = shader_from_text("needs_normal.frag",
                                                 "#version 300 es\n"
                                                 "precision highp float;\n"
                                                 "in vec3 v_normal;\n"
                                                 "out vec4 frag_color;\n"
                                                 "void main() { frag_color = vec4(v_normal, 1.0); }\n");
  try {
    ShaderProgram(embedded_shader("fullscreen_triangle.vert"), fragment);
    FAIL() << "mismatched stages linked";
  } catch (const ShaderError& error) {
    EXPECT_TRUE(contains(error.what(), "program fullscreen_triangle.vert + needs_normal.frag does not link:\n"))
        << error.what();
    EXPECT_TRUE(contains(error.what(), "v_normal")) << error.what();
  }
}

TEST_F(ShaderProgramTest, AStageInTheWrongRoleIsRefused) {
  EXPECT_THROW(ShaderProgram(embedded_shader("solid_color.frag"), embedded_shader("uv_gradient.frag")), RenderError);
}

TEST_F(ShaderProgramTest, UniformsAreFoundAndUnusedOnesAreMinusOne) {
  const ShaderProgram program = ShaderProgram::from_embedded("fullscreen_triangle.vert", "solid_color.frag");
  EXPECT_TRUE(program.has_uniform("u_color"));
  EXPECT_EQ(program.uniform_location("u_color"), glGetUniformLocation(program.id(), "u_color"));
  EXPECT_EQ(program.uniform_location("u_no_such_uniform"), -1);
  program.set_vec4("u_color", 0.25f, 0.5f, 0.75f, 1.0f);
  program.set_float("u_no_such_uniform", 1.0f);  // ignored, like GL does
  GLfloat value[4] = {};
  glGetUniformfv(program.id(), program.uniform_location("u_color"), value);
  EXPECT_EQ(value[0], 0.25f);
  EXPECT_EQ(value[1], 0.5f);
  EXPECT_EQ(value[2], 0.75f);
  EXPECT_EQ(value[3], 1.0f);
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(static_cast<GLuint>(current), program.id());  // setters make the program current
  EXPECT_FALSE(program.bind_uniform_block("NoSuchBlock", 0));
}

}  // namespace
}  // namespace trailray::render
