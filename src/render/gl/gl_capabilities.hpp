#pragma once
// What the current OpenGL ES context offers, queried once after it is created (DESIGN.md: query
// capabilities once at start and keep one code path per capability, not #ifs). Passes read
// these flags to choose a path, e.g. float G-buffer targets only with EXT_color_buffer_float,
// GPU timings only with EXT_disjoint_timer_query.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace trailray::render {

struct GlCapabilities {
  std::string vendor, renderer, version, shading_language_version;  // glGetString, verbatim
  int major_version = 0, minor_version = 0;                         // of OpenGL ES
  std::vector<std::string> extensions;                              // sorted, "GL_EXT_..."

  // The extensions the renderer uses (each decides a code path).
  bool color_buffer_float = false;          // EXT_color_buffer_float: render into R16F..RGBA32F
  bool color_buffer_half_float = false;     // EXT_color_buffer_half_float: render into 16-bit floats only
  bool texture_float_linear = false;        // OES_texture_float_linear: filter 32-bit float textures
  bool disjoint_timer_query = false;        // EXT_disjoint_timer_query: GPU time per pass
  bool texture_filter_anisotropic = false;  // EXT_texture_filter_anisotropic: sharp oblique imagery
  bool depth_clamp = false;                 // EXT_depth_clamp: shadow casters behind the near plane
  bool clip_control = false;                // EXT_clip_control: reversed-Z with [0, 1] depth
  bool debug_output = false;                // KHR_debug: driver messages and object labels

  float max_anisotropy = 1.0f;  // 1 without EXT_texture_filter_anisotropic
  int max_texture_size = 0, max_renderbuffer_size = 0, max_array_texture_layers = 0;
  int max_draw_buffers = 0, max_color_attachments = 0, max_samples = 0;
  int max_texture_image_units = 0, max_vertex_texture_image_units = 0;
  int max_viewport_width = 0, max_viewport_height = 0;

  // `name` with or without the "GL_" prefix.
  bool has_extension(std::string_view name) const;
  // A CPU rasterizer (Mesa llvmpipe/softpipe/swrast, SwiftShader): slow, but exact and everywhere.
  bool is_software() const;
  // The lines `--verbose` logs: renderer, version, the extensions used (present or not), limits.
  std::vector<std::string> describe() const;
};

// Queries the context current on this thread. Needs one (GL answers nothing without).
GlCapabilities query_gl_capabilities();

// The OpenGL ES version in a GL_VERSION string ("OpenGL ES 3.2 Mesa 22.3.6" -> {3, 2}); nullopt
// when it is not an ES version string (a desktop "4.6.0 NVIDIA ..." or garbage).
std::optional<std::pair<int, int>> parse_gles_version(std::string_view gl_version);

}  // namespace trailray::render
