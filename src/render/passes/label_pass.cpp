#include "render/passes/label_pass.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "render/gl/render_error.hpp"
#include "scene/text/label_raster.hpp"

namespace trailray::render {

// One corner of a label's quad.
struct LabelVertex {
  float position_px[2];
  float atlas_px[2];
  float anchor_px[2];
  float distance_m;
  float alpha;
  float color[3];
  float pin_reach_m;
};

namespace {

// RG8 texels: 8 MB, room for about a thousand labels at twice the default size.
constexpr int kAtlasSize = 2048;
// RGBA8 texels: 4 MB, room for about sixty thumbnails at twice the default size (the atlas
// starts over when a view shows more than it holds).
constexpr int kPhotoAtlasSize = 1024;
constexpr int kAtlasGap = 1;  // between slots: no texel of a neighbour is ever read

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

std::string key_of(const scene::PlacedLabel& label) {
  if (label.image != nullptr)  // a thumbnail, at the size and frame the layout gave it
    return 'p' + std::to_string(label.image->id) + '/' + std::to_string(label.box.width) + 'x' +
           std::to_string(label.box.height) + '/' + std::to_string(label.frame_px);
  std::string key = std::to_string(label.font_px) + '/' + std::to_string(label.halo_px);
  key += label.weight == scene::FontWeight::bold ? 'b' : 'r';
  key += label.text;
  return key;
}

void append_quad(std::vector<LabelVertex>& out, const scene::PlacedLabel& label, int atlas_x, int atlas_y) {
  const auto x0 = static_cast<float>(label.box.x), y0 = static_cast<float>(label.box.y);
  const auto w = static_cast<float>(label.box.width), h = static_cast<float>(label.box.height);
  const auto ax = static_cast<float>(atlas_x), ay = static_cast<float>(atlas_y);
  const auto corner = [&](float u, float v) {
    return LabelVertex{{x0 + u * w, y0 + v * h},
                       {ax + u * w, ay + v * h},
                       {static_cast<float>(label.anchor_px.x), static_cast<float>(label.anchor_px.y)},
                       static_cast<float>(label.anchor_distance_m),
                       label.alpha,
                       {label.color.r / 255.0f, label.color.g / 255.0f, label.color.b / 255.0f},
                       static_cast<float>(label.pin_reach_m)};
  };
  for (const auto& [u, v] : std::array<std::pair<float, float>, 6>{{{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}}})
    out.push_back(corner(u, v));
}

}  // namespace

LabelPass::LabelPass()
    : program_(ShaderProgram::from_embedded("label.vert", "label.frag")),
      photo_program_(ShaderProgram::from_embedded("label.vert", "label_photo.frag")),
      vertex_array_(VertexArray::create()),
      vertices_(Buffer::create()) {
  text_atlas_.size = kAtlasSize;
  text_atlas_.texel_bytes = 2;
  text_atlas_.internal_format = GL_RG8;
  text_atlas_.format = GL_RG;
  photo_atlas_.size = kPhotoAtlasSize;
  photo_atlas_.texel_bytes = 4;
  photo_atlas_.internal_format = GL_RGBA8;
  photo_atlas_.format = GL_RGBA;
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  const auto attribute = [](GLuint location, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(LabelVertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 2, offsetof(LabelVertex, position_px));
  attribute(1, 2, offsetof(LabelVertex, atlas_px));
  attribute(2, 2, offsetof(LabelVertex, anchor_px));
  attribute(3, 1, offsetof(LabelVertex, distance_m));
  attribute(4, 1, offsetof(LabelVertex, alpha));
  attribute(5, 3, offsetof(LabelVertex, color));
  attribute(6, 1, offsetof(LabelVertex, pin_reach_m));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  check_gl("setting up the labels pass");
}

void LabelPass::Atlas::reset() {
  slots.clear();
  std::fill(pixels.begin(), pixels.end(), std::uint8_t{0});
  shelf_x = shelf_y = shelf_height = 0;
}

const LabelPass::Slot* LabelPass::Atlas::insert(const std::string& key, int w, int h, const std::uint8_t* texels) {
  if (w <= 0 || h <= 0 || w > size || h > size) return nullptr;
  if (shelf_x + w > size) {  // the next shelf
    shelf_y += shelf_height + kAtlasGap;
    shelf_x = shelf_height = 0;
  }
  if (shelf_y + h > size) return nullptr;
  const Slot slot{shelf_x, shelf_y, w, h};
  shelf_x += w + kAtlasGap;
  shelf_height = std::max(shelf_height, h);
  if (pixels.empty()) pixels.assign(static_cast<std::size_t>(size) * size * texel_bytes, 0);
  const auto row_bytes = static_cast<std::ptrdiff_t>(w) * texel_bytes;
  for (int row = 0; row < h; ++row)
    std::copy_n(texels + row * row_bytes, row_bytes,
                pixels.begin() + (static_cast<std::ptrdiff_t>(slot.y + row) * size + slot.x) * texel_bytes);
  changed_rows = {std::min(changed_rows.first, slot.y), std::max(changed_rows.second, slot.y + h)};
  return &slots.emplace(key, slot).first->second;
}

void LabelPass::Atlas::upload_changes() {
  if (changed_rows.first >= changed_rows.second) return;
  if (!texture) texture = make_texture_2d(internal_format, size, size);
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const int first = changed_rows.first, count = changed_rows.second - changed_rows.first;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, first, size, count, format, GL_UNSIGNED_BYTE,
                  pixels.data() + static_cast<std::size_t>(first) * size * texel_bytes);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
  changed_rows = {1 << 30, 0};
}

std::vector<LabelVertex> LabelPass::quads_of(Atlas& atlas, const std::vector<const scene::PlacedLabel*>& labels,
                                             bool photos) {
  std::vector<LabelVertex> quads;
  quads.reserve(labels.size() * 6);
  for (int attempt = 0; attempt < 2; ++attempt) {
    quads.clear();
    bool full = false;
    for (const scene::PlacedLabel* label : labels) {
      const std::string key = key_of(*label);
      const auto found = atlas.slots.find(key);
      const Slot* slot = nullptr;
      if (found != atlas.slots.end()) {
        slot = &found->second;
      } else if (photos) {
        const scene::RgbaImage framed = scene::rasterize_photo_label(*label);
        slot = atlas.insert(key, static_cast<int>(framed.width), static_cast<int>(framed.height), framed.rgba.data());
        if (slot != nullptr) ++rasterized_;
      } else {
        const scene::LabelBitmap bitmap = scene::rasterize_label(layouter_.text(), *label);
        slot = atlas.insert(key, bitmap.width, bitmap.height, bitmap.text_and_halo.data());
        if (slot != nullptr) ++rasterized_;
      }
      if (slot == nullptr) {
        full = true;
        continue;
      }
      append_quad(quads, *label, slot->x, slot->y);
    }
    if (!full || attempt == 1) break;
    atlas.reset();
    ++resets_;
  }
  return quads;
}

void LabelPass::draw_quads(ShaderProgram& program, Atlas& atlas, const std::vector<LabelVertex>& quads,
                           const GBuffer& gbuffer, const scene::LabelStyle& style) {
  if (quads.empty()) return;
  atlas.upload_changes();
  program.use();
  program.set_vec2("u_viewport_px", static_cast<float>(gbuffer.width()), static_cast<float>(gbuffer.height()));
  program.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  program.set_float("u_hidden_alpha", style.hide_occluded ? 0.0f : std::clamp(style.ghost_alpha, 0.0f, 1.0f));
  program.set_int("u_distance", 0);
  program.set_int("u_atlas", 1);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gbuffer.distance().id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, atlas.texture.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quads.size() * sizeof(LabelVertex)), quads.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(quads.size()));
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void LabelPass::draw(const GBuffer& gbuffer, std::span<const scene::PlacedLabel> labels,
                     const scene::LabelStyle& style) {
  if (labels.empty()) return;
  std::vector<const scene::PlacedLabel*> texts, photos;
  for (const scene::PlacedLabel& label : labels) (label.image != nullptr ? photos : texts).push_back(&label);
  const std::vector<LabelVertex> text_quads = quads_of(text_atlas_, texts, false);
  const std::vector<LabelVertex> photo_quads = quads_of(photo_atlas_, photos, true);
  if (text_quads.empty() && photo_quads.empty()) return;

  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // The boxes never overlap (the layout), so the order of the two draws does not matter.
  draw_quads(photo_program_, photo_atlas_, photo_quads, gbuffer, style);
  draw_quads(program_, text_atlas_, text_quads, gbuffer, style);
  glDisable(GL_BLEND);
  check_gl("drawing the labels");
}

}  // namespace trailray::render
