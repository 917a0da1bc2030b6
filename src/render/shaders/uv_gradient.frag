#version 300 es
// The interpolated viewport coordinate as colour (red = u, green = v): a test pattern that shows
// where every pixel's centre lies and which way is up.
precision highp float;

in vec2 v_uv;

out vec4 frag_color;

void main() { frag_color = vec4(v_uv, 0.0, 1.0); }
