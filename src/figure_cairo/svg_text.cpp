#include "figure_cairo/svg_text.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cb {

namespace {

const cairo_user_data_key_t kLayerKey{};

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", std::abs(v) < 1e-9 ? 0.0 : v);  // cos(π/2)
  return buffer;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

void SvgTextLayer::attach(cairo_t* cr) {
  cairo_set_user_data(cr, &kLayerKey, this, nullptr);
}

SvgTextLayer* SvgTextLayer::of(cairo_t* cr) {
  return static_cast<SvgTextLayer*>(cairo_get_user_data(cr, &kLayerKey));
}

void SvgTextLayer::add(cairo_t* cr, FontFace face, const std::vector<SvgTextRun>& runs) {
  double r = 0, g = 0, b = 0, a = 1;
  cairo_pattern_get_rgba(cairo_get_source(cr), &r, &g, &b, &a);  // text has solid sources
  cairo_matrix_t m;
  cairo_get_matrix(cr, &m);
  const auto byte = [](double v) { return std::to_string(static_cast<int>(v * 255.0 + 0.5)); };
  const bool identity = m.xx == 1 && m.yx == 0 && m.xy == 0 && m.yy == 1 && m.x0 == 0 && m.y0 == 0;
  std::string e =
      "<text" +
      (identity ? std::string()
                : " transform=\"matrix(" + number(m.xx) + " " + number(m.yx) + " " + number(m.xy) +
                      " " + number(m.yy) + " " + number(m.x0) + " " + number(m.y0) + ")\"") +
      " font-family=\"" + font_family(face) + "\"" +
      (face == FontFace::Bold ? " font-weight=\"bold\"" : "") + " fill=\"rgb(" + byte(r) + "," +
      byte(g) + "," + byte(b) + ")\"" + (a < 1.0 ? " fill-opacity=\"" + number(a) + "\"" : "") +
      " xml:space=\"preserve\">";
  // Every run at the position draw_text computed from cairo's own advances: the SVG viewer's
  // spacing cannot drift from the PNG's.
  for (const SvgTextRun& run : runs)
    e += "<tspan x=\"" + number(run.x) + "\" y=\"" + number(run.y) + "\" font-size=\"" +
         number(run.size) + "\">" + escaped(run.text) + "</tspan>";
  elements_ += e + "</text>\n";
}

std::string SvgTextLayer::insert_into(const std::string& svg) const {
  const std::size_t end = svg.rfind("</svg>");
  if (end == std::string::npos) throw std::runtime_error("cairo wrote an SVG without </svg>");
  return svg.substr(0, end) + "<g id=\"text\">\n" + elements_ + "</g>\n" + svg.substr(end);
}

}  // namespace cb
