// Two maps the paper does not draw: which spring of an N = 30 chain breaks first against
// zeta_c = phi_c / beta (exact and RK4, gamma = 0 and 0.01, with the continuum prediction of
// Eq. (phij)), and which string of the one-body experiment breaks against beta (Eq. (heald)).
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "figures/break_maps.h"
#include "figures/figure_specs.h"

namespace cb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kN = kMapBeads;

double spring_or_nan(const FirstBreak& b) {
  return b.broke ? b.spring : kNaN;
}

}  // namespace

Figure figure_breaking_map(const FigureOptions& o) {
  Figure f{
      "breaking_map",
      "Breaking map: the spring that breaks first against \u03B6_c = \u03C6_c / \u03B2 for a ramp, "
      "N = 30, \u03B3 = 0 and 0.01: exact (lines), RK4 (points), continuum Eq. (phij) (bands)",
      {}};
  Panel p;
  p.title =
      "Which spring breaks first, N = 30, f = \u03B2\u03C4, threshold \u03B6_c = \u03C6_c/\u03B2";
  p.x = axis("\u03B6_c = \u03C6_c / \u03B2   (small: a fast pull, large: a slow pull)", 0.0,
             kMapZetaMax);
  p.y = axis("spring", 0.0, kN + 6.0);  // room above spring N for the legend
  for (int j : {1, 5, 10, 15, 20, 25, 30}) p.y.ticks.push_back({double(j), std::to_string(j)});
  // The continuum prediction at gamma = 0: spring N, or springs 1 .. last_spring together.
  const std::vector<double> fine = linspace(0.5, kMapZetaMax, 2000);
  Series pulled =
      make_series("continuum: spring N", SeriesStyle::Band, FigureColour::Muted, fine, {});
  Series wall = make_series("continuum: springs 1..\u03BE*", SeriesStyle::Band, FigureColour::Muted,
                            fine, {});
  for (double zeta : fine) {
    const ContinuumBreak c = continuum_ramp_break(kN, zeta);
    pulled.y.push_back(c.pulled_end ? kN - 0.5 : kNaN);
    pulled.y2.push_back(c.pulled_end ? kN + 0.5 : kNaN);
    wall.y.push_back(c.pulled_end ? kNaN : 0.5);
    wall.y2.push_back(c.pulled_end ? kNaN : c.last_spring + 0.5);
  }
  p.series.push_back(std::move(pulled));
  p.series.push_back(std::move(wall));
  Series edges = make_series("continuum boundaries 2N, 4N, 6N, 8N", SeriesStyle::VLines,
                             FigureColour::Muted, {2.0 * kN, 4.0 * kN, 6.0 * kN, 8.0 * kN}, {});
  p.series.push_back(std::move(edges));

  const std::vector<double> zeta = linspace(0.5, kMapZetaMax, o.map_exact);
  const std::vector<double> coarse = linspace(1.0, kMapZetaMax - 1.0, o.map_rk4);
  const double t_end = 4.0 * kMapZetaMax + 8.0 * kN;
  const struct {
    double gamma;
    FigureColour colour;
    const char* name;
  } cases[2] = {{0.0, FigureColour::Series2, "\u03B3 = 0"},
                {0.01, FigureColour::Series0, "\u03B3 = 0.01"}};
  for (const auto& c : cases) {
    std::vector<double> exact_spring;
    for (const FirstBreak& b : breaking_map(kN, c.gamma, BreakMode::Abs, zeta, t_end, o.stop))
      exact_spring.push_back(spring_or_nan(b));
    p.series.push_back(make_series(std::string("exact ") + c.name, SeriesStyle::Line, c.colour,
                                   zeta, std::move(exact_spring)));
    if (stopped(o)) return f;  // each exact map is seconds of work: look between them
  }
  for (const auto& c : cases) {
    const auto runs = parallel_first_breaks(static_cast<int>(coarse.size()), o.jobs, [&](int i) {
      ChainParams chain;
      chain.beads = kN;
      chain.gamma = c.gamma;
      chain.threshold = coarse[static_cast<std::size_t>(i)];
      DriveDesc ramp;
      ramp.type = DriveType::Ramp;
      ramp.beta = 1.0;
      return simulated_first_break(chain, ramp, t_end, o.dt, o.stop);
    });
    std::vector<double> spring;
    for (const FirstBreak& b : runs) spring.push_back(spring_or_nan(b));
    p.series.push_back(make_series(std::string("RK4 ") + c.name, SeriesStyle::Points, c.colour,
                                   coarse, std::move(spring)));
  }
  // Where the exact map switches between spring N and the others, marked above spring N
  // (gamma = 0 with its value, gamma = 0.01 in its colour a row higher).
  for (const auto& c : cases) {
    const double row = kN + (c.gamma == 0.0 ? 1.3 : 2.3);
    Series switches =
        make_series(std::string("exact N / not-N switch ") + c.name, SeriesStyle::Points,
                    c.gamma == 0.0 ? FigureColour::Accent : c.colour, {}, {});
    if (stopped(o)) return f;
    for (const MapBoundary& b :
         spring_n_boundaries(kN, c.gamma, 0.5, kMapZetaMax, 250, 1e-9, o.stop)) {
      switches.x.push_back(b.zeta);
      switches.y.push_back(row);
      const bool at_right = b.zeta > kMapZetaMax - 15.0;  // keep the label inside the plot
      if (c.gamma == 0.0)
        p.notes.push_back(
            {at_right ? b.zeta - 13.0 : b.zeta + 1.5, row, fixed(b.zeta, 2), FigureColour::Accent});
    }
    p.series.push_back(std::move(switches));
  }
  f.panels.push_back(std::move(p));
  return f;
}

