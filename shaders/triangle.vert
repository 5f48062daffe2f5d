// Filled triangles in pixel coordinates (arrow heads, markers), colour per vertex.
layout(location = LOC_POSITION) in vec2 position;
layout(location = LOC_COLOR) in vec4 color;

uniform vec2 u_viewport;

out vec4 v_color;

void main() {
  v_color = color;
  gl_Position = vec4(2.0 * position.x / u_viewport.x - 1.0, 1.0 - 2.0 * position.y / u_viewport.y, 0.0, 1.0);
}
