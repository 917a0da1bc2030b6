// Linear light <-> sRGB transfer function (IEC 61966-2-1), the same curve as
// linear_to_srgb8 in render/framebuffer_readback.hpp. Passes work in linear light; the compose
// pass encodes once, at the end, into an 8-bit target.

vec3 linear_to_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  vec3 low = c * 12.92;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(high, low, vec3(lessThanEqual(c, vec3(0.0031308))));
}

vec3 srgb_to_linear(vec3 srgb) {
  vec3 c = clamp(srgb, 0.0, 1.0);
  vec3 low = c / 12.92;
  vec3 high = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(high, low, vec3(lessThanEqual(c, vec3(0.04045))));
}
