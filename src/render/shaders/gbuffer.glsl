// The G-buffer's encodings (gbuffer.hpp), shared by the pass that fills it and those that read it.
// Distance from the camera (metres; 0 = no terrain, the sky) is an R32F texel where
// EXT_color_buffer_float allows it, else packed into the RGB bytes of an RGBA8 texel as 24-bit
// fixed point (1/16 m steps, up to 1048 km): u_packed_distance says which, per frame.
// Normals are view-space unit vectors stored as n * 0.5 + 0.5 (RGB10_A2).

const float kDistanceStepsPerMetre = 16.0;
const float kMaxDistanceSteps = 16777215.0;  // 2^24 - 1

vec4 pack_distance(float distance_m) {
  float steps = clamp(floor(distance_m * kDistanceStepsPerMetre + 0.5), 1.0, kMaxDistanceSteps);
  float high = floor(steps / 65536.0);
  steps -= high * 65536.0;
  float middle = floor(steps / 256.0);
  float low = steps - middle * 256.0;
  return vec4(low, middle, high, 255.0) / 255.0;
}

float unpack_distance(vec4 texel) {
  vec3 bytes = floor(texel.rgb * 255.0 + 0.5);
  return dot(bytes, vec3(1.0, 256.0, 65536.0)) / kDistanceStepsPerMetre;
}

float read_distance(sampler2D distances, ivec2 pixel, bool is_packed) {
  vec4 texel = texelFetch(distances, pixel, 0);
  return is_packed ? unpack_distance(texel) : texel.r;
}

vec4 encode_normal(vec3 n) { return vec4(n * 0.5 + 0.5, 1.0); }
vec3 decode_normal(vec4 texel) { return normalize(texel.xyz * 2.0 - 1.0); }

// The view-space direction through a point of the viewport (uv 0..1, origin bottom left);
// tan_half_fov: the tangents of the horizontal and vertical half angles.
vec3 view_ray(vec2 uv, vec2 tan_half_fov) { return normalize(vec3((uv * 2.0 - 1.0) * tan_half_fov, -1.0)); }
