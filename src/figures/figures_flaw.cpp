// Which spring of a flawed chain breaks first (issue #23): N = 30 springs whose thresholds are
// drawn from a Weibull law, pulled at rate beta. For each beta, thousands of seeds in one RK4 run
// (physics/threshold_ensemble.h): the fraction of seeds in which each spring breaks first.
// A slow pull stretches the chain almost evenly, so the weakest spring breaks wherever it is
// (1/N each: the weakest-link limit); a jerk breaks the pulled end, spring N, before the wave
// reaches the rest (the paper's Fig. 4(c) regime), whatever the flaws.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "figures/break_maps.h"
#include "figures/figure_specs.h"
#include "physics/threshold_draw.h"
#include "physics/threshold_ensemble.h"

namespace cb {

namespace {

// The drawn thresholds of seeds 1 .. count, as the ensemble takes them (member m, spring j at
// m N + j - 1): the same values `run --set chain.seed=S` uses.
std::vector<double> flaw_thresholds(int count) {
  std::vector<double> all;
  all.reserve(static_cast<std::size_t>(count) * kMapBeads);
  for (int seed = 1; seed <= count; ++seed) {
    const std::vector<double> t = draw_thresholds(ThresholdDist::Weibull, 1.0, kFlawMapModulus,
                                                  static_cast<std::uint64_t>(seed), kMapBeads);
    all.insert(all.end(), t.begin(), t.end());
  }
  return all;
}

}  // namespace

FlawMapData flaw_map_data(const FigureOptions& o, int betas, int seeds) {
  FlawMapData d;
  d.beta = logspace(kFlawBetaLo, kFlawBetaHi, betas);
  d.seeds = seeds;
  d.fraction.assign(static_cast<std::size_t>(betas) * kMapBeads, 0.0);
  d.unbroken.assign(static_cast<std::size_t>(betas), 0);
  const std::vector<double> thresholds = flaw_thresholds(seeds);
  parallel_first_breaks(betas, o.jobs, [&](int i) {
    const double beta = d.beta[static_cast<std::size_t>(i)];
    ThresholdEnsemble e;
    e.chain.beads = kMapBeads;
    e.chain.gamma = kFlawMapGamma;
    e.chain.threshold = 1.0;
    e.chain.normalize();
    DriveDesc drive;
    drive.type = DriveType::Ramp;
    drive.beta = beta;
    e.forcing = make_forcing(drive);
    e.dt = o.dt;
    // The weakest of 30 Weibull(4) springs lies below 1 for every seed; f = beta tau reaches
    // twice that long before the search ends.
    e.last_step = static_cast<std::int64_t>(std::ceil((2.0 / beta + 8.0 * kMapBeads) / o.dt));
    e.thresholds = thresholds;  // every beta's the same seeds, read in place
    const std::vector<LaneEnd> ends = ensemble_first_breaks(e, o.stop);
    for (const LaneEnd& end : ends) {
      if (end.kind != LaneEnd::Kind::Broke) {
        ++d.unbroken[static_cast<std::size_t>(i)];
        continue;
      }
      d.fraction[static_cast<std::size_t>(i) * kMapBeads + end.first.spring - 1] += 1.0 / seeds;
    }
    return FirstBreak{};
  });
  return d;
}

double FlawMapData::mean_spring(int b) const {
  double mean = 0.0;
  for (int j = 1; j <= kMapBeads; ++j) mean += j * at(b, j);
  return mean;
}

double FlawMapData::spread(int b) const {
  const double mean = mean_spring(b);
  double var = 0.0;
  for (int j = 1; j <= kMapBeads; ++j) var += (j - mean) * (j - mean) * at(b, j);
  return std::sqrt(var);
}

Figure figure_flaw_map(const FigureOptions& o) {
  const int betas = 28, seeds = 2000;
  const FlawMapData d = flaw_map_data(o, betas, seeds);
  Figure f{"flaw_map", "", {}};
  if (stopped(o)) return f;
  Panel p;
  p.title = "Which spring of a flawed chain breaks first, N = 30, Weibull thresholds, m = 4";
  p.x = axis("\u03B2 (log scale)   left: slow pull, right: jerk", kFlawBetaLo, kFlawBetaHi, true);
  p.y = axis("spring (N = 30: the pulled end)", 0.5, kMapBeads + 0.5);
  for (int j : {1, 5, 10, 15, 20, 25, 30}) p.y.ticks.push_back({double(j), std::to_string(j)});
  Heatmap& h = p.heatmap;
  h.columns = betas;
  h.rows = kMapBeads;
  h.x_lo = d.beta[0] / std::sqrt(d.beta[1] / d.beta[0]);
  h.x_hi = d.beta.back() * std::sqrt(d.beta[1] / d.beta[0]);
  h.y_lo = 0.5;
  h.y_hi = kMapBeads + 0.5;
  h.x_log = true;
  h.colours = HeatmapColours::Sequential;
  // 1/N = 0.033 (the weakest-link limit) sits a third up the map; the jerk's spring N saturates.
  h.scale = kFlawMapColourTop;
  h.label = "fraction";  // of the seeds; 0.1 and above: the darkest
  for (int j = 1; j <= kMapBeads; ++j)
    for (int b = 0; b < betas; ++b) h.values.push_back(static_cast<float>(d.at(b, j)));
  p.x.lo = h.x_lo;
  p.x.hi = h.x_hi;
  std::vector<double> mean;
  for (int b = 0; b < betas; ++b) mean.push_back(d.mean_spring(b));
  p.series.push_back(make_series("mean breaking spring", SeriesStyle::Line, FigureColour::Accent,
                                 d.beta, std::move(mean)));
  p.series.push_back(make_series("weakest link: (N + 1)/2 on average", SeriesStyle::HLines,
                                 FigureColour::Muted, {}, {0.5 * (kMapBeads + 1)}));
  p.legend = Panel::Legend::BottomRight;
  const int last = betas - 1;
  f.caption = "Weibull thresholds (modulus 4, scale 1), N = 30, \u03B3 = 0.05, f = \u03B2\u03C4, " +
              std::to_string(seeds) +
              " seeds per \u03B2 (one RK4 run each): the spread of the breaking spring (its "
              "standard deviation) " +
              (d.spread(last) < d.spread(0) ? "shrinks" : "grows") + " from " +
              fixed(d.spread(0), 1) + " at \u03B2 = " + fixed(d.beta[0], 3) +
              " (1/N each: " + fixed(std::sqrt((kMapBeads * kMapBeads - 1) / 12.0), 1) + ") to " +
              fixed(d.spread(last), 1) + " at \u03B2 = " + fixed(d.beta[last], 0) +
              ", where spring N breaks in " + fixed(100.0 * d.at(last, kMapBeads), 0) +
              " % of the seeds";
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace cb
