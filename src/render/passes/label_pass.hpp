#pragma once
// The labels pass (after the overlays, before the output): the names the layout placed
// (scene/label_layout.hpp) drawn over the composed frame as textured quads in screen space.
//
// Each label is rasterized once on the CPU (scene/label_raster.hpp: the text's coverage and a
// dark halo, at the picture's pixel size) into an atlas texture kept between frames, so a viewer
// uploads only names it has not drawn before; one draw call takes them all. The vertex shader
// reads the G-buffer's distances around each label's anchor: a label whose point the terrain
// hides is drawn ghosted (LabelStyle::ghost_alpha) or not at all (hide_occluded).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/gbuffer.hpp"
#include "scene/label_layout.hpp"
#include "scene/style.hpp"

namespace trailray::render {

class LabelPass {
 public:
  // Compiles the shaders (the GL context must be current). Throws ShaderError.
  LabelPass();

  // Draws `labels` over the bound framebuffer (the composed frame, the G-buffer's size), blended;
  // `gbuffer`'s distances decide which anchors are hidden. Throws RenderError from GL.
  void draw(const GBuffer& gbuffer, std::span<const scene::PlacedLabel> labels, const scene::LabelStyle& style);

  // The layout's font and measurements, kept with the pass's atlas between frames.
  scene::LabelLayouter& layouter() { return layouter_; }

  // Labels rasterized into the atlas so far (a label drawn again is not rasterized again), and
  // times the atlas was full and started over.
  std::size_t rasterized() const { return rasterized_; }
  std::size_t atlas_resets() const { return resets_; }

 private:
  struct Slot {
    int x = 0, y = 0, width = 0, height = 0;
  };
  // Rasterizes a label into the atlas's CPU copy; nullptr when it cannot fit even into an empty atlas.
  const Slot* insert(const std::string& key, const scene::PlacedLabel& label);
  void upload_changes();
  void reset_atlas();

  ShaderProgram program_;
  VertexArray vertex_array_;
  Buffer vertices_;
  Texture atlas_;                                 // RG8: text and halo coverage
  std::vector<std::uint8_t> pixels_;              // its CPU copy
  std::pair<int, int> changed_rows_{1 << 30, 0};  // rows [first, second) not uploaded yet
  // Shelf packing: rows of labels from the top, each as tall as its tallest label.
  int shelf_y_ = 0, shelf_height_ = 0, shelf_x_ = 0;
  std::unordered_map<std::string, Slot> slots_;
  scene::LabelLayouter layouter_;
  std::size_t rasterized_ = 0, resets_ = 0;
};

}  // namespace trailray::render
