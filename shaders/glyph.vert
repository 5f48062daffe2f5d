// Glyphs: a pixel rectangle of the frame textured with its glyph's coverage from
// the atlas (render/glyph_atlas.h). Rectangles sit on whole pixels and are the glyph's size,
// so each texel lands on exactly one pixel: crisp, and the same wherever the text is.
layout(location = LOC_CORNER) in vec2 corner;  // 0..1 in x and y
layout(location = LOC_RECT) in vec4 rect;      // x, y (top-left), width, height in pixels
layout(location = LOC_UV) in vec4 uv;          // u0, v0, u1, v1 in the atlas (0..1)
layout(location = LOC_COLOR) in vec4 color;

uniform vec2 u_viewport;

out vec4 v_color;
out vec2 v_uv;

void main() {
  vec2 p = rect.xy + corner * rect.zw;
  v_color = color;
  v_uv = mix(uv.xy, uv.zw, corner);
  gl_Position = vec4(2.0 * p.x / u_viewport.x - 1.0, 1.0 - 2.0 * p.y / u_viewport.y, 0.0, 1.0);
}
