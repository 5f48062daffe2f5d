// The figures `chainbreak figures` makes, each with the parameters its caption in the paper
// gives: Fig. 3(a)-(d), Fig. 4(a)-(d), Fig. 5, and two maps the paper does not draw (which
// spring breaks first against zeta_c = phi_c / beta for N = 30; which string of the one-body
// pull-or-jerk experiment breaks against beta). Plain data, no GL.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "figures/figure.h"
#include "physics/stop_flag.h"

namespace cb {

struct FigureOptions {
  int jobs = 0;          // threads for the RK4 maps; 0: all cores
  double dt = 0.01;      // RK4 step (the paper's Appendix: 150 / 15000)
  int map_exact = 1200;  // zeta_c (or beta) samples of the exact maps
  int map_rk4 = 90;      // samples of the RK4 maps (each a run until the first break)
  // When set and true, the RK4 runs stop early: the figure is then incomplete and the
  // caller (an interrupted `figures`) throws it away.
  const std::atomic<bool>* stop = nullptr;
};

// True once options.stop is set and true: a builder may then return what it has.
inline bool stopped(const FigureOptions& o) {
  return stop_requested(o.stop);
}

struct FigureEntry {
  std::string name;  // fig3a ... fig5, breaking_map, one_body_map
  std::function<Figure(const FigureOptions&)> build;
};
// In the order the paper has them, then the two maps.
const std::vector<FigureEntry>& figure_entries();

// The paper's figures (figures_fig3.cpp, figures_fig4.cpp).
Figure figure_3a(const FigureOptions&);  // psi(xi, tau), step, N = 30, gamma = 0.01
Figure figure_3b(const FigureOptions&);  // dG/dxi, gamma = 0
Figure figure_3c(const FigureOptions&);  // phi_j under sin(2 pi tau / 4N), RK4 vs Eq. (sum)
Figure figure_3d(const FigureOptions&);  // phi(xi, tau) for delta(tau) + delta(tau - N)
Figure figure_4a(const FigureOptions&);  // phi_1, phi_15, phi_30: RK4 vs Eqs. (extension)-(phi1)
Figure figure_4b(const FigureOptions&);  // energy per particle, Eq. (energy)
Figure figure_4c(const FigureOptions&);  // zeta_1, zeta_N and three thresholds
Figure figure_4d(const FigureOptions&);  // gamma = 0.01
Figure figure_5(const FigureOptions&);   // Eq. (exactconv) vs RK4, with an inset
// The maps (figures_maps.cpp).
Figure figure_breaking_map(const FigureOptions&);
Figure figure_one_body_map(const FigureOptions&);
// Under gravity (figures_gravity.cpp, issue #22): Heald's ball in the (beta, G) plane; which
// spring of a hanging N = 30 chain breaks first against beta.
Figure figure_gravity_map(const FigureOptions&);
Figure figure_hanging_map(const FigureOptions&);
// Anharmonic springs (figures_fput.cpp, issue #24): first break against beta, RK4.
Figure figure_fput_map(const FigureOptions&);
// Flawed chains (figures_flaw.cpp, issue #23): the fraction of Weibull seeds in which each spring
// breaks first, against beta (a heatmap springs x beta).
Figure figure_flaw_map(const FigureOptions&);
inline constexpr int kMapBeads = 30;  // the maps' chains
inline constexpr double kFlawBetaLo = 0.001, kFlawBetaHi = 3.0;
inline constexpr double kFlawMapModulus = 4.0, kFlawMapGamma = 0.05;
inline constexpr double kFlawMapColourTop = 0.1;  // the sequential map's darkest fraction
// The flaw map's numbers: fraction of seeds 1 .. seeds in which spring j breaks first at beta[b].
struct FlawMapData {
  std::vector<double> beta;
  int seeds = 0;
  std::vector<double> fraction;  // at b N + j - 1
  std::vector<int> unbroken;     // per beta: seeds with no break by the end of the search
  double at(int b, int spring) const {
    return fraction[static_cast<std::size_t>(b) * kMapBeads + spring - 1];
  }
  double mean_spring(int b) const;  // sum_j j fraction
  double spread(int b) const;       // the breaking spring's standard deviation
};
FlawMapData flaw_map_data(const FigureOptions& o, int betas, int seeds);

// The breaking map's range and its three thresholds of Fig. 4(c), for N = 30.
inline constexpr double kMapZetaMax = 250.0;  // past 8N = 240
inline constexpr double kFig4cThresholds[3] = {40.0, 100.0, 160.0};
// The anharmonic map's threshold, for every b (below b = -0.1's flat point 1.826).
inline constexpr double kFputMapThreshold = 1.5;
// The one-body map's range of beta (log scale).
inline constexpr double kOneBodyBetaLo = 0.01, kOneBodyBetaHi = 10.0;
// The gravity map's range (linear beta: the windows m = 1, 2, 3 and the jerk; G up to past the
// first window's top, 0.128) and the hanging map's (log beta).
inline constexpr double kGravityBetaLo = 0.03, kGravityBetaHi = 0.5, kGravityGMax = 0.3;
inline constexpr double kHangingBetaLo = 0.002, kHangingBetaHi = 2.0;

// Shared by the builders (figure.cpp).
std::vector<double> linspace(double lo, double hi, int count);
std::vector<double> logspace(double lo, double hi, int count);
Series make_series(std::string label, SeriesStyle style, FigureColour colour, std::vector<double> x,
                   std::vector<double> y);
// value with `decimals` decimals (labels and notes).
std::string fixed(double value, int decimals);
// y from the smallest to the largest y of the panel's series, widened by `pad` of the span.
void fit_y(Panel& panel, double pad = 0.05);
// The series of `panel` called `label`; null when there is none.
const Series* find_series(const Panel& panel, const std::string& label);

}  // namespace cb
