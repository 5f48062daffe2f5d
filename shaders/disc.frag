// A lit sphere's silhouette: Lambert shading from the upper left, a soft highlight, and a
// one-pixel antialiased rim.
in vec4 v_color;
in vec2 v_offset;
flat in float v_radius;

layout(location = 0) out vec4 frag_color;

void main() {
  float d = length(v_offset);
  float coverage = clamp(v_radius - d + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  vec2 n2 = v_offset / max(v_radius, 1e-3);
  float nz = sqrt(max(0.0, 1.0 - dot(n2, n2)));
  vec3 normal = vec3(n2.x, -n2.y, nz);
  vec3 light = normalize(vec3(-0.45, 0.55, 0.7));
  float lambert = max(dot(normal, light), 0.0);
  float highlight = pow(max(dot(reflect(-light, normal), vec3(0.0, 0.0, 1.0)), 0.0), 24.0);
  vec3 rgb = v_color.rgb * (0.45 + 0.6 * lambert) + vec3(0.35 * highlight);
  frag_color = vec4(min(rgb, vec3(1.0)), v_color.a * coverage);
}
