// Where an axis gets its ticks: round numbers (1, 2 or 5 times a power of ten) or, on a log
// axis, 1, 2 and 5 times each power of ten. Plain data, shared by the overlay's plots and the
// figures' cairo backend, so both pick the same ticks for the same range.
#pragma once

#include <string>
#include <vector>

#include "figures/figure.h"

namespace cb {

struct Ticks {
  std::vector<double> values;  // in the mapping's units: log10(value) on a log axis
  double step = 1.0;
  std::vector<std::string> labels;  // one per value; empty: the values, formatted
};

// Ticks at 1, 2 or 5 times a power of ten, at most about `count` of them in [lo, hi].
Ticks nice_ticks(double lo, double hi, int count);

// The ticks of a figure's axis, labels always filled: the axis' own ticks when it lists them,
// else round numbers (about `count` of them) or a log axis' 1-2-5 steps. Negative labels get
// a true minus sign (U+2212), as typeset mathematics has it.
Ticks axis_ticks(const Axis& axis, int count);

// A data value in the mapping's units: log10(value) on a log axis.
double axis_value(const Axis& axis, double value);

}  // namespace cb
