#include "render/passes/label_pass.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "render/gl/render_error.hpp"
#include "scene/label_raster.hpp"

namespace trailray::render {
namespace {

// RG8 texels: 8 MB, room for about a thousand labels at twice the default size.
constexpr int kAtlasSize = 2048;
constexpr int kAtlasGap = 1;  // between slots: no texel of a neighbour is ever read

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

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

std::string key_of(const scene::PlacedLabel& label) {
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
      vertex_array_(VertexArray::create()),
      vertices_(Buffer::create()) {
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

void LabelPass::reset_atlas() {
  slots_.clear();
  std::fill(pixels_.begin(), pixels_.end(), std::uint8_t{0});
  shelf_x_ = shelf_y_ = shelf_height_ = 0;
}

const LabelPass::Slot* LabelPass::insert(const std::string& key, const scene::PlacedLabel& label) {
  const scene::LabelBitmap bitmap = scene::rasterize_label(layouter_.text(), label);
  const int w = bitmap.width, h = bitmap.height;
  if (w <= 0 || h <= 0 || w > kAtlasSize || h > kAtlasSize) return nullptr;
  if (shelf_x_ + w > kAtlasSize) {  // the next shelf
    shelf_y_ += shelf_height_ + kAtlasGap;
    shelf_x_ = shelf_height_ = 0;
  }
  if (shelf_y_ + h > kAtlasSize) return nullptr;
  const Slot slot{shelf_x_, shelf_y_, w, h};
  shelf_x_ += w + kAtlasGap;
  shelf_height_ = std::max(shelf_height_, h);
  // Into the CPU copy; the rows that changed go to the GPU once per frame (upload_changes): one
  // upload instead of one per label, which a software driver makes expensive.
  if (pixels_.empty()) pixels_.assign(static_cast<std::size_t>(kAtlasSize) * kAtlasSize * 2, 0);
  for (int row = 0; row < h; ++row)
    std::copy_n(bitmap.text_and_halo.begin() + static_cast<std::ptrdiff_t>(row) * w * 2, w * 2,
                pixels_.begin() + (static_cast<std::ptrdiff_t>(slot.y + row) * kAtlasSize + slot.x) * 2);
  changed_rows_ = {std::min(changed_rows_.first, slot.y), std::max(changed_rows_.second, slot.y + h)};
  ++rasterized_;
  return &slots_.emplace(key, slot).first->second;
}

void LabelPass::upload_changes() {
  if (changed_rows_.first >= changed_rows_.second) return;
  if (!atlas_) atlas_ = make_texture_2d(GL_RG8, kAtlasSize, kAtlasSize);
  glBindTexture(GL_TEXTURE_2D, atlas_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const int first = changed_rows_.first, count = changed_rows_.second - changed_rows_.first;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, first, kAtlasSize, count, GL_RG, GL_UNSIGNED_BYTE,
                  pixels_.data() + static_cast<std::size_t>(first) * kAtlasSize * 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
  changed_rows_ = {1 << 30, 0};
}

void LabelPass::draw(const GBuffer& gbuffer, std::span<const scene::PlacedLabel> labels,
                     const scene::LabelStyle& style) {
  if (labels.empty()) return;
  // Every label's slot first; an atlas that fills up starts over once with this frame's labels.
  std::vector<LabelVertex> quads;
  quads.reserve(labels.size() * 6);
  for (int attempt = 0; attempt < 2; ++attempt) {
    quads.clear();
    bool full = false;
    for (const scene::PlacedLabel& label : labels) {
      const std::string key = key_of(label);
      const auto found = slots_.find(key);
      const Slot* slot = found != slots_.end() ? &found->second : insert(key, label);
      if (slot == nullptr) {
        full = true;
        continue;
      }
      append_quad(quads, label, slot->x, slot->y);
    }
    if (!full || attempt == 1) break;
    reset_atlas();
    ++resets_;
  }
  if (quads.empty()) return;
  upload_changes();

  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  program_.use();
  program_.set_vec2("u_viewport_px", static_cast<float>(gbuffer.width()), static_cast<float>(gbuffer.height()));
  program_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  program_.set_float("u_hidden_alpha", style.hide_occluded ? 0.0f : std::clamp(style.ghost_alpha, 0.0f, 1.0f));
  program_.set_int("u_distance", 0);
  program_.set_int("u_atlas", 1);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gbuffer.distance().id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, atlas_.id());
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
  glDisable(GL_BLEND);
  check_gl("drawing the labels");
}

}  // namespace trailray::render
