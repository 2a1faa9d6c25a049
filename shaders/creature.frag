#version 330 core
// The lit face colour, and on the ground the checkerboard of unit cells that makes forward
// motion visible.
flat in vec3 v_colour;
in vec2 v_ground;
uniform int checker;  // 1 for the ground, its shadow and marks on it
out vec4 fragment;
void main() {
  vec3 base = v_colour;
  if (checker == 1) {
    float cell = mod(floor(v_ground.x) + floor(v_ground.y), 2.0);
    base *= mix(0.82, 1.0, cell);
  }
  fragment = vec4(base, 1.0);
}
