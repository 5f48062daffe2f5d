// Two maps of chains under their weight (issue #22): Heald's ball on two strings in the
// (beta, G) plane, where the anomalous windows of the one-body map close one by one as the ball
// gets heavier; and which spring of a hanging 30-bead chain breaks first against beta.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "figures/break_maps.h"
#include "figures/figure_specs.h"

namespace cb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

DriveDesc ramp(double beta) {
  DriveDesc d;
  d.type = DriveType::Ramp;
  d.beta = beta;
  return d;
}

// Heald's ball: one bead hanging on the upper string (spring 1), pulled down through the lower
// one (the pull string), both breaking at T_c = 1: gamma_g = m g / T_c = G, X = beta.
ChainParams heald_ball(double gravity) {
  ChainParams c;
  c.beads = 1;
  c.threshold = 1.0;
  c.pull_string = true;
  c.gravity = gravity;
  return c;
}

// The search runs past tau = 1/beta, when the lower string breaks if nothing broke before.
double ball_t_end(double beta) {
  return 1.0 / beta + 10.0;
}

ChainParams hanging_chain(double gravity) {
  ChainParams c;
  c.beads = kMapBeads;
  c.threshold = 1.0;
  c.gravity = gravity;
  return c;
}

// A slow pull breaks the top spring once phi_eq,1 + beta tau ~ 1; the search runs well past.
double chain_t_end(double beta) {
  return 2.0 / beta + 8.0 * kMapBeads;
}

}  // namespace

