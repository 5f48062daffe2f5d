#include "figure_cairo/figure_text.h"

#include "figure_cairo/figure_fonts.h"
#include "figure_cairo/svg_text.h"

namespace cb {

namespace {

// DejaVu Sans' capital height is 0.73 em: a line's visual middle lies 0.365 em above its
// baseline. A subscript is 0.7 em, its baseline 0.22 em lower.
constexpr double kHalfCap = 0.365, kSubScale = 0.7, kSubDrop = 0.22;

struct Run {
  std::string text;
  bool sub = false;
};

std::size_t code_point_length(unsigned char lead) {
  return lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : 4;
}

std::vector<Run> runs(const std::string& s) {
  std::vector<Run> out(1);
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == '_' && i + 1 < s.size()) {
      const std::size_t n = code_point_length(static_cast<unsigned char>(s[i + 1]));
      out.push_back({s.substr(i + 1, n), true});
      out.push_back({});
      i += 1 + n;
      continue;
    }
    out.back().text += s[i++];
  }
  return out;
}

void select(cairo_t* cr, const TextFont& font, bool sub) {
  cairo_set_font_face(cr, figure_font(font.face));
  cairo_set_font_size(cr, sub ? kSubScale * font.size : font.size);
}

double advance(cairo_t* cr, const TextFont& font, const Run& run) {
  if (run.text.empty()) return 0.0;
  select(cr, font, run.sub);
  cairo_text_extents_t e;
  cairo_text_extents(cr, run.text.c_str(), &e);
  return e.x_advance;
}

}  // namespace

double text_advance(cairo_t* cr, const TextFont& font, const std::string& text) {
  double w = 0;
  for (const Run& r : runs(text)) w += advance(cr, font, r);
  return w;
}

double draw_text(cairo_t* cr, const TextFont& font, double x, double y, const std::string& text,
                 double align) {
  const std::vector<Run> parts = runs(text);
  double width = 0;
  for (const Run& r : parts) width += advance(cr, font, r);
  double pen = x - align * width;
  const double baseline = y + kHalfCap * font.size;
  std::vector<SvgTextRun> placed;
  for (const Run& r : parts) {
    if (r.text.empty()) continue;
    placed.push_back({r.text, pen, baseline + (r.sub ? kSubDrop * font.size : 0.0),
                      r.sub ? kSubScale * font.size : font.size});
    pen += advance(cr, font, r);
  }
  if (SvgTextLayer* layer = SvgTextLayer::of(cr)) {
    layer->add(cr, font.face, placed);
    return width;
  }
  for (const SvgTextRun& r : placed) {
    select(cr, font, r.size < font.size);
    cairo_move_to(cr, r.x, r.y);
    cairo_show_text(cr, r.text.c_str());
  }
  cairo_new_path(cr);  // show_text leaves the pen as the current point: start clean
  return width;
}

std::vector<std::string> wrap_text(cairo_t* cr, const TextFont& font, const std::string& text,
                                   double width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_advance(cr, font, longer) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace cb
