// Thick line / rectangle in pixel coordinates (rects, segments, coils), a quad of four
// vertices that each carry the segment's data (renderer.cpp, QuadBatch).
// Interface names (LOC_*) are defined by the program from render/shader_interface.h.
layout(location = LOC_CORNER) in vec2 corner;  // x: 0..1 along the segment, y: -1..1 across
layout(location = LOC_ENDS) in vec4 ends;      // x0, y0, x1, y1 in pixels
layout(location = LOC_COLOR) in vec4 color;
layout(location = LOC_STYLE) in vec2 style;    // width in pixels, antialiasing margin (0 or 1)

uniform vec2 u_viewport;  // framebuffer size in pixels

out vec4 v_color;
out float v_across;  // signed distance from the centre line, pixels
flat out float v_half;
flat out float v_aa;

void main() {
  vec2 d = ends.zw - ends.xy;
  float len = length(d);
  vec2 dir = len > 0.0 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  float aa = style.y;
  float half_width = 0.5 * style.x + aa;  // grow across by the margin so the edge can fade
  // Along the segment it ends exactly at its end points (no fade there, so no overshoot).
  vec2 p = ends.xy + dir * (corner.x * len) + nrm * (corner.y * half_width);
  v_color = color;
  v_across = corner.y * half_width;
  v_half = 0.5 * style.x;
  v_aa = aa;
  gl_Position = vec4(2.0 * p.x / u_viewport.x - 1.0, 1.0 - 2.0 * p.y / u_viewport.y, 0.0, 1.0);
}
