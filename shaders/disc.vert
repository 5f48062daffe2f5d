// A bead: a screen-aligned square around each centre, shaded as a disc in disc.frag.
layout(location = LOC_CORNER) in vec2 corner;  // -1..1 in both directions
layout(location = LOC_CENTER) in vec3 center;  // x, y, radius in pixels
layout(location = LOC_COLOR) in vec4 color;

uniform vec2 u_viewport;

out vec4 v_color;
out vec2 v_offset;  // from the centre, pixels
flat out float v_radius;

void main() {
  float extent = center.z + 1.0;  // one pixel more for the antialiased rim
  vec2 p = center.xy + corner * extent;
  v_color = color;
  v_offset = corner * extent;
  v_radius = center.z;
  gl_Position = vec4(2.0 * p.x / u_viewport.x - 1.0, 1.0 - 2.0 * p.y / u_viewport.y, 0.0, 1.0);
}
