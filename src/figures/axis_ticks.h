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

// How the plots of a video's overlay and of the page write a linear axis' tick labels: very
// small or large values (the largest under 1e-2 or from 1e4) share a power of ten, which the
// axis shows once (power_of_ten_text), with as many decimals as the step needs.
struct TickFormat {
  int exponent = 0;  // labels are value / 10^exponent
  int decimals = 0;
};
TickFormat tick_format(const Ticks& t);
// value / 10^exponent, a true minus sign (U+2212), no "-0".
std::string tick_label(double value, const TickFormat& f);
// "×10⁻³" for -3.
std::string power_of_ten_text(int exponent);
// A time or spring axis has no room for a shared power of ten: whole numbers below 1e4 as
// they are, larger values with an SI suffix (50k, 1.5M), smaller steps with their decimals.
std::string x_tick_label(double value, const Ticks& t);

}  // namespace cb
