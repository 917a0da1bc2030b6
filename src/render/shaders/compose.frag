#version 300 es
// Compose (DESIGN.md "The frame", step 5): lights the G-buffer (sun x Lambert x shadow (cascaded shadow maps) + sky
// light from the normal's up component x ambient occlusion), then the atmosphere: terrain fades
// into the light the air scatters by its distance, and where there is no terrain the sky is that
// light along an endless ray. Linear light throughout, sRGB-encoded once at the end.
precision highp float;

#include "atmosphere.glsl"
#include "gbuffer.glsl"
#include "shadows.glsl"
#include "srgb.glsl"

uniform sampler2D u_albedo;
uniform sampler2D u_normal;
uniform sampler2D u_distance;
uniform sampler2D u_ao;
uniform bool u_packed_distance;
uniform bool u_has_ao;
uniform bool u_atmosphere;
uniform bool u_has_shadows;
uniform mat3 u_view_to_ecef;  // view-space directions -> ECEF (the shadow matrices' frame)
uniform vec2 u_tan_half_fov;
uniform vec3 u_sun_view;  // unit, towards the sun, view space
uniform vec3 u_up_view;   // the ellipsoid normal under the camera, view space
uniform vec3 u_sun_radiance;
uniform vec3 u_sky_radiance;
uniform vec3 u_flat_sky;  // linear: the sky without the atmosphere

in vec2 v_uv;
out vec4 frag_color;

// The sky's rays end at the top of the atmosphere; this stands in for "far enough".
const float kSkyPathM = 1.0e6;
const float kSunCosRadius = 0.99999;  // ~0.26 degrees: the sun's disc
const float kTrackHaze = 0.3;         // the share of the aerial perspective a track gets

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 ray = view_ray((vec2(pixel) + 0.5) / vec2(textureSize(u_distance, 0)), u_tan_half_fov);
  float rise = dot(ray, u_up_view);
  float mu = dot(ray, u_sun_view);
  float distance_m = read_distance(u_distance, pixel, u_packed_distance);
  vec3 color;
  if (distance_m <= 0.0) {
    if (u_atmosphere) {
      vec3 transmittance;
      // Below the horizon with no terrain: seen as along the horizon.
      color = inscattering(max(rise, 0.0), kSkyPathM, mu, u_sun_radiance, u_sky_radiance, transmittance);
      if (mu > kSunCosRadius && rise > 0.0) color += u_sun_radiance * transmittance * 20.0;
    } else {
      color = u_flat_sky;
    }
  } else {
    vec4 albedo_texel = texelFetch(u_albedo, pixel, 0);
    vec3 albedo = albedo_texel.rgb;
    // Alpha 0 marks a track (track_visible.frag): data, not landscape, so the haze only tints it
    // a little and its colours stay readable against the legend at any distance.
    float haze = albedo_texel.a < 0.5 ? kTrackHaze : 1.0;
    vec3 normal = decode_normal(texelFetch(u_normal, pixel, 0));
    float ao = u_has_ao ? texelFetch(u_ao, pixel, 0).r : 1.0;
    float shadow = 1.0;
    if (u_has_shadows) {
      // The pixel's position relative to the camera from its distance along its view ray; the
      // lookup wants it, its normal and the sun in the cascades' camera-relative ECEF frame.
      vec3 position_view = ray * distance_m;
      shadow = shadow_visibility(u_view_to_ecef * position_view, -position_view.z, u_view_to_ecef * normal,
                                 u_view_to_ecef * u_sun_view);
    }
    float sun = max(dot(normal, u_sun_view), 0.0) * shadow;
    float sky = 0.5 + 0.5 * dot(normal, u_up_view);
    color = albedo * (u_sun_radiance * sun + u_sky_radiance * sky * ao);
    if (u_atmosphere) {
      vec3 transmittance;
      vec3 light = inscattering(rise, distance_m, mu, u_sun_radiance, u_sky_radiance, transmittance);
      color = mix(color, color * transmittance + light, haze);
    }
  }
  frag_color = vec4(linear_to_srgb(color), 1.0);
}
