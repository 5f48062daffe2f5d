#include "app/figure_csv.h"

#include "app/csv.h"

namespace cb {

namespace {

void quoted(std::string& out, const std::string& text) {
  out += '"';
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  out += '"';
}

void row(std::string& out, std::size_t panel, const std::string& name, const char* style, double x,
         double y, const double* z) {
  out += std::to_string(panel) + ",";
  quoted(out, name);
  out += std::string(",") + style + ",";
  append_number(out, x);
  out += ',';
  append_number(out, y);
  out += ',';
  if (z) append_number(out, *z);
  out += '\n';
}

}  // namespace

std::string figure_csv(const Figure& figure) {
  std::string out = "panel,series,style,x,y,z\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    const Heatmap& h = panel.heatmap;
    for (int r = 0; r < h.rows; ++r)
      for (int c = 0; c < h.columns; ++c) {
        const double value = h.values[static_cast<std::size_t>(r) * h.columns + c];
        row(out, p, h.label, "heatmap", h.x_at(c), h.y_at(r), &value);
      }
    for (const Series& s : panel.series) {
      const char* style = series_style_name(s.style);
      const std::size_t count = std::max(s.x.size(), s.y.size());
      for (std::size_t i = 0; i < count; ++i) {
        const double x = i < s.x.size() ? s.x[i] : 0.0, y = i < s.y.size() ? s.y[i] : 0.0;
        const double* z = i < s.x2.size() ? &s.x2[i] : i < s.y2.size() ? &s.y2[i] : nullptr;
        row(out, p, s.label.empty() ? panel.title : s.label, style, x, y, z);
      }
    }
  }
  return out;
}

}  // namespace cb
