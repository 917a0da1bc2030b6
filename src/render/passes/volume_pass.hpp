#pragma once
// The volumes pass (after the overlays, before the labels): airspaces and task cylinders
// (scene/volumes/volumes.hpp) as translucent walls over the composed frame, with the outlines of their
// floors and ceilings as lines a few pixels wide. Blended (premultiplied, over the frame's sRGB
// values, as the labels are), never writing depth, and tested against the G-buffer's distances
// in the fragment shader: the terrain (and a track tube) in front of a wall hides it, so a wall
// disappears behind a ridge and into the ground. Walls are drawn from both sides, stronger at
// the floor than at the ceiling, an unlimited or capped top fading out, and the far ones fainter,
// so a country's airspaces do not drown the picture.
//
// Cost: one draw for all the walls and one for all the outlines; the fragments are bounded by
// how much of the picture the walls cover (a few layers over a whole view at most).

#include "render/gl/shader_program.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/volume_gpu.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::render {

struct VolumeStyle {
  float outline_px = 2.0f;  // the outlines' width in picture pixels (times the pixel ratio)
  // Walls farther than this fade, to `far_alpha` of their opacity at `fade_end_m`.
  float fade_start_m = 8000.0f;
  float fade_end_m = 60000.0f;
  float far_alpha = 0.25f;
};

class VolumePass {
 public:
  // Compiles the shaders (the GL context must be current). Throws ShaderError.
  VolumePass();

  // Draws the volumes over the bound framebuffer (the composed frame, the G-buffer's size).
  // Throws RenderError from GL.
  void draw(const GBuffer& gbuffer, const scene::Camera& camera, const VolumeDraw& volumes, double pixel_ratio,
            const VolumeStyle& style = {}) const;

 private:
  ShaderProgram walls_;
  ShaderProgram outlines_;
};

}  // namespace trailray::render
