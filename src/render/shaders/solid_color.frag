#version 300 es
// Every pixel one colour: the simplest pass, for tests and for clearing one attachment.
precision highp float;

uniform vec4 u_color;

out vec4 frag_color;

void main() { frag_color = u_color; }
