#pragma once
// Arrays as 2D textures the shaders index linearly (track_common.glsl fetch_texel: texel i at
// (i % width, i / width)): the track buffer's points, blocks and level-of-detail lists, and the
// track pass's per-frame piece and style tables. At most kMaxWidth wide: a texture wider than
// 2048 is not guaranteed by WebGL2.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "render/gl/gl_objects.hpp"

namespace trailray::render::texel_table {

inline constexpr int kMaxWidth = 2048;

inline int rows_for(std::size_t texels, int width) { return static_cast<int>((texels + width - 1) / width); }

// The narrowest width (at most kMaxWidth) that holds `texels` in as few rows as the widest would:
// the last row is then nearly full (2049 texels take 2 rows of 1025, not of 2048).
inline int width_for(std::size_t texels) {
  const auto max_width = static_cast<std::size_t>(kMaxWidth);
  const std::size_t rows = std::max<std::size_t>(1, (texels + max_width - 1) / max_width);
  return static_cast<int>(std::max<std::size_t>(1, (texels + rows - 1) / rows));
}

// `texels` (`channels` values each) as a texture `width` wide, the last row padded with zeros
// (at least one texel: a sampler must always have a texture).
template <typename T>
Texture upload(std::vector<T>& texels, int channels, int width, GLenum internal_format, GLenum format, GLenum type) {
  const std::size_t count = texels.size() / static_cast<std::size_t>(channels);
  const int rows = std::max(1, rows_for(count, width));
  texels.resize(static_cast<std::size_t>(width) * rows * channels, T{0});
  Texture texture = make_texture_2d(internal_format, width, rows);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, rows, format, type, texels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

}  // namespace trailray::render::texel_table
