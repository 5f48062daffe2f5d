// Internal to src/scene: chain.mass, chain.stiffness and chain.threshold, the per-bead and
// per-spring coefficients of issue #21's chain, in the scene's three forms (scene.cpp):
//   mass = 2.0                                     every bead
//   mass = [1.0, 1.0, 4.0, ...]                    bead 1..N (spring 1..N), N values
//   mass = { value = 4.0, at = 15 }                one bead differs from `base`
//   mass = { value = 4.0, from = 16, to = 30 }     a segment (from, to default 1 and N)
//   mass = { from_value = 1.0, to_value = 2.0 }    linear from bead 1 to bead N
// `base` (every other bead or spring) defaults to 1 for mass and stiffness; a threshold
// pattern must give it. The reader and the scene writer both live here, so the patterns it
// writes are exactly those it reads.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_reader.h"
#include "scene/scene_units.h"

namespace cb::scene_detail {

// A pattern expands to one value per bead; beyond this N a pattern would allocate more than a
// run can use (80 MB per array), and a scene with such a chain is a typo.
inline constexpr int kMaxCoefficientBeads = 10'000'000;

struct CoefficientKey {
  std::string_view key;                          // "mass", "stiffness" or "threshold" of [chain]
  std::string_view element;                      // "bead" or "spring"
  std::optional<double> base;                    // the pattern's default base, if any
  double (*convert)(const Conversion&, double);  // scene units -> Eq. (dimless)
};

struct Coefficients {
  std::optional<double> scalar;  // a number was given
  std::vector<double> values;    // an array (any length; validate() checks it is N) or a
                                 // pattern expanded to N values
};

// nullopt when absent, or wrong (noted as a problem), or a pattern on a chain whose N is
// itself wrong (its problem is noted by validate()).
std::optional<Coefficients> read_coefficients(const SceneReader& r, const CoefficientKey& spec,
                                              int beads, bool beads_ok, const Conversion& c);

// "chain.mass has 29 values but the chain has N = 30 beads; ...": one message for the reader
// (an empty array) and validate() (any other length).
std::string length_problem(std::string_view key, std::string_view element, std::size_t got,
                           int beads);

// Value j (1..n) of the linear pattern from a (bead 1) to b (bead n); the writer recognises
// a gradient by this very formula, so what it writes reads back bit for bit.
double gradient_value(double a, double b, int j, int n);

// The shortest form above that gives back `values` exactly: a number, a pattern, or the
// array. `number` writes one value (the writer's format).
std::string coefficients_text(const std::vector<double>& values, std::optional<double> default_base,
                              std::string (*number)(double));

}  // namespace cb::scene_detail
