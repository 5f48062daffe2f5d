// Fig. 4 and Fig. 5 of the paper: a chain of N = 30 pulled by the ramp f = beta tau, beta = 1.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "exact/continuum.h"
#include "exact/first_break.h"
#include "figures/break_maps.h"
#include "figures/figure_specs.h"
#include "figures/trajectories.h"

namespace cb {

namespace {

constexpr int kN = 30;
const std::vector<int> kSprings = {1, kN / 2, kN};
constexpr FigureColour kColours[3] = {FigureColour::Series0, FigureColour::Series1,
                                      FigureColour::Series2};

Panel time_panel(std::string title, double tau_end, std::string y_label) {
  Panel p;
  p.title = std::move(title);
  p.x = axis("\u03C4", 0.0, tau_end);
  p.y = axis(std::move(y_label), 0.0, 1.0);
  return p;
}

// Lines of `lines` (name suffix `line_name`) and points of `points` for each of `springs`.
void add_phi(Panel& p, const std::vector<int>& springs, const Trajectory& lines,
             const std::string& line_name, const Trajectory* points, const char* letter) {
  for (std::size_t i = 0; i < springs.size(); ++i)
    p.series.push_back(make_series(phi_name(springs[i], letter) + " " + line_name,
                                   SeriesStyle::Line, kColours[i % 3], lines.tau, lines.phi[i]));
  if (points)
    for (std::size_t i = 0; i < springs.size(); ++i)
      p.series.push_back(make_series(phi_name(springs[i], letter) + " RK4", SeriesStyle::Points,
                                     kColours[i % 3], points->tau, points->phi[i]));
}

}  // namespace

Figure figure_4a(const FigureOptions& o) {
  Figure f{"fig4a",
           "Fig. 4(a): \u03C6\u2081, \u03C6\u2081\u2085, \u03C6\u2083\u2080 for f = \u03C4, N = "
           "30, \u03B3 = 0: RK4 (points) vs "
           "Eqs. (phi1), (phij), (phiN) (lines)",
           {}};
  Panel p = time_panel(
      "Fig. 4(a)  f = \u03B2\u03C4, \u03B2 = 1, N = 30, \u03B3 = 0: RK4 "
      "(points), Eqs. (phi1), (phij), (phiN) (lines)",
      150.0, "\u03C6\u2C7C");
  Trajectory lines;
  lines.tau = linspace(0.0, 150.0, 601);
  lines.phi.resize(3);
  for (double t : lines.tau) {
    lines.phi[0].push_back(continuum_phi1(kN, 1.0, t));
    lines.phi[1].push_back(continuum_phij(kN, 1.0, kN / 2, t));
    lines.phi[2].push_back(continuum_phiN(1.0, t));
  }
  const Trajectory rk4 = rk4_trajectory(kN, 0.0, unit_ramp(), kSprings, 150.0, 1.5, o.dt);
  add_phi(p, kSprings, lines, "continuum", &rk4, "\u03C6");
  fit_y(p);
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_4b(const FigureOptions& o) {
  Figure f{"fig4b",
           "Fig. 4(b): energy per particle, Eq. (energy), RK4, f = \u03C4, N = 30, \u03B3 = 0",
           {}};
  Panel p = time_panel(
      "Fig. 4(b)  energy per particle, Eq. (energy), RK4, \u03B2 = 1, N = 30, "
      "\u03B3 = 0",
      150.0, "\u03B5");
  const Trajectory rk4 = rk4_trajectory(kN, 0.0, unit_ramp(), {}, 150.0, 0.25, o.dt);
  std::vector<double> total;
  for (std::size_t i = 0; i < rk4.tau.size(); ++i)
    total.push_back(rk4.kinetic[i] + rk4.potential[i]);
  p.series.push_back(make_series("total", SeriesStyle::Line, FigureColour::Ink, rk4.tau, total));
  p.series.push_back(
      make_series("kinetic", SeriesStyle::Line, FigureColour::Kinetic, rk4.tau, rk4.kinetic));
  p.series.push_back(
      make_series("potential", SeriesStyle::Line, FigureColour::Potential, rk4.tau, rk4.potential));
  fit_y(p);
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_4c(const FigureOptions&) {
  Figure f{"fig4c",
           "Fig. 4(c): \u03B6\u2C7C = \u03C6\u2C7C / \u03B2 (Eq. (rescale2)), exact, N = 30, "
           "\u03B3 = 0, and "
           "three thresholds \u03B6_c with the spring that breaks first",
           {}};
  Panel p = time_panel(
      "Fig. 4(c)  which part breaks: \u03B6\u2C7C = \u03C6\u2C7C/\u03B2 "
      "(exact) and three thresholds \u03B6_c",
      220.0, "\u03B6\u2C7C");
  const Trajectory exact =
      exact_trajectory(kN, 0.0, unit_ramp(), kSprings, linspace(0.0, 220.0, 881));
  add_phi(p, kSprings, exact, "exact", nullptr, "\u03B6");
  Series thresholds = make_series("thresholds", SeriesStyle::HLines, FigureColour::Accent, {}, {});
  for (double zeta : kFig4cThresholds) {
    const FirstBreak b = ramp_first_break(kN, 0.0, zeta);
    thresholds.x.push_back(b.tau);  // where the threshold is first reached
    thresholds.y.push_back(zeta);
    const char* why = b.spring == kN
                          ? (zeta > 4 * kN ? "anomalous: spring N again" : "fast pull: spring N")
                          : "slow pull: near the wall";
    p.notes.push_back({4.0, zeta + 7.0,
                       "\u03B6_c = " + fixed(zeta, 0) + ": spring " + std::to_string(b.spring) +
                           " breaks first at \u03C4 = " + fixed(b.tau, 1) + " (" + why + ")",
                       FigureColour::Accent});
  }
  p.series.push_back(std::move(thresholds));
  p.y.lo = -5.0;
  p.y.hi = 200.0;
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_4d(const FigureOptions& o) {
  Figure f{"fig4d",
           "Fig. 4(d): friction \u03B3 = 0.01, f = \u03C4, N = 30: RK4 (points) vs the exact "
           "solution (lines)",
           {}};
  Panel p = time_panel(
      "Fig. 4(d)  friction \u03B3 = 0.01, \u03B2 = 1, N = 30: RK4 (points), "
      "exact (lines)",
      300.0, "\u03C6\u2C7C");
  const std::vector<int> springs = {1, kN};
  const Trajectory exact =
      exact_trajectory(kN, 0.01, unit_ramp(), springs, linspace(0.0, 300.0, 1201));
  const Trajectory rk4 = rk4_trajectory(kN, 0.01, unit_ramp(), springs, 300.0, 3.0, o.dt);
  add_phi(p, springs, exact, "exact", &rk4, "\u03C6");
  fit_y(p);
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_5(const FigureOptions& o) {
  Figure f{
      "fig5",
      "Fig. 5: the exact solution Eq. (exactconv) (lines) vs RK4 (points), N = 30, \u03B3 = 0, "
      "f = \u03C4; inset: the small oscillation of \u03C6\u2081 on its plateau",
      {}};
  const std::vector<int> springs = {1, kN};
  Panel p = time_panel(
      "Fig. 5  Eq. (exactconv) (lines) vs RK4 (points), N = 30, \u03B3 = 0, "
      "f = \u03C4",
      150.0, "\u03C6\u2C7C");
  add_phi(p, springs, exact_trajectory(kN, 0.0, unit_ramp(), springs, linspace(0, 150, 1201)),
          "exact", nullptr, "\u03C6");
  const Trajectory rk4 = rk4_trajectory(kN, 0.0, unit_ramp(), springs, 150.0, 1.5, o.dt);
  for (std::size_t i = 0; i < springs.size(); ++i)
    p.series.push_back(make_series(phi_name(springs[i]) + " RK4", SeriesStyle::Points, kColours[i],
                                   rk4.tau, rk4.phi[i]));
  fit_y(p);
  p.legend = Panel::Legend::BottomRight;
  // The inset: the small oscillation of phi_1 about the plateau 4N of Eq. (phi1), where the
  // discrete chain departs from the continuum and RK4 still follows the exact solution.
  Panel inset = time_panel("inset: \u03C6\u2081 on its plateau", 150.0, "\u03C6\u2081");
  inset.x.lo = 96.0;
  inset.legend = Panel::Legend::BottomRight;
  inset.x.label = "";
  const std::vector<int> first = {1};
  const Trajectory small_exact =
      exact_trajectory(kN, 0.0, unit_ramp(), first, linspace(96, 150, 541));
  Trajectory small_rk4 = rk4_trajectory(kN, 0.0, unit_ramp(), first, 150.0, 0.75, o.dt);
  const auto from =
      std::find_if(small_rk4.tau.begin(), small_rk4.tau.end(), [](double t) { return t >= 96.0; }) -
      small_rk4.tau.begin();
  small_rk4.tau.erase(small_rk4.tau.begin(), small_rk4.tau.begin() + from);
  small_rk4.phi[0].erase(small_rk4.phi[0].begin(), small_rk4.phi[0].begin() + from);
  inset.series.push_back(make_series("\u03C6\u2081 exact (inset)", SeriesStyle::Line, kColours[0],
                                     small_exact.tau, small_exact.phi[0]));
  inset.series.push_back(make_series("\u03C6\u2081 RK4 (inset)", SeriesStyle::Points, kColours[0],
                                     small_rk4.tau, small_rk4.phi[0]));
  fit_y(inset);
  inset.inset = true;
  inset.left = 0.08f;
  inset.top = 0.10f;
  inset.width = 0.42f;
  inset.height = 0.42f;
  f.panels.push_back(std::move(p));
  f.panels.push_back(std::move(inset));
  return f;
}

}  // namespace cb
