#pragma once
// The light of the day and the air it crosses (compose pass, shaders/atmosphere.glsl): the sun's
// radiance after its path through the air (it reddens as it sinks), the sky's light on the
// ground, and the scattering parameters the compose shader integrates along each view ray.
// Linear light, in units where a white surface facing a high sun reflects about 1.

#include <glm/glm.hpp>

namespace trailray::render {

struct AtmosphereModel {
  // Air: Rayleigh scattering at sea level (per metre, red/green/blue at 680/550/440 nm) and its
  // scale height.
  glm::vec3 rayleigh_per_m{5.8e-6f, 13.5e-6f, 33.1e-6f};
  float rayleigh_scale_height_m = 8000.0f;
  // Haze: Mie scattering at sea level (grey) and its scale height; a clear Alpine day.
  float mie_per_m = 1.2e-5f;
  float mie_scale_height_m = 1200.0f;
  float mie_asymmetry = 0.76f;  // Henyey-Greenstein g: most light forward, a glow around the sun
  // The scattered light's brightness relative to the sun's radiance (single scattering leaves out
  // the light scattered more than once; this puts the sky's brightness where it is seen).
  float inscatter_scale = 0.55f;
};

// The sun's radiance at the ground for a sun `elevation_deg` above the horizon: the colour of a
// high sun, reddened and dimmed by the air mass of its path (Kasten-Young) relative to the zenith;
// 0 below the horizon (fading over its disc's width).
glm::vec3 sun_radiance(double elevation_deg, const AtmosphereModel& model = {});

// The sky's light on a surface facing the zenith: bluish, dimming as the sun sinks.
glm::vec3 sky_radiance(double elevation_deg);

// The sun's elevation in degrees at a place (the ellipsoid normal `up`) for a unit direction
// towards the sun.
double elevation_deg(const glm::dvec3& sun_direction, const glm::dvec3& up);

}  // namespace trailray::render
