// Solid colour; with antialiasing, coverage falls off over one pixel at the long edges.
in vec4 v_color;
in float v_across;
flat in float v_half;
flat in float v_aa;

layout(location = 0) out vec4 frag_color;

void main() {
  float coverage = v_aa > 0.0 ? clamp(v_half + 0.5 - abs(v_across), 0.0, 1.0) : 1.0;
  frag_color = vec4(v_color.rgb, v_color.a * coverage);
}
