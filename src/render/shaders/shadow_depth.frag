#version 300 es
// Depth only: the shadow map has no colour attachment, the rasterizer writes the depth.
precision mediump float;

void main() {}
