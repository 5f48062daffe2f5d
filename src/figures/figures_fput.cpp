// The breaking map of a chain of anharmonic springs (issue #24): which spring of an N = 30 chain
// breaks first against the ramp's slope beta, for tensions phi + b phi^3 with b = 0, 0.5 and
// -0.1, all with phi_c = 1.5. A harmonic chain's map depends on beta only through zeta_c =
// phi_c / beta (Eq. (rescale2)); anharmonic springs break that scaling, so the axis is beta and
// the maps come from RK4 with breaking. The harmonic chain's exact map is drawn as a line.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "figures/break_maps.h"
#include "figures/figure_specs.h"

namespace cb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

Figure figure_fput_map(const FigureOptions& o) {
  const int n = kMapBeads;
  // phi_c below the flat point of b = -0.1 (T' = 1 - 0.3 phi^2 = 0 at phi = 1.826), where that
  // chain's tension stops growing; the scene reader refuses chains beyond it.
  const double phi_c = kFputMapThreshold;
  const double beta_lo = phi_c / kMapZetaMax, beta_hi = phi_c / 0.5;  // the harmonic map's range
  Figure f{"fput_map",
           "Anharmonic springs, tension \u03C6 + b\u03C6\u00B3: the spring that breaks first "
           "against \u03B2 for a ramp f = \u03B2\u03C4, N = 30, \u03C6_c = 1.5, \u03B3 = 0; "
           "RK4 (points) for b = 0, 0.5, \u22120.1 and the harmonic chain's exact map (line)",
           {}};
  Panel p;
  p.title = "Which spring breaks first, FPUT-\u03B2 springs, N = 30, \u03C6_c = 1.5";
  p.x = axis("\u03B2 (log scale)   left: a slow pull, right: a fast pull", beta_lo, beta_hi, true);
  p.y = axis("spring", 0.0, n + 6.0);
  for (int j : {1, 5, 10, 15, 20, 25, 30}) p.y.ticks.push_back({double(j), std::to_string(j)});

  // b = 0: the exact map of Eq. (rescale2) at zeta_c = phi_c / beta.
  const std::vector<double> fine = logspace(beta_lo, beta_hi, o.map_exact);
  std::vector<double> zeta;
  for (double b : fine) zeta.push_back(phi_c / b);
  std::vector<double> exact;
  for (const FirstBreak& b :
       breaking_map(n, 0.0, BreakMode::Abs, zeta, 4.0 * kMapZetaMax + 8.0 * n, o.stop))
    exact.push_back(b.broke ? b.spring : kNaN);
  p.series.push_back(make_series("exact b = 0 (harmonic)", SeriesStyle::Line, FigureColour::Ink,
                                 fine, std::move(exact)));
  if (stopped(o)) return f;

  const std::vector<double> coarse = logspace(beta_lo, beta_hi, o.map_rk4);
  const struct {
    double b;
    FigureColour colour;
    const char* name;
  } cases[3] = {{0.0, FigureColour::Series2, "RK4 b = 0"},
                {0.5, FigureColour::Series0, "RK4 b = 0.5 (stiffening)"},
                {-0.1, FigureColour::Series1, "RK4 b = \u22120.1 (softening)"}};
  for (const auto& c : cases) {
    ChainParams chain;
    chain.beads = n;
    chain.threshold = phi_c;
    chain.fput_beta = c.b;
    // Until the drive is four times the tension at phi_c (the harmonic one's for b < 0), and
    // 8N more: past the time the pulled spring alone would break.
    const double load = 4.0 * fput_tension(phi_c, 0.0, std::max(c.b, 0.0));
    const auto runs = parallel_first_breaks(static_cast<int>(coarse.size()), o.jobs, [&](int i) {
      const double beta = coarse[static_cast<std::size_t>(i)];
      DriveDesc ramp;
      ramp.type = DriveType::Ramp;
      ramp.beta = beta;
      return simulated_first_break(chain, ramp, load / beta + 8.0 * n, o.dt, o.stop);
    });
    std::vector<double> spring;
    for (const FirstBreak& b : runs) spring.push_back(b.broke ? b.spring : kNaN);
    p.series.push_back(
        make_series(c.name, SeriesStyle::Points, c.colour, coarse, std::move(spring)));
    if (stopped(o)) return f;
  }
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace cb
