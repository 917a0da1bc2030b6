#include "render/gl/gl_capabilities.hpp"

#include <algorithm>
#include <charconv>
#include <tuple>

#include "render/gl/gl_api.hpp"

namespace trailray::render {
namespace {

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

int gl_integer(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

// Parses the decimal number at the front of `text`, advancing it; nullopt when there is none.
std::optional<int> take_number(std::string_view& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data()) return std::nullopt;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return value;
}

std::string yes_no(bool present) { return present ? "yes" : "no"; }

}  // namespace

std::optional<std::pair<int, int>> parse_gles_version(std::string_view gl_version) {
  // The ES specification fixes the form: "OpenGL ES N.M vendor-specific information".
  constexpr std::string_view kPrefix = "OpenGL ES ";
  if (!gl_version.starts_with(kPrefix)) return std::nullopt;
  std::string_view rest = gl_version.substr(kPrefix.size());
  const std::optional<int> major = take_number(rest);
  if (!major || !rest.starts_with('.')) return std::nullopt;
  rest.remove_prefix(1);
  const std::optional<int> minor = take_number(rest);
  if (!minor) return std::nullopt;
  return std::pair{*major, *minor};
}

bool GlCapabilities::has_extension(std::string_view name) const {
  std::string full = name.starts_with("GL_") ? std::string(name) : "GL_" + std::string(name);
  return std::binary_search(extensions.begin(), extensions.end(), full);
}

bool GlCapabilities::is_software() const {
  for (std::string_view marker : {"llvmpipe", "softpipe", "swrast", "SwiftShader"})
    if (renderer.find(marker) != std::string::npos) return true;
  return false;
}

std::vector<std::string> GlCapabilities::describe() const {
  std::vector<std::string> lines;
  lines.push_back("GL renderer: " + renderer + " (" + vendor + (is_software() ? ", software" : "") + ")");
  lines.push_back("GL version: " + version + "; " + shading_language_version);
  std::string anisotropy = yes_no(texture_filter_anisotropic);
  if (texture_filter_anisotropic) anisotropy += " (" + std::to_string(static_cast<int>(max_anisotropy)) + "x)";
  lines.push_back("GL extensions used: EXT_color_buffer_float " + yes_no(color_buffer_float) +
                  ", EXT_color_buffer_half_float " + yes_no(color_buffer_half_float) + ", OES_texture_float_linear " +
                  yes_no(texture_float_linear) + ", EXT_disjoint_timer_query " + yes_no(disjoint_timer_query) +
                  ", EXT_texture_filter_anisotropic " + anisotropy + ", EXT_depth_clamp " + yes_no(depth_clamp) +
                  ", EXT_clip_control " + yes_no(clip_control) + ", KHR_debug " + yes_no(debug_output));
  lines.push_back("GL limits: texture " + std::to_string(max_texture_size) + ", renderbuffer " +
                  std::to_string(max_renderbuffer_size) + ", viewport " + std::to_string(max_viewport_width) + "x" +
                  std::to_string(max_viewport_height) + ", array layers " + std::to_string(max_array_texture_layers) +
                  ", draw buffers " + std::to_string(max_draw_buffers) + ", samples " + std::to_string(max_samples) +
                  ", texture units " + std::to_string(max_texture_image_units) + " (vertex " +
                  std::to_string(max_vertex_texture_image_units) + ")");
  return lines;
}

GlCapabilities query_gl_capabilities() {
  GlCapabilities caps;
  caps.vendor = gl_string(GL_VENDOR);
  caps.renderer = gl_string(GL_RENDERER);
  caps.version = gl_string(GL_VERSION);
  caps.shading_language_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
  if (const auto version = parse_gles_version(caps.version))
    std::tie(caps.major_version, caps.minor_version) = *version;

  const int count = gl_integer(GL_NUM_EXTENSIONS);
  caps.extensions.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    const GLubyte* name = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
    if (name) caps.extensions.emplace_back(reinterpret_cast<const char*>(name));
  }
  std::sort(caps.extensions.begin(), caps.extensions.end());

  caps.color_buffer_float = caps.has_extension("EXT_color_buffer_float");
  caps.color_buffer_half_float = caps.color_buffer_float || caps.has_extension("EXT_color_buffer_half_float");
  caps.texture_float_linear = caps.has_extension("OES_texture_float_linear");
  caps.disjoint_timer_query = caps.has_extension("EXT_disjoint_timer_query");
  caps.texture_filter_anisotropic = caps.has_extension("EXT_texture_filter_anisotropic");
  caps.depth_clamp = caps.has_extension("EXT_depth_clamp");
  caps.clip_control = caps.has_extension("EXT_clip_control");
  caps.debug_output = caps.has_extension("KHR_debug") || caps.major_version > 3 ||
                      (caps.major_version == 3 && caps.minor_version >= 2);  // core in ES 3.2

  if (caps.texture_filter_anisotropic) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &caps.max_anisotropy);
  caps.max_texture_size = gl_integer(GL_MAX_TEXTURE_SIZE);
  caps.max_renderbuffer_size = gl_integer(GL_MAX_RENDERBUFFER_SIZE);
  caps.max_array_texture_layers = gl_integer(GL_MAX_ARRAY_TEXTURE_LAYERS);
  caps.max_draw_buffers = gl_integer(GL_MAX_DRAW_BUFFERS);
  caps.max_color_attachments = gl_integer(GL_MAX_COLOR_ATTACHMENTS);
  caps.max_samples = gl_integer(GL_MAX_SAMPLES);
  caps.max_texture_image_units = gl_integer(GL_MAX_TEXTURE_IMAGE_UNITS);
  caps.max_vertex_texture_image_units = gl_integer(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS);
  GLint viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  caps.max_viewport_width = viewport[0];
  caps.max_viewport_height = viewport[1];
  // A query the driver did not know must not leave an error flag for the first pass to trip on.
  for (int i = 0; i < 8 && glGetError() != GL_NO_ERROR; ++i) {
  }
  return caps;
}

}  // namespace trailray::render
