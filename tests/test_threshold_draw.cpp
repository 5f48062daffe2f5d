// Flawed chains' thresholds (issue #23's scene keys; src/scene/threshold_draw.h): the
// counter-based uniform numbers against the same hash written in Python, the inverse CDFs
// against a Kolmogorov-Smirnov test and scipy's quantiles, and the scene keys.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "physics/threshold_draw.h"
#include "scene/scene.h"
#include "scene/scene_writer.h"
#include "scene_test_support.h"

using Catch::Matchers::Contains;
using namespace cb::scene_test;

TEST_CASE("thresholds: the uniform number of (seed, spring) is the documented hash",
          "[scene][flaws]") {
  // Expected: SplitMix64's finaliser applied as in threshold_draw.cpp, written again in
  // Python with arbitrary-precision integers masked to 64 bits (exact, no rounding but the
  // final conversion, which both do the same way).
  CHECK(cb::uniform_open01(1, 1) == 0.6871007905211135);
  CHECK(cb::uniform_open01(1, 2) == 0.9688225399024724);
  CHECK(cb::uniform_open01(7, 30) == 0.16575583810128286);
}

TEST_CASE("thresholds: u stays inside (0, 1) for every 53 bits, and so the Weibull draws finite",
          "[scene][flaws]") {
  // (k + 1/2) 2^-53: exact below 2^52, rounded to an even neighbour above, and for the largest
  // k to 1 itself, where a Weibull draw is infinite: that k is taken just below 1.
  const std::uint64_t top = (std::uint64_t{1} << 53) - 1;
  CHECK(cb::uniform_of_bits(0) == 0x1.0p-54);
  CHECK(cb::uniform_of_bits(top) == 0x1.fffffffffffffp-1);
  CHECK(cb::uniform_of_bits(top - 1) == 0x1.ffffffffffffep-1);  // 2^53 - 1.5 rounds to 2^53 - 2
  CHECK(cb::uniform_of_bits(std::uint64_t{1} << 51) == 0.25 + 0x1.0p-54);
  // The least and the largest draw bound every draw: positive and finite for these moduli, not
  // where the least underflows (modulus 0.01: (2^-54)^100).
  for (const double shape : {0.5, 1.5, 6.0, 40.0}) {
    INFO("shape " << shape);
    CHECK(std::isfinite(cb::weibull_threshold(0.8, shape, cb::uniform_of_bits(top))));
    CHECK(cb::weibull_draws_positive_finite(0.8, shape));
  }
  CHECK_FALSE(cb::weibull_draws_positive_finite(1.0, 0.01));
}

TEST_CASE("thresholds: 10^5 Weibull draws pass a Kolmogorov-Smirnov test", "[scene][flaws]") {
  // D_n = sup |F_n(x) - F(x)| against F(x) = 1 - exp(-x^m). For n = 10^5 the 0.1 % critical
  // value is 1.949 / sqrt(n) = 0.00616 (Kolmogorov's distribution): a correct sampler
  // exceeds it once in a thousand seeds, a wrong quantile (x^m instead of x^(1/m), a shifted
  // u) by far.
  constexpr int n = 100000;
  for (const double m : {2.0, 6.0}) {
    INFO("modulus " << m);
    std::vector<double> x(n);
    for (int j = 0; j < n; ++j)
      x[j] = cb::weibull_quantile(cb::uniform_open01(42, static_cast<std::uint64_t>(j + 1)), m);
    std::sort(x.begin(), x.end());
    double d = 0.0;
    for (int j = 0; j < n; ++j) {
      const double f = 1.0 - std::exp(-std::pow(x[j], m));
      d = std::max({d, (j + 1.0) / n - f, f - static_cast<double>(j) / n});
    }
    CHECK(d < 1.949 / std::sqrt(static_cast<double>(n)));
  }
}

TEST_CASE("thresholds: the normal quantile matches scipy's norm.ppf", "[scene][flaws]") {
  // scipy.stats.norm.ppf (scipy 1.10), to 4 ulps.
  CHECK(cb::normal_quantile(0.975) == Approx(1.959963984540054).epsilon(1e-15));
  CHECK(cb::normal_quantile(0.3) == Approx(-0.5244005127080407).epsilon(1e-15));
  CHECK(cb::normal_quantile(1e-9) == Approx(-5.997807015007686).epsilon(1e-15));
  CHECK(cb::normal_quantile(1e-300) == Approx(-37.0470962993612).epsilon(1e-14));
  CHECK(cb::normal_quantile(0.5) == 0.0);
}

namespace {

// kBase with drawn thresholds (a function: with() checks its argument with REQUIRE).
std::string flawed() {
  return with("gamma = 0.0",
              "gamma = 0.0\nthreshold = 3.0\nthreshold_dist = \"weibull\"\nthreshold_shape = "
              "6.0\nseed = 1");
}

}  // namespace

TEST_CASE("thresholds: chain.seed draws the same thresholds every time, others for another seed",
          "[scene][flaws]") {
  const cb::SceneDesc a = parse_scene(flawed(), "f.toml");
  REQUIRE(a.chain.thresholds.size() == 30);
  // Spring 1 and 2 of seed 1: 3 x the Weibull quantiles of the hash above (Python's values).
  CHECK(a.chain.thresholds[0] == Approx(3.0759629724364337).epsilon(1e-15));
  CHECK(a.chain.thresholds[1] == Approx(3.6909289565343313).epsilon(1e-15));
  CHECK(a.chain.threshold ==
        *std::min_element(a.chain.thresholds.begin(), a.chain.thresholds.end()));
  CHECK(parse_scene(flawed(), "f.toml").chain.thresholds == a.chain.thresholds);
  const cb::SceneDesc b = parse_scene(flawed(), "f.toml", {{"chain.seed", "2"}});
  CHECK(b.chain.thresholds != a.chain.thresholds);
  // Truncated normal: every threshold > 0 even with a relative spread of 1.
  const cb::SceneDesc n = parse_scene(
      flawed(), "f.toml", {{"chain.threshold_dist", "normal"}, {"chain.threshold_shape", "1.0"}});
  CHECK(std::all_of(n.chain.thresholds.begin(), n.chain.thresholds.end(),
                    [](double t) { return t > 0.0; }));
  // The writer writes the three keys back, not 30 numbers, and they draw the same values.
  const std::string text = cb::write_scene(a);
  CHECK_THAT(text, Contains("threshold = 3.0\nthreshold_dist = \"weibull\"\nthreshold_shape = "
                            "6.0\nseed = 1\n"));
  CHECK(parse_scene(text, "w.toml").chain.thresholds == a.chain.thresholds);
}

TEST_CASE("thresholds: mistakes in the drawing keys", "[scene][flaws]") {
  CHECK_THAT(error_of(with("gamma = 0.0", "seed = 1")),
             Contains("t.toml:3:8: chain.seed draws thresholds at random and needs "
                      "chain.threshold_dist"));
  CHECK_THAT(error_of(flawed(), {{"chain.threshold_dist", "weibul"}}),
             Contains("unknown chain.threshold_dist 'weibul'; did you mean \"weibull\"?"));
  CHECK_THAT(error_of(flawed(), {{"chain.threshold_shape", "0"}}),
             Contains("chain.threshold_shape must be > 0, got 0"));
  CHECK_THAT(error_of(flawed(), {{"chain.seed", "-3"}}), Contains("chain.seed must be >= 0"));
  CHECK_THAT(error_of(flawed(), {{"chain.threshold", "[1, 2]"}}),
             Contains("chain.threshold must be one number, their scale"));
}
