// Internal: where inside a step a spring or the pull string reaches its threshold.
#pragma once

#include <functional>

namespace cb::detail {

// First theta in [0, h] at which the cubic Hermite interpolant of phi through
// (0, p0, m0) and (h, p1, m1) reaches the threshold (|phi| >= c, or phi >= c when
// stretch_only); a negative value when it does not. The interpolant's error is O(h^4), so
// the crossing time is too wherever phi crosses with a nonzero slope.
double hermite_first_crossing(double p0, double p1, double m0, double m1, double h, double c,
                              bool stretch_only);

// First t in [ta, tb] with f(t) >= c, by sampling and bisection; negative when none.
// f is evaluated at tb only through f_end (its left limit there).
double first_time_at_least(const std::function<double(double)>& f, double f_end, double ta,
                           double tb, double c);

}  // namespace cb::detail
