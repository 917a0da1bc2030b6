#pragma once
// Screen-space ambient occlusion (shaders/ssao.frag, ssao_blur.frag): how much of the sky each
// terrain pixel's surroundings hide, from the G-buffer's distances and normals, then a
// depth-aware 4x4 blur. 1 = open, 0 = buried; the sky is 1. The compose pass multiplies the sky
// light by it.
//
// By default at half the G-buffer's resolution each way (a quarter of the samples: SSAO was a
// third of a frame on llvmpipe), brought back by a depth-aware upsample (ssao_upsample.frag).
// The occlusion varies over the hemisphere's radius, 8% of the distance, i.e. tens of pixels:
// half resolution keeps it; only at depth edges does the upsample have to choose sides.

#include <glm/glm.hpp>

#include <vector>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/gbuffer.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::render {

inline constexpr int kSsaoSamples = 16;  // shaders/ssao.frag's kSamples

// `count` points in the unit hemisphere around +z, spread by a golden-angle spiral, each at least
// 10 degrees above the plane, with lengths growing from 0.1 to 1 (denser near the centre, where
// the occluders that matter most are).
std::vector<glm::vec3> hemisphere_kernel(int count);

struct SsaoSettings {
  // The hemisphere's radius as a fraction of the pixel's distance: the scale of the hollows that
  // darken is the same at every distance (a few percent: valleys, not pebbles).
  float radius_fraction = 0.08f;
  // Occlusion counted this many times over (1 - intensity * buried fraction, at least 0): a few
  // samples within a bounded radius see only the nearest part of what hides the sky, and a
  // valley should read as clearly as in shaded relief.
  float intensity = 1.5f;
  // G-buffer pixels per occlusion pixel, each way: 2 (half resolution, upsampled) or 1 (full,
  // the reference).
  int resolution_divisor = 2;
};

class SsaoPass {
 public:
  // Compiles the shaders (the GL context must be current). Throws ShaderError.
  SsaoPass();

  // The blurred occlusion of the G-buffer's pixels (an R8 texture of its size, owned by the pass
  // and valid until the next run). Leaves the framebuffer binding to the caller. Throws
  // RenderError, and std::invalid_argument for a divisor other than 1 or 2.
  const Texture& run(const GBuffer& gbuffer, const scene::Camera& camera, const SsaoSettings& settings = {});

 private:
  // An R8 texture and its framebuffer.
  struct Target {
    int width = 0, height = 0;
    Texture texture;
    Framebuffer framebuffer;
  };
  static void resize(Target& target, int width, int height, const char* what);

  ShaderProgram occlusion_, blur_, upsample_;
  VertexArray fullscreen_;
  std::vector<glm::vec3> kernel_;
  Target raw_, blurred_, upsampled_;
};

}  // namespace trailray::render
