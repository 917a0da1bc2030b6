#version 300 es
// Blends a premultiplied overlay texture over the bound framebuffer (blend ONE,
// ONE_MINUS_SRC_ALPHA): the track overlay over the composed frame.
precision mediump float;

uniform sampler2D u_overlay;

in vec2 v_uv;
out vec4 frag_color;

void main() { frag_color = texelFetch(u_overlay, ivec2(gl_FragCoord.xy), 0); }
