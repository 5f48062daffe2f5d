#include "figures/axis_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cb {

namespace {

// As many decimals as the step needs (0.25 -> 2).
int decimals_for(double step) {
  return std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
}

std::string fixed(double value, int decimals, const char* suffix = "") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f%s", decimals, value, suffix);
  return buffer;
}

// A true minus sign, no "-0".
std::string with_minus_sign(const std::string& s) {
  if (s.find_first_not_of("-0.") == std::string::npos) return s[0] == '-' ? s.substr(1) : s;
  return s[0] == '-' ? "\u2212" + s.substr(1) : s;
}

std::string tick_label(double value, double step) {
  return with_minus_sign(fixed(value, decimals_for(step)));
}

}  // namespace

TickFormat tick_format(const Ticks& t) {
  TickFormat f;
  double largest = 0;
  for (double v : t.values) largest = std::max(largest, std::abs(v));
  if (largest > 0 && (largest < 1e-2 || largest >= 1e4))
    f.exponent = static_cast<int>(std::floor(std::log10(largest)));
  f.decimals = decimals_for(t.step / std::pow(10.0, f.exponent));
  return f;
}

std::string tick_label(double value, const TickFormat& f) {
  return with_minus_sign(fixed(value / std::pow(10.0, f.exponent), f.decimals));
}

std::string power_of_ten_text(int exponent) {
  static const char* const kSuperscript[10] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                               "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string text = "\u00D710";
  for (char c : std::to_string(exponent)) text += c == '-' ? "\u207B" : kSuperscript[c - '0'];
  return text;
}

std::string x_tick_label(double value, const Ticks& t) {
  if (std::abs(value) < 1e4 && t.step >= 1.0) return fixed(value, 0);
  if (std::abs(value) < 1e4) return tick_label(value, tick_format(t));
  const bool mega = std::abs(value) >= 1e6;
  const double unit = mega ? 1e6 : 1e3;
  return fixed(value / unit, decimals_for(t.step / unit), mega ? "M" : "k");
}

Ticks nice_ticks(double lo, double hi, int count) {
  Ticks t;
  const double raw = (hi - lo) / std::max(1, count);
  if (!(raw > 0) || !std::isfinite(raw)) return t;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  t.step = (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag;
  for (double v = std::ceil(lo / t.step) * t.step; v <= hi + 1e-9 * t.step; v += t.step)
    t.values.push_back(std::abs(v) < 1e-9 * t.step ? 0.0 : v);
  return t;
}

double axis_value(const Axis& axis, double value) {
  return axis.log ? std::log10(value) : value;
}

Ticks axis_ticks(const Axis& axis, int count) {
  Ticks t;
  if (!axis.ticks.empty()) {
    for (const AxisTick& tick : axis.ticks) {
      t.values.push_back(axis_value(axis, tick.value));
      t.labels.push_back(tick.label);
    }
    return t;
  }
  if (!axis.log) {
    t = nice_ticks(axis.lo, axis.hi, count);
    for (double v : t.values) t.labels.push_back(tick_label(v, t.step));
    return t;
  }
  for (int e = static_cast<int>(std::floor(std::log10(axis.lo))); std::pow(10.0, e) <= axis.hi; ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (v < axis.lo * (1 - 1e-12) || v > axis.hi * (1 + 1e-12)) continue;
      t.values.push_back(std::log10(v));
      t.labels.push_back(tick_label(v, std::min(1.0, std::pow(10.0, e))));
    }
  return t;
}

}  // namespace cb
