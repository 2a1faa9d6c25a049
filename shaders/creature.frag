#version 330 core
// The lit face colour, and on the ground the checkerboard of unit cells that makes forward
// motion visible. The checkerboard is box-filtered over each pixel's footprint (the integral of
// the pattern over the pixel, from the screen-space derivatives of the ground position): its
// edges are anti-aliased, and where cells shrink towards the horizon it fades to its mean
// shade instead of aliasing into moire that flickers as the camera moves. Both are what the
// video encoder pays most for in a frame.
flat in vec3 v_colour;
in vec2 v_ground;
uniform int checker;  // 1 for the ground, its shadow and marks on it
out vec4 fragment;

// Fraction of the pixel's footprint (width `w` in cells, per axis) on light cells.
float LightCells(vec2 p, vec2 w) {
  // The integral of a square wave of period 2 is a triangle wave; its difference across the
  // footprint, divided by the width, is the box-filtered square wave.
  vec2 a = abs(fract((p - 0.5 * w) * 0.5) - 0.5);
  vec2 b = abs(fract((p + 0.5 * w) * 0.5) - 0.5);
  vec2 s = 2.0 * (a - b) / w;  // filtered square wave per axis, in [-1, 1]
  return 0.5 - 0.5 * s.x * s.y;
}

void main() {
  vec3 base = v_colour;
  if (checker == 1) {
    float light = LightCells(v_ground, fwidth(v_ground) + 1e-4);
    base *= mix(0.82, 1.0, light);
  }
  fragment = vec4(base, 1.0);
}
