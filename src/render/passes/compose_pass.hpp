#pragma once
// The compose pass (shaders/compose.frag): lights the G-buffer with the sun and the sky, darkens
// the sky light by the ambient occlusion, shades the sun by the cascaded shadow maps, adds the atmosphere
// (aerial perspective over the terrain, the sky where there is none), and writes sRGB into the
// bound RGBA8 framebuffer.

#include <glm/glm.hpp>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/atmosphere.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/shadow_maps.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::render {

struct SceneLighting {
  glm::dvec3 sun_direction_ecef{0.0, 0.0, 1.0};  // unit, towards the sun
  glm::vec3 sun_radiance{1.0f, 0.97f, 0.92f};    // linear, for a surface facing the sun
  glm::vec3 sky_radiance{0.22f, 0.26f, 0.32f};   // linear, for a surface facing the zenith
};

// The lighting of a sun direction at the camera's place: radiances from its elevation there.
SceneLighting lighting_for(const glm::dvec3& sun_direction_ecef, const scene::Camera& camera,
                           const AtmosphereModel& model = {});

// The sky without the atmosphere (8-bit sRGB, flat).
inline constexpr glm::vec3 kSkyColorSrgb{0.64f, 0.77f, 0.91f};

struct ComposeSettings {
  bool atmosphere = true;  // false: no haze, and the flat kSkyColorSrgb sky
  AtmosphereModel model;
};

// The sun's shadows for the compose pass: the rendered maps and the cascades they were rendered
// for (both outlive the draw).
struct ComposeShadows {
  const ShadowMaps* maps = nullptr;
  const ShadowCascades* cascades = nullptr;
};

class ComposePass {
 public:
  // Compiles the shader (the GL context must be current). Throws ShaderError.
  ComposePass();

  // Draws every pixel of the bound framebuffer (its viewport the G-buffer's size) from the
  // G-buffer; `ambient_occlusion` nullptr: none; `shadows` nullptr: the sun reaches everything.
  // Throws RenderError.
  void draw(const GBuffer& gbuffer, const Texture* ambient_occlusion, const ComposeShadows* shadows,
            const scene::Camera& camera, const SceneLighting& lighting, const ComposeSettings& settings) const;

 private:
  ShaderProgram program_;
  VertexArray fullscreen_;
};

}  // namespace trailray::render
