#version 330 core
// Flat-shaded polygons: every vertex carries its face's normal and colour, so the face's
// lighting (Lambert from one directional light plus ambient, from both sides: leg skins are
// single polygons) is computed here once per vertex and passed on flat. The fragment shader
// then interpolates only the ground position, which is what a software rasterizer pays for
// per pixel (a frame is mostly ground).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 view_projection;
uniform vec3 light_direction;  // towards the light, unit length
uniform float ambient;         // 1 for unlit meshes (shadow, decals, overlay)
uniform float point_size;      // for the particle overlay
flat out vec3 v_colour;
out vec2 v_ground;
void main() {
  float diffuse = abs(dot(normalize(normal), light_direction));
  v_colour = colour * (ambient + (1.0 - ambient) * diffuse);
  v_ground = position.xy;
  gl_Position = view_projection * vec4(position, 1.0);
  gl_PointSize = point_size;
}
