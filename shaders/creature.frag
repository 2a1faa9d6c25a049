#version 330 core
// Lambert lighting from one directional light plus ambient, lit from both sides (leg skins
// are single polygons). The ground's checkerboard is computed here so forward motion shows.
in vec3 v_normal;
in vec3 v_colour;
in vec3 v_world;
uniform vec3 light_direction;  // towards the light, unit length
uniform float ambient;
uniform int checker;           // 1 for the ground
out vec4 fragment;
void main() {
  vec3 base = v_colour;
  if (checker == 1) {
    float cell = mod(floor(v_world.x) + floor(v_world.y), 2.0);
    base *= mix(0.82, 1.0, cell);
  }
  float diffuse = abs(dot(normalize(v_normal), light_direction));
  fragment = vec4(base * (ambient + (1.0 - ambient) * diffuse), 1.0);
}
