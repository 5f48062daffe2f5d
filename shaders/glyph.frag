// The text's colour at the glyph's anti-aliased coverage (the atlas's one channel).
in vec4 v_color;
in vec2 v_uv;

uniform sampler2D u_atlas;

layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(v_color.rgb, v_color.a * texture(u_atlas, v_uv).r);
}
