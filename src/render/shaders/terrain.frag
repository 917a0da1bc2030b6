#version 300 es
// Terrain shading: albedo (imagery, else a hypsometric tint by height; the neutral ground where
// the source has no data) lit by the sun (Lambert) and the sky (an ambient term that fades on
// slopes facing away from the zenith, like a hillshade's). Works in linear light and writes
// sRGB: the image is final until the deferred passes (shadows, SSAO, atmosphere) take over.
precision highp float;

#include "srgb.glsl"

uniform vec3 u_sun_direction;  // unit, towards the sun, ECEF
uniform vec3 u_up;             // the ellipsoid normal at the tile, ECEF
uniform vec3 u_sun_radiance;   // linear
uniform vec3 u_sky_radiance;   // linear
uniform vec3 u_neutral_albedo;  // linear
uniform bool u_has_imagery;
uniform sampler2D u_imagery;  // sRGB texture: sampled as linear

in vec3 v_normal;
in float v_height;
in vec2 v_imagery_uv;
in float v_covered;

out vec4 frag_color;

// Colours of the tint (sRGB, as a map would print them) at increasing heights in metres: green
// lowlands, brown foothills, grey rock, white above about 3000 m.
const int kStops = 6;
const float kStopHeights[kStops] = float[](0.0, 700.0, 1500.0, 2200.0, 2700.0, 3200.0);
const vec3 kStopColors[kStops] = vec3[](vec3(0.47, 0.62, 0.38), vec3(0.58, 0.67, 0.42), vec3(0.68, 0.63, 0.45),
                                         vec3(0.62, 0.54, 0.45), vec3(0.60, 0.59, 0.57), vec3(0.95, 0.95, 0.97));

vec3 hypsometric_tint(float height_m) {
  vec3 color = kStopColors[0];
  for (int i = 1; i < kStops; ++i) {
    float t = clamp((height_m - kStopHeights[i - 1]) / (kStopHeights[i] - kStopHeights[i - 1]), 0.0, 1.0);
    color = mix(color, kStopColors[i], t);
  }
  return srgb_to_linear(color);
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 albedo = u_has_imagery ? texture(u_imagery, v_imagery_uv).rgb : hypsometric_tint(v_height);
  if (v_covered < 0.5) albedo = u_neutral_albedo;
  float sun = max(dot(n, u_sun_direction), 0.0);
  float sky = 0.5 + 0.5 * dot(n, u_up);
  vec3 radiance = albedo * (u_sun_radiance * sun + u_sky_radiance * sky);
  frag_color = vec4(linear_to_srgb(radiance), 1.0);
}
