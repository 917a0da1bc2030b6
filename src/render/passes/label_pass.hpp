#pragma once
// The labels pass (after the overlays, before the output): the names the layout placed
// (scene/text/label_layout.hpp) drawn over the composed frame as textured quads in screen space.
//
// Each label is rasterized once on the CPU (scene/text/label_raster.hpp: the text's coverage and a
// dark halo, at the picture's pixel size) into an atlas texture kept between frames, so a viewer
// uploads only names it has not drawn before; one draw call takes them all. The vertex shader
// reads the G-buffer's distances around each label's anchor: a label whose point the terrain
// hides is drawn ghosted (LabelStyle::ghost_alpha) or not at all (hide_occluded).
//
// Photos' thumbnails (a label whose `image` is set) are drawn the same way from a second atlas of
// RGBA texels (each thumbnail framed and resampled on the CPU to the size the layout gave it),
// so they fade, ghost and hide exactly as names do, in one more draw call.

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
#include "scene/text/label_layout.hpp"
#include "scene/style.hpp"

namespace trailray::render {

struct LabelVertex;  // one corner of a label's quad (label_pass.cpp)

class LabelPass {
 public:
  // Compiles the shaders (the GL context must be current). Throws ShaderError.
  LabelPass();

  // Draws `labels` over the bound framebuffer (the composed frame, the G-buffer's size), blended;
  // `gbuffer`'s distances decide which anchors are hidden. Throws RenderError from GL.
  void draw(const GBuffer& gbuffer, std::span<const scene::PlacedLabel> labels, const scene::LabelStyle& style);

  // The layout's font and measurements, kept with the pass's atlas between frames.
  scene::LabelLayouter& layouter() { return layouter_; }

  // Labels rasterized into the atlases so far (a label drawn again is not rasterized again), and
  // times an atlas was full and started over.
  std::size_t rasterized() const { return rasterized_; }
  std::size_t atlas_resets() const { return resets_; }

 private:
  struct Slot {
    int x = 0, y = 0, width = 0, height = 0;
  };
  // Texels packed in shelves (rows of slots from the top, each as tall as its tallest) in a CPU
  // copy; the rows that changed go to the GPU once per frame: one upload instead of one per
  // label, which a software driver makes expensive.
  struct Atlas {
    int size = 0, texel_bytes = 0;
    GLenum internal_format = 0, format = 0;
    Texture texture;
    std::vector<std::uint8_t> pixels;
    std::pair<int, int> changed_rows{1 << 30, 0};  // rows [first, second) not uploaded yet
    int shelf_y = 0, shelf_height = 0, shelf_x = 0;
    std::unordered_map<std::string, Slot> slots;

    // Copies `texels` (w x h, rows top-down) into a free slot; nullptr when it cannot fit.
    const Slot* insert(const std::string& key, int w, int h, const std::uint8_t* texels);
    void upload_changes();
    void reset();
  };
  // Every label's quad into `quads`, rasterizing what the atlas lacks; an atlas that fills up
  // starts over once with this frame's labels.
  std::vector<LabelVertex> quads_of(Atlas& atlas, const std::vector<const scene::PlacedLabel*>& labels, bool photos);
  void draw_quads(ShaderProgram& program, Atlas& atlas, const std::vector<LabelVertex>& quads, const GBuffer& gbuffer,
                  const scene::LabelStyle& style);

  ShaderProgram program_, photo_program_;
  VertexArray vertex_array_;
  Buffer vertices_;
  Atlas text_atlas_;   // RG8: text and halo coverage
  Atlas photo_atlas_;  // RGBA8: framed thumbnails
  scene::LabelLayouter layouter_;
  std::size_t rasterized_ = 0, resets_ = 0;
};

}  // namespace trailray::render