Figure figure_gravity_map(const FigureOptions& o) {
  Figure f{"gravity_map",
           "Heald's ball on two strings: which string breaks first in the (\u03B2, G) plane, "
           "f = \u03B2\u03C4, T_c = 1 (\u03B3_g = G, X = \u03B2): exact regions, Heald's boundary "
           "G = \u03B2 sin(1/\u03B2), RK4 points",
           {}};
  Panel p;
  p.title = "Ball on two strings under its weight G = mg/(Kl): which string breaks first";
  p.x = axis("\u03B2   (left: slow pull, right: jerk)", kGravityBetaLo, kGravityBetaHi);
  p.y = axis("G = mg / (K l)   (weight over the strings' strength)", 0.0, kGravityGMax);
  // Exact regions: +0.6 where the upper string breaks first, -0.6 where the lower one does.
  Heatmap& h = p.heatmap;
  h.columns = std::max(40, o.map_exact / 6);
  h.rows = std::max(20, o.map_exact / 12);
  h.x_lo = kGravityBetaLo;
  h.x_hi = kGravityBetaHi;
  h.y_lo = 0.0;
  h.y_hi = kGravityGMax;
  h.scale = 1.0;
  h.label = "\u2212 lower, + upper";
  const auto cells = parallel_first_breaks(h.columns * h.rows, o.jobs, [&](int i) {
    if (stopped(o)) return FirstBreak{};
    const double beta = h.x_at(i % h.columns), g = h.y_at(i / h.columns);
    return exact_first_break(heald_ball(g), ramp(beta), ball_t_end(beta));
  });
  if (stopped(o)) return f;
  for (const FirstBreak& b : cells)
    h.values.push_back(!b.broke ? 0.0f : b.spring == 0 ? -0.6f : 0.6f);
  // Heald's boundary: the lower string first iff G < beta sin(1/beta) (where that is > 0).
  const std::vector<double> fine = linspace(kGravityBetaLo, kGravityBetaHi, 4000);
  std::vector<double> boundary;
  for (double beta : fine) {
    const double g = beta * std::sin(1.0 / beta);
    boundary.push_back(g > 0.0 ? g : kNaN);
  }
  p.series.push_back(make_series("Heald: G = \u03B2 sin(1/\u03B2)", SeriesStyle::Line,
                                 FigureColour::Ink, fine, std::move(boundary)));
  // RK4 on a coarse grid, each run to its first break: one series per outcome.
  const int nb = std::max(6, o.map_rk4 / 5), ng = std::max(4, o.map_rk4 / 10);
  const std::vector<double> betas = linspace(kGravityBetaLo + 0.01, kGravityBetaHi - 0.01, nb);
  const std::vector<double> gs = linspace(0.01, kGravityGMax - 0.01, ng);
  const auto runs = parallel_first_breaks(nb * ng, o.jobs, [&](int i) {
    const double beta = betas[static_cast<std::size_t>(i % nb)];
    const double g = gs[static_cast<std::size_t>(i / nb)];
    return simulated_first_break(heald_ball(g), ramp(beta), ball_t_end(beta), o.dt, o.stop);
  });
  if (stopped(o)) return f;
  // Each outcome's points in a colour that stands out on the region it should fall in.
  Series lower =
      make_series("RK4: lower string first", SeriesStyle::Points, FigureColour::Potential, {}, {});
  Series upper =
      make_series("RK4: upper string first", SeriesStyle::Points, FigureColour::Series0, {}, {});
  for (int i = 0; i < nb * ng; ++i) {
    const FirstBreak& b = runs[static_cast<std::size_t>(i)];
    if (!b.broke) continue;
    Series& s = b.spring == 0 ? lower : upper;
    s.x.push_back(betas[static_cast<std::size_t>(i % nb)]);
    s.y.push_back(gs[static_cast<std::size_t>(i / nb)]);
  }
  p.series.push_back(std::move(lower));
  p.series.push_back(std::move(upper));
  // The anomalous windows' heights: the k-th closes at the maximum of beta sin(1/beta) in it.
  p.notes.push_back({0.113, 0.137, "m=1: G < 0.128", FigureColour::Accent});
  p.notes.push_back({0.058, 0.082, "m=2", FigureColour::Accent});
  p.legend = Panel::Legend::BottomRight;
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_hanging_map(const FigureOptions& o) {
  Figure f{"hanging_map",
           "A hanging chain, N = 30, \u03C6_c = 1, \u03B3 = 0, pulled down at its free end by "
           "f = \u03B2\u03C4: the spring that breaks first against \u03B2, on a table (G = 0) and "
           "hanging (G = 0.01, 0.02): exact (lines), RK4 (points)",
           {}};
  Panel p;
  p.title = "Which spring of a hanging chain breaks first, N = 30, f = \u03B2\u03C4";
  p.x = axis("\u03B2 (log scale)   left: slow pull, right: jerk", kHangingBetaLo, kHangingBetaHi,
             true);
  p.y = axis("spring (1: at the ceiling)", 0.0, kMapBeads + 6.0);
  for (int j : {1, 5, 10, 15, 20, 25, 30}) p.y.ticks.push_back({double(j), std::to_string(j)});
  const struct {
    double gravity;
    FigureColour colour;
    const char* name;
  } cases[3] = {{0.0, FigureColour::Muted, "G = 0"},
                {0.01, FigureColour::Series0, "G = 0.01"},
                {0.02, FigureColour::Series2, "G = 0.02"}};
  const std::vector<double> beta = logspace(kHangingBetaLo, kHangingBetaHi, o.map_exact / 4);
  for (const auto& c : cases) {
    const auto exact = parallel_first_breaks(static_cast<int>(beta.size()), o.jobs, [&](int i) {
      if (stopped(o)) return FirstBreak{};
      const double b = beta[static_cast<std::size_t>(i)];
      return exact_first_break(hanging_chain(c.gravity), ramp(b), chain_t_end(b));
    });
    if (stopped(o)) return f;
    std::vector<double> spring;
    for (const FirstBreak& b : exact) spring.push_back(b.broke ? b.spring : kNaN);
    p.series.push_back(make_series(std::string("exact ") + c.name, SeriesStyle::Line, c.colour,
                                   beta, std::move(spring)));
  }
  for (const auto& c : cases) {
    if (c.gravity == 0.0) continue;  // the table's chain is breaking_map's
    // Grids of different sizes, so the two weights' points do not hide each other.
    const std::vector<double> coarse =
        logspace(kHangingBetaLo, kHangingBetaHi, o.map_rk4 / 3 + (c.gravity > 0.015 ? 7 : 0));
    const auto runs = parallel_first_breaks(static_cast<int>(coarse.size()), o.jobs, [&](int i) {
      const double b = coarse[static_cast<std::size_t>(i)];
      return simulated_first_break(hanging_chain(c.gravity), ramp(b), chain_t_end(b), o.dt, o.stop);
    });
    if (stopped(o)) return f;
    std::vector<double> spring;
    for (const FirstBreak& b : runs) spring.push_back(b.broke ? b.spring : kNaN);
    p.series.push_back(make_series(std::string("RK4 ") + c.name, SeriesStyle::Points, c.colour,
                                   coarse, std::move(spring)));
  }
  p.notes.push_back({kHangingBetaLo * 1.1, kMapBeads + 3.5,
                     "a slow pull breaks the top spring, which holds the whole weight",
                     FigureColour::Muted});
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace cb
