#include "render/gl/shader_program.hpp"

#include <algorithm>
#include <vector>

namespace trailray::render {
namespace {

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  if (length <= 1) return {};
  std::vector<char> text(static_cast<std::size_t>(length));
  GLsizei written = 0;
  if (is_program)
    glGetProgramInfoLog(object, length, &written, text.data());
  else
    glGetShaderInfoLog(object, length, &written, text.data());
  return std::string(text.data(), static_cast<std::size_t>(std::max(written, 0)));
}

Shader compile(const ShaderSource& source, ShaderStage expected_stage) {
  if (source.stage != expected_stage)
    throw RenderError("shader " + source.name + " is a " + std::string(to_string(source.stage)) + " shader, used as " +
                      std::string(to_string(expected_stage)) + " shader");
  Shader shader = Shader::create(expected_stage == ShaderStage::vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
  const char* text = source.text.c_str();
  const GLint length = static_cast<GLint>(source.text.size());
  glShaderSource(shader.id(), 1, &text, &length);
  glCompileShader(shader.id());
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE) {
    std::string log = map_info_log(info_log(shader.id(), false), source);
    if (log.empty()) log = "(the driver gave no log)";
    throw ShaderError("shader " + source.name + " (" + std::string(to_string(source.stage)) + ") does not compile:\n" +
                      log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment)
    : name_(vertex.name + " + " + fragment.name) {
  const Shader vertex_shader = compile(vertex, ShaderStage::vertex);
  const Shader fragment_shader = compile(fragment, ShaderStage::fragment);
  program_ = Program::create();
  glAttachShader(program_.id(), vertex_shader.id());
  glAttachShader(program_.id(), fragment_shader.id());
  glLinkProgram(program_.id());
  GLint linked = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &linked);
  // The program keeps its code once linked; the shader objects are deleted with their owners.
  glDetachShader(program_.id(), vertex_shader.id());
  glDetachShader(program_.id(), fragment_shader.id());
  if (linked != GL_TRUE) {
    std::string log = info_log(program_.id(), true);
    while (!log.empty() && (log.back() == '\n' || log.back() == '\0')) log.pop_back();
    throw ShaderError("program " + name_ + " does not link:\n" + (log.empty() ? "(the driver gave no log)" : log));
  }
}

ShaderProgram ShaderProgram::from_embedded(std::string_view vertex_file, std::string_view fragment_file) {
  return ShaderProgram(embedded_shader(vertex_file), embedded_shader(fragment_file));
}

void ShaderProgram::use() const { glUseProgram(program_.id()); }

GLint ShaderProgram::uniform_location(std::string_view uniform) const {
  if (const auto it = uniform_locations_.find(uniform); it != uniform_locations_.end()) return it->second;
  const std::string key(uniform);
  const GLint location = glGetUniformLocation(program_.id(), key.c_str());
  uniform_locations_.emplace(key, location);
  return location;
}

GLint ShaderProgram::use_and_locate(std::string_view uniform) const {
  use();
  return uniform_location(uniform);
}

void ShaderProgram::set_int(std::string_view uniform, int value) const { glUniform1i(use_and_locate(uniform), value); }
void ShaderProgram::set_float(std::string_view uniform, float value) const {
  glUniform1f(use_and_locate(uniform), value);
}
void ShaderProgram::set_vec2(std::string_view uniform, float x, float y) const {
  glUniform2f(use_and_locate(uniform), x, y);
}
void ShaderProgram::set_vec3(std::string_view uniform, float x, float y, float z) const {
  glUniform3f(use_and_locate(uniform), x, y, z);
}
void ShaderProgram::set_vec4(std::string_view uniform, float x, float y, float z, float w) const {
  glUniform4f(use_and_locate(uniform), x, y, z, w);
}
void ShaderProgram::set_mat3(std::string_view uniform, std::span<const float, 9> column_major) const {
  glUniformMatrix3fv(use_and_locate(uniform), 1, GL_FALSE, column_major.data());
}
void ShaderProgram::set_mat4(std::string_view uniform, std::span<const float, 16> column_major) const {
  glUniformMatrix4fv(use_and_locate(uniform), 1, GL_FALSE, column_major.data());
}

bool ShaderProgram::bind_uniform_block(std::string_view block, GLuint binding) const {
  const std::string name(block);
  const GLuint index = glGetUniformBlockIndex(program_.id(), name.c_str());
  if (index == GL_INVALID_INDEX) return false;
  glUniformBlockBinding(program_.id(), index, binding);
  return true;
}

}  // namespace trailray::render
