// Fig. 3 of the paper: the continuum Green's function and what it does (N = 30).
#include <cmath>
#include <functional>
#include <numbers>

#include "exact/continuum.h"
#include "figures/figure_specs.h"
#include "figures/trajectories.h"

namespace cb {

namespace {

constexpr int kN = 30;

// A field over xi in [0, N] (across) and tau in [0, tau_end] (up), as the paper's (xi, tau)
// plane, sampled at cell centres.
Heatmap field(double tau_end, int rows, double scale, std::string label,
              const std::function<double(double, double)>& value) {
  Heatmap h;
  h.columns = 4 * kN;
  h.rows = rows;
  h.x_hi = kN;
  h.y_hi = tau_end;
  h.scale = scale;
  h.label = std::move(label);
  for (int r = 0; r < h.rows; ++r)
    for (int c = 0; c < h.columns; ++c)
      h.values.push_back(static_cast<float>(value(h.x_at(c), h.y_at(r))));
  return h;
}

Panel field_panel(std::string title, Heatmap h) {
  Panel p;
  p.title = std::move(title);
  p.x = axis("\u03BE  (the wall at 0, the pulled end at N = 30)", 0.0, static_cast<double>(kN));
  p.y = axis("\u03C4", h.y_lo, h.y_hi);
  p.heatmap = std::move(h);
  return p;
}

// The gamma = 0 propagator dG/dxi = H_N(tau + xi) + H_N(tau - xi), the closed form of H_N
// (Sec. II), inside the physical region tau > 0, 0 < xi < N.
double propagator(double xi, double tau) {
  return tau > 0.0 ? continuum_H(kN, tau + xi) + continuum_H(kN, tau - xi) : 0.0;
}

}  // namespace

Figure figure_3a(const FigureOptions&) {
  Figure f{
      "fig3a",
      "Fig. 3(a): \u03C8(\u03BE, \u03C4) of Eq. (conv) for f = u(\u03C4), N = 30, \u03B3 = 0.01",
      {}};
  f.panels.push_back(field_panel(
      "Fig. 3(a)  \u03C8(\u03BE, \u03C4) of Eq. (conv), f = u(\u03C4), N = 30, \u03B3 = 0.01",
      field(480.0, 240, 2.0 * kN, "\u03C8",
            [](double xi, double tau) { return continuum_psi_step(kN, 0.01, xi, tau); })));
  f.panels[0].notes.push_back(
      {1.0, 440.0, "\u03C8 \u2192 \u03BE, the particular solution", FigureColour::Ink});
  return f;
}

Figure figure_3b(const FigureOptions&) {
  Figure f{"fig3b", "Fig. 3(b): the propagator dG/d\u03BE of Eq. (conv2), \u03B3 = 0, N = 30", {}};
  f.panels.push_back(field_panel("Fig. 3(b)  the propagator dG/d\u03BE, \u03B3 = 0, N = 30",
                                 field(8.0 * kN, 480, 1.0, "dG/d\u03BE", propagator)));
  return f;
}

Figure figure_3c(const FigureOptions& o) {
  Figure f{"fig3c",
           "Fig. 3(c): \u03C6\u2C7C under f = sin(2\u03C0\u03C4 / 4N), N = 30, \u03B3 = 0: RK4 "
           "(points) vs "
           "Eq. (sum) (lines)",
           {}};
  DriveDesc sine;
  sine.type = DriveType::Sine;
  sine.amplitude = 1.0;
  sine.period = 4.0 * kN;
  const std::vector<int> springs = {1, kN / 2, kN};
  const Trajectory rk4 = rk4_trajectory(kN, 0.0, sine, springs, 480.0, 4.0, o.dt);
  Panel p;
  p.title =
      "Fig. 3(c)  resonance: f = sin(2\u03C0\u03C4/\u03C4\u2080), \u03C4\u2080 = 4N, N = 30, "
      "\u03B3 = 0";
  p.x = axis("\u03C4", 0.0, 480.0);
  p.y = axis("\u03C6\u2C7C", -1.0, 1.0);
  const FigureColour colours[3] = {FigureColour::Series0, FigureColour::Series1,
                                   FigureColour::Series2};
  const auto f_of = [](double t) { return std::sin(2.0 * std::numbers::pi * t / (4.0 * kN)); };
  const std::vector<double> fine = linspace(0.0, 480.0, 1921);
  for (std::size_t i = 0; i < springs.size(); ++i) {
    std::vector<double> line;
    for (double t : fine) line.push_back(continuum_phi_sum(kN, springs[i], t, f_of));
    p.series.push_back(make_series(phi_name(springs[i]) + " Eq. (sum)", SeriesStyle::Line,
                                   colours[i], fine, std::move(line)));
  }
  for (std::size_t i = 0; i < springs.size(); ++i)
    p.series.push_back(make_series(phi_name(springs[i]) + " RK4", SeriesStyle::Points, colours[i],
                                   rk4.tau, rk4.phi[i]));
  fit_y(p);
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_3d(const FigureOptions&) {
  Figure f{"fig3d",
           "Fig. 3(d): \u03C6(\u03BE, \u03C4) for f = \u03B4(\u03C4) + \u03B4(\u03C4 \u2212 N), "
           "\u03B3 = 0",
           {}};
  f.panels.push_back(
      field_panel("Fig. 3(d)  \u03C6(\u03BE, \u03C4) for f = \u03B4(\u03C4) + \u03B4(\u03C4 \u2212 "
                  "N), \u03B3 = 0",
                  field(8.0 * kN, 480, 1.0, "\u03C6", [](double xi, double tau) {
                    // Eq. (conv2) with two impulses: the propagator and its copy delayed by N.
                    return propagator(xi, tau) + propagator(xi, tau - kN);
                  })));
  return f;
}

}  // namespace cb