Figure figure_one_body_map(const FigureOptions& o) {
  Figure f{
      "one_body_map",
      "One-body pull-or-jerk: which string breaks first against \u03B2 (ramp f = \u03B2\u03C4, "
      "\u03C6_c = 1): exact (line), RK4 (points), windows sin(1/\u03B2) > 0 of Eq. (heald)",
      {}};
  Panel p;
  p.title = "Pull or jerk, one body: which string breaks, f = \u03B2\u03C4, \u03C6_c = 1";
  p.x = axis("\u03B2 (log scale)   left: slow pull, right: jerk", kOneBodyBetaLo, kOneBodyBetaHi,
             true);
  p.y = {"first to break",
         -0.6,
         1.9,
         false,
         {{0.0, "lower (pull string)"}, {1.0, "upper (spring 1)"}}};
  // Eq. (heald): the lower string first iff sin(1/beta) > 0; every window inside the range.
  Series jerk =
      make_series("jerk: \u03B2 > 1/\u03C0", SeriesStyle::XSpans, FigureColour::Series1, {}, {});
  Series anomalous = make_series("anomalous windows 1/((2m+1)\u03C0) < \u03B2 < 1/(2m\u03C0)",
                                 SeriesStyle::XSpans, FigureColour::Kinetic, {}, {});
  const int count = static_cast<int>(std::ceil(1.0 / (2.0 * std::numbers::pi * kOneBodyBetaLo)));
  const auto windows = one_body_jerk_windows(count + 1);
  for (std::size_t m = 0; m < windows.size(); ++m) {
    const double lo = std::max(windows[m].lo, kOneBodyBetaLo);
    const double hi = std::min(windows[m].hi, kOneBodyBetaHi);
    if (!(hi > lo)) continue;
    Series& s = m == 0 ? jerk : anomalous;
    s.x.push_back(lo);
    s.x2.push_back(hi);
    if (m >= 1 && m <= 3)
      p.notes.push_back({lo, 1.55, "m=" + std::to_string(m), FigureColour::Kinetic});
  }
  p.series.push_back(std::move(jerk));
  p.series.push_back(std::move(anomalous));

  ChainParams chain;
  chain.beads = 1;
  chain.threshold = 1.0;
  chain.pull_string = true;
  const auto ramp = [](double beta) {
    DriveDesc d;
    d.type = DriveType::Ramp;
    d.beta = beta;
    return d;
  };
  const std::vector<double> beta = logspace(kOneBodyBetaLo, kOneBodyBetaHi, o.map_exact * 2);
  std::vector<double> exact;
  for (double b : beta)
    exact.push_back(spring_or_nan(exact_first_break(chain, ramp(b), 1.0 / b + 10.0)));
  p.series.push_back(
      make_series("exact", SeriesStyle::Line, FigureColour::Ink, beta, std::move(exact)));
  const std::vector<double> coarse = logspace(kOneBodyBetaLo, kOneBodyBetaHi, o.map_rk4 * 2);
  const auto runs = parallel_first_breaks(static_cast<int>(coarse.size()), o.jobs, [&](int i) {
    const double b = coarse[static_cast<std::size_t>(i)];
    return simulated_first_break(chain, ramp(b), 1.0 / b + 10.0, o.dt, o.stop);
  });
  std::vector<double> rk4;
  for (const FirstBreak& b : runs) rk4.push_back(spring_or_nan(b));
  p.series.push_back(
      make_series("RK4", SeriesStyle::Points, FigureColour::Series2, coarse, std::move(rk4)));
  p.notes.push_back({kOneBodyBetaLo * 1.05, -0.35,
                     "the windows go on, ever narrower, as \u03B2 \u2192 0", FigureColour::Muted});
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace cb
