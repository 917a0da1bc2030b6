#include "render/passes/atmosphere.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::render {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;
// The sun's colour high in the sky (slightly warm white), which the renderer has always used.
constexpr glm::dvec3 kHighSunRadiance{1.0, 0.97, 0.92};
constexpr glm::dvec3 kHighSkyRadiance{0.22, 0.26, 0.32};

// Relative air mass (1 at the zenith) for an apparent elevation (Kasten & Young 1989).
double air_mass(double elevation_deg) {
  const double e = std::max(elevation_deg, 0.0);
  return 1.0 / (std::sin(e / kDegPerRad) + 0.50572 * std::pow(e + 6.07995, -1.6364));
}

}  // namespace

glm::vec3 sun_radiance(double elevation_deg, const AtmosphereModel& model) {
  // Vertical optical depths from sea level; the extra air mass over the zenith's reddens.
  const glm::dvec3 tau = glm::dvec3(model.rayleigh_per_m) * static_cast<double>(model.rayleigh_scale_height_m) +
                         glm::dvec3(static_cast<double>(model.mie_per_m) * model.mie_scale_height_m);
  const double extra_air = air_mass(elevation_deg) - 1.0;
  const glm::dvec3 transmittance = glm::exp(-tau * extra_air);
  // The disc sets over about half a degree.
  const double above = std::clamp((elevation_deg + 0.27) / 0.54, 0.0, 1.0);
  return glm::vec3(kHighSunRadiance * transmittance * above);
}

glm::vec3 sky_radiance(double elevation_deg) {
  // Twilight keeps some light after sunset; full daylight from about 30 degrees up.
  const double t = std::clamp((elevation_deg + 6.0) / 36.0, 0.0, 1.0);
  const double brightness = 0.05 + 0.95 * t * t * (3.0 - 2.0 * t);
  return glm::vec3(kHighSkyRadiance * brightness);
}

double elevation_deg(const glm::dvec3& sun_direction, const glm::dvec3& up) {
  const double s = glm::dot(glm::normalize(sun_direction), glm::normalize(up));
  return std::asin(std::clamp(s, -1.0, 1.0)) * kDegPerRad;
}

}  // namespace trailray::render
