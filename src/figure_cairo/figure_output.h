// A figure as a file's bytes: PNG (through the project's Image and PNG writer), SVG or PDF,
// each a cairo surface that draw_figure() draws on. Nothing here writes files: the caller
// commits the bytes through output/output_file.h, so a failure leaves no half-written file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "figure_cairo/figure_layout.h"
#include "figures/figure.h"
#include "output/image.h"
#include "theme/theme.h"

namespace cb {

enum class FigureFormat { Png, Svg, Pdf };
const char* figure_format_name(FigureFormat format);  // "png", also the file's extension
// "png,svg,pdf" (any subset, any order, no repeats) -> the formats in the order given; nullopt
// for an unknown or repeated name or an empty list.
std::optional<std::vector<FigureFormat>> parse_figure_formats(const std::string& text);

// The figure drawn into an RGBA image, width x height pixels.
Image figure_image(const Figure& figure, const Theme& theme, int width = kFigureWidth,
                   int height = kFigureHeight);

// The figure as an SVG document (width x height px) or a PDF file (the same layout on a page
// of kPdfScale x that size in points, the font embedded). Throws std::runtime_error when cairo
// fails.
inline constexpr double kPdfScale = 0.5;  // 1200 x 800 -> 600 x 400 pt, 8.3 x 5.6 in
std::string figure_vector(const Figure& figure, const Theme& theme, FigureFormat format,
                          int width = kFigureWidth, int height = kFigureHeight);

}  // namespace cb
