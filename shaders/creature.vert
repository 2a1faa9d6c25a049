#version 330 core
// Flat-shaded polygons: every vertex carries its face's normal and colour.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 view_projection;
uniform float point_size;  // for the particle overlay
out vec3 v_normal;
out vec3 v_colour;
out vec3 v_world;
void main() {
  v_normal = normal;
  v_colour = colour;
  v_world = position;
  gl_Position = view_projection * vec4(position, 1.0);
  gl_PointSize = point_size;
}
