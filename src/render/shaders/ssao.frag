#version 300 es
// Screen-space ambient occlusion: for each terrain pixel, points of a hemisphere around its normal
// (view space, rebuilt from the G-buffer's distance and normal) are projected back into the
// image; a point that lies behind the terrain seen at its pixel is buried, i.e. occluded. The
// radius grows with distance (a fraction of it), so valleys darken at every scale of the view.
// The kernel turns by one of 16 angles in a 4x4 pattern, which ssao_blur.frag averages away.
// It may run at a fraction of the G-buffer's resolution (u_step 2: half each way): each of its
// pixels then stands for the G-buffer pixel at u_step times its coordinates.
precision highp float;

#include "gbuffer.glsl"

const int kSamples = 16;

uniform sampler2D u_normal;
uniform sampler2D u_distance;
uniform bool u_packed_distance;
uniform mat4 u_projection;
uniform vec2 u_tan_half_fov;
uniform vec3 u_kernel[kSamples];  // unit hemisphere (z up), ssao_pass.hpp
uniform float u_radius_fraction;  // radius / distance
uniform float u_intensity;        // ssao_pass.hpp
uniform int u_step;               // G-buffer pixels per occlusion pixel, each way (1 or 2)

in vec2 v_uv;
out vec4 frag_ao;

const float kRotations[16] =
    float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

void main() {
  ivec2 size = textureSize(u_distance, 0);
  ivec2 pixel = ivec2(gl_FragCoord.xy);  // in the occlusion's resolution: the rotation pattern
  ivec2 source = pixel * u_step;         // the G-buffer pixel it stands for
  float distance_m = read_distance(u_distance, source, u_packed_distance);
  if (distance_m <= 0.0) {
    frag_ao = vec4(1.0);
    return;
  }
  vec3 position = view_ray((vec2(source) + 0.5) / vec2(size), u_tan_half_fov) * distance_m;
  vec3 normal = decode_normal(texelFetch(u_normal, source, 0));
  float radius = u_radius_fraction * distance_m;

  float angle = (kRotations[(pixel.x & 3) + 4 * (pixel.y & 3)] + 0.5) * (6.2831853 / 16.0);
  vec3 helper = abs(normal.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t0 = normalize(cross(helper, normal));
  vec3 b0 = cross(normal, t0);
  vec3 tangent = cos(angle) * t0 + sin(angle) * b0;
  vec3 bitangent = cross(normal, tangent);

  float occlusion = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    vec3 k = u_kernel[i];
    vec3 s = position + (tangent * k.x + bitangent * k.y + normal * k.z) * radius;
    vec4 clip = u_projection * vec4(s, 1.0);
    if (clip.w <= 0.0) continue;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
    float scene_m = read_distance(u_distance, ivec2(uv * vec2(size)), u_packed_distance);
    if (scene_m <= 0.0) continue;  // the sky occludes nothing
    // Terrain far in front of the sample (another ridge) does not shade this one.
    float in_range = smoothstep(0.0, 1.0, radius / max(abs(distance_m - scene_m), 1e-3));
    occlusion += (scene_m < length(s) - 0.02 * radius ? 1.0 : 0.0) * in_range;
  }
  frag_ao = vec4(vec3(clamp(1.0 - u_intensity * occlusion / float(kSamples), 0.0, 1.0)), 1.0);
}
