// A picture's cells (snapshot.h, Picture): the texel under the pixel, sharp (nearest), drawn
// by glyph.vert's rectangle with the texture's whole range as its uv.
in vec4 v_color;
in vec2 v_uv;

uniform sampler2D u_picture;

layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = v_color * texture(u_picture, v_uv);
}
