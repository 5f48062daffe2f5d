#include "exact/drive_terms.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace cb::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Slope of piece i of a table: piece 0 is before the first point, piece m after the last
// (both flat, as drive_value extends the table), piece i between points i-1 and i.
double table_piece_slope(const std::vector<std::pair<double, double>>& table, std::size_t i) {
  if (i == 0 || i >= table.size()) return 0.0;
  return (table[i].second - table[i - 1].second) / (table[i].first - table[i - 1].first);
}

void add_table(const DriveDesc& d, double start, std::vector<Kink>& kinks) {
  const auto& table = d.table;
  const double local = start - d.t0;  // table time at tau = start
  const std::size_t first = static_cast<std::size_t>(
      std::upper_bound(table.begin(), table.end(), local,
                       [](double v, const auto& p) { return v < p.first; }) -
      table.begin());
  kinks.push_back({start, drive_value(d, start), table_piece_slope(table, first)});
  for (std::size_t i = first; i < table.size(); ++i) {
    const double change = table_piece_slope(table, i + 1) - table_piece_slope(table, i);
    if (change != 0.0) kinks.push_back({d.t0 + table[i].first, 0.0, change});
  }
}

// First s >= 0 with amplitude sin(nu s + phase) >= c > 0.
double sine_first_at_least(const SineTerm& s, double c) {
  double amp = s.amplitude, phase = s.phase;
  if (amp < 0.0) {
    amp = -amp;
    phase += std::numbers::pi;
  }
  if (amp < c || s.nu <= 0.0) return kInf;
  const double two_pi = 2.0 * std::numbers::pi;
  const double alpha = std::asin(c / amp);  // sin >= c / amp on [alpha, pi - alpha] mod 2 pi
  const double theta = phase - two_pi * std::floor(phase / two_pi);
  if (theta >= alpha && theta <= std::numbers::pi - alpha) return s.start;
  const double target = theta < alpha ? alpha : two_pi + alpha;
  return s.start + (target - theta) / s.nu;
}

}  // namespace

DriveTerms decompose_drive(const DriveDesc& d) {
  DriveTerms terms;
  const double start = std::max(d.t0, 0.0);
  switch (d.type) {
    case DriveType::Step:
      terms.kinks.push_back({start, d.amplitude, 0.0});
      break;
    case DriveType::Ramp:
      terms.kinks.push_back({start, d.beta * (start - d.t0), d.beta});
      break;
    case DriveType::Table:
      add_table(d, start, terms.kinks);
      break;
    case DriveType::Sine: {
      const double nu = 2.0 * std::numbers::pi / d.period;
      terms.has_sine = true;
      terms.sine = {start, d.amplitude, nu, nu * (start - d.t0)};
      break;
    }
    case DriveType::Impulses:
      for (std::size_t i = 0; i < d.times.size(); ++i) {
        const double tau = d.t0 + d.times[i];
        const double s = i < d.strengths.size() ? d.strengths[i] : 1.0;
        if (tau >= 0.0) terms.kicks.push_back({tau, s});
      }
      std::sort(terms.kicks.begin(), terms.kicks.end(),
                [](const Kick& a, const Kick& b) { return a.tau < b.tau; });
      break;
    case DriveType::Expr:
      terms.is_expr = true;
      terms.expr = make_forcing(d);
      terms.expr_start = start;
      break;
  }
  return terms;
}

double DriveTerms::value(double tau) const {
  assert(!is_expr);
  double f = 0.0;
  for (const Kink& k : kinks)
    if (k.tau <= tau) f += k.jump + k.slope * (tau - k.tau);
  if (has_sine && tau >= sine.start)
    f += sine.amplitude * std::sin(sine.nu * (tau - sine.start) + sine.phase);
  return f;
}

double DriveTerms::slope(double tau) const {
  assert(!is_expr);
  double s = 0.0;
  for (const Kink& k : kinks)
    if (k.tau <= tau) s += k.slope;
  if (has_sine && tau >= sine.start)
    s += sine.amplitude * sine.nu * std::cos(sine.nu * (tau - sine.start) + sine.phase);
  return s;
}

double DriveTerms::curvature_bound() const {
  return has_sine ? std::abs(sine.amplitude) * sine.nu * sine.nu : 0.0;
}

std::vector<double> DriveTerms::breakpoints() const {
  std::vector<double> out;
  for (const Kink& k : kinks) out.push_back(k.tau);
  for (const Kick& k : kicks) out.push_back(k.tau);
  if (has_sine) out.push_back(sine.start);
  if (is_expr) out.push_back(expr_start);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double DriveTerms::first_time_at_least(double c) const {
  assert(!is_expr && c > 0.0);
  if (has_sine) return sine_first_at_least(sine, c);
  // Piecewise linear: on [kinks[i].tau, kinks[i+1].tau) f = value + slope (tau - start).
  double value_now = 0.0, slope_now = 0.0;
  for (std::size_t i = 0; i < kinks.size(); ++i) {
    if (i > 0) value_now += slope_now * (kinks[i].tau - kinks[i - 1].tau);
    value_now += kinks[i].jump;
    slope_now += kinks[i].slope;
    if (value_now >= c) return kinks[i].tau;
    if (slope_now > 0.0) {
      const double t = kinks[i].tau + (c - value_now) / slope_now;
      if (i + 1 == kinks.size() || t < kinks[i + 1].tau) return t;
    }
  }
  return kInf;
}

}  // namespace cb::detail
