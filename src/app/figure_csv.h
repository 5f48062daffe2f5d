// The numbers behind a figure as CSV, one row per plotted value:
//   panel,series,style,x,y,z
// panel: the panel's index (0, or 1 for an inset); series: its legend label (or the heatmap's
// label); style: line, points, band, xspans, vlines, hlines or heatmap; z: a band's upper edge,
// a span's right edge or a heatmap cell's value (x, y: the cell's centre); empty otherwise.
#pragma once

#include <string>

#include "figures/figure.h"

namespace cb {

std::string figure_csv(const Figure& figure);

}  // namespace cb
