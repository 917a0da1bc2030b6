// Aerial perspective and sky (atmosphere.hpp): single scattering in an atmosphere of air
// (Rayleigh, scale height ~8 km, scatters blue most) and haze (Mie, ~1.2 km, grey, forward
// peaked around the sun). The optical depth along a straight ray from the camera's height is
// integrated in closed form for each exponential layer; the flat-Earth layers are enough at the
// scale of a mountain view. The light scattered into the ray is the sun's, weighted by each
// component's phase function, plus a little of the sky's own; it fills what the air takes away.

uniform vec3 u_rayleigh_per_m;          // scattering at sea level, per channel
uniform float u_rayleigh_scale_height;  // metres
uniform float u_mie_per_m;
uniform float u_mie_scale_height;
uniform float u_mie_g;            // Henyey-Greenstein asymmetry
uniform float u_inscatter_scale;  // brightness of the scattered light relative to the sun's
uniform float u_camera_height;    // metres above the ellipsoid

// The integral of exp(-(h0 + t * rise) / H) over t in [0, length].
float layer_path(float h0, float rise, float length_m, float scale_height) {
  float density = exp(-h0 / scale_height);
  if (abs(rise) < 1e-5) return density * length_m;
  return density * scale_height / rise * (1.0 - exp(-length_m * rise / scale_height));
}

float rayleigh_phase(float mu) { return 0.75 * (1.0 + mu * mu); }  // averages to 1
float mie_phase(float mu) {
  float g = u_mie_g;
  return (1.0 - g * g) / pow(1.0 + g * g - 2.0 * g * mu, 1.5);  // averages to 1
}

// rise: the view ray's up component; mu: cosine of the angle between the ray and the sun.
// transmittance: what reaches the camera of the light behind; returns the light scattered in.
vec3 inscattering(float rise, float length_m, float mu, vec3 sun_radiance, vec3 sky_radiance, out vec3 transmittance) {
  vec3 tau_rayleigh = u_rayleigh_per_m * layer_path(u_camera_height, rise, length_m, u_rayleigh_scale_height);
  vec3 tau_mie = vec3(u_mie_per_m * layer_path(u_camera_height, rise, length_m, u_mie_scale_height));
  vec3 tau = tau_rayleigh + tau_mie;
  transmittance = exp(-tau);
  vec3 phase = (tau_rayleigh * rayleigh_phase(mu) + tau_mie * mie_phase(mu)) / max(tau, vec3(1e-9));
  return u_inscatter_scale * (sun_radiance * phase + sky_radiance) * (1.0 - transmittance);
}
