#pragma once
// A linked GLSL ES 3.00 program from a vertex and a fragment source, with its uniforms looked up
// by name. Compile and link errors throw ShaderError, whose message names the shader file and
// line (through the source's line map) and quotes the offending line.

#include <map>
#include <span>
#include <string>
#include <string_view>

#include "render/gl/gl_objects.hpp"
#include "render/gl/render_error.hpp"
#include "render/gl/shader_source.hpp"

namespace trailray::render {

class ShaderError : public RenderError {
 public:
  using RenderError::RenderError;
};

class ShaderProgram {
 public:
  // Compiles both stages and links them (the GL context must be current). Throws ShaderError:
  //   "shader broken.frag (fragment) does not compile:
  //    broken.frag:6:12: error: `colour' undeclared
  //        6 |   frag_color = colour;"
  // or ShaderError "program a.vert + b.frag does not link: ..." with the driver's log; and
  // RenderError when a source is not of the stage its role needs.
  ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment);
  // The same from embedded shader files by name (shader_source.hpp).
  static ShaderProgram from_embedded(std::string_view vertex_file, std::string_view fragment_file);

  GLuint id() const { return program_.id(); }
  const std::string& name() const { return name_; }  // "fullscreen_triangle.vert + solid_color.frag"
  void use() const;

  // The location of an active uniform, -1 for a name the program does not use (GLSL drops
  // unused uniforms, so a variant of a shader may lack one). Looked up once per name.
  GLint uniform_location(std::string_view uniform) const;
  bool has_uniform(std::string_view uniform) const { return uniform_location(uniform) >= 0; }

  // Setters make the program current first (ES 3.0 has no glProgramUniform). Like GL, they do
  // nothing for a uniform the program does not use. Matrices are column-major.
  void set_int(std::string_view uniform, int value) const;
  void set_float(std::string_view uniform, float value) const;
  void set_vec2(std::string_view uniform, float x, float y) const;
  void set_vec3(std::string_view uniform, float x, float y, float z) const;
  void set_vec4(std::string_view uniform, float x, float y, float z, float w) const;
  void set_mat3(std::string_view uniform, std::span<const float, 9> column_major) const;
  void set_mat4(std::string_view uniform, std::span<const float, 16> column_major) const;
  // Binds a uniform block to a binding point; false when the program has no such block.
  bool bind_uniform_block(std::string_view block, GLuint binding) const;

 private:
  // The location for a setter, after making the program current.
  GLint use_and_locate(std::string_view uniform) const;

  Program program_;
  std::string name_;
  mutable std::map<std::string, GLint, std::less<>> uniform_locations_;
};

}  // namespace trailray::render
