// set_scene_number(): one numeric key of an in-memory scene, as a scene file would give it.
//
// Why: `sweep` varies one key over hundreds of values; reading and parsing the scene file
// again for each was the only way to have each value checked. Now the value is converted to
// Eq. (dimless) form here and checked by validate(), the same rules as the file's.
#include <algorithm>
#include <climits>
#include <cmath>

#include "physics/threshold_draw.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"
#include "scene/scene_units.h"

namespace cb {

namespace {

enum class Quantity { Plain, Time, Force, Slope };

struct NumberKey {
  const char* key;
  Quantity quantity;
  double* (*field)(SceneDesc&);
};

// The keys a double of the scene holds directly; beads and the frame size are whole
// numbers and handled apart.
const NumberKey kNumberKeys[] = {
    {"chain.threshold", Quantity::Force, [](SceneDesc& s) { return &s.chain.threshold; }},
    {"chain.gravity", Quantity::Force, [](SceneDesc& s) { return &s.chain.gravity; }},
    {"drive.beta", Quantity::Slope, [](SceneDesc& s) { return &s.drive.beta; }},
    {"drive.amplitude", Quantity::Force, [](SceneDesc& s) { return &s.drive.amplitude; }},
    {"drive.period", Quantity::Time, [](SceneDesc& s) { return &s.drive.period; }},
    {"drive.t0", Quantity::Time, [](SceneDesc& s) { return &s.drive.t0; }},
    {"integrator.dt", Quantity::Time, [](SceneDesc& s) { return &s.integrator.dt; }},
    {"integrator.t_end", Quantity::Time, [](SceneDesc& s) { return &s.integrator.t_end; }},
    {"render.fps", Quantity::Plain, [](SceneDesc& s) { return &s.render.fps; }},
    {"render.speed", Quantity::Plain, [](SceneDesc& s) { return &s.render.speed; }},
};

double converted(const scene_detail::Conversion& c, Quantity q, double v) {
  switch (q) {
    case Quantity::Time:
      return c.time(v);
    case Quantity::Force:
      return c.force(v);
    case Quantity::Slope:
      return c.slope(v);
    case Quantity::Plain:
      break;
  }
  return v;
}

int whole(const std::string& key, double v, const std::string& origin) {
  if (v != std::floor(v) || std::abs(v) > INT_MAX)
    throw SceneError(origin + ": " + key + " must be an integer (a whole number), got " +
                     std::to_string(v));
  return static_cast<int>(v);
}

}  // namespace

namespace {

// Sets `key` of `next` without validating it; false for a key that cannot be set in memory.
bool assign_number(SceneDesc& next, const std::string& key, double value,
                   const std::string& origin) {
  const scene_detail::Conversion c = scene_detail::conversion_for(next.units);
  // The chain's arrays were expanded for its N, and the thresholds' scale is their smallest:
  // a new N or threshold re-reads the text, where each pattern expands anew (or an explicit
  // array is refused for its length).
  const ChainParams& chain = next.chain;
  if ((key == "chain.beads" &&
       !(chain.mass.empty() && chain.stiffness.empty() && chain.thresholds.empty())) ||
      (key == "chain.threshold" && !chain.thresholds.empty()))
    return false;
  // A hanging chain's view defaults to vertical (scene_render.cpp): where G starts or stops
  // hanging the chain and the text gives no view, the text is read again for it.
  if (key == "chain.gravity" && !next.origins.contains("render.view") &&
      (value > 0.0) != chain.hanging())
    return false;
  if (key == "chain.seed") {
    // Drawn here as the reader draws them, so a sweep over 10^4 seeds does not parse the file
    // 10^4 times.
    if (!redraw_thresholds(next, value)) return false;
  } else if (key == "chain.beads") {
    next.chain.beads = whole(key, value, origin);
  } else if (key == "render.width") {
    next.render.width = whole(key, value, origin);
  } else if (key == "render.height") {
    next.render.height = whole(key, value, origin);
  } else if (key == "integrator.after_break") {
    next.integrator.after_break = c.time(value);
  } else if (key == "chain.gamma") {
    // With units.friction given, gamma follows from it and the reader must settle the two.
    if (next.units && next.origins.contains("units.friction")) return false;
    next.chain.gamma = value;
    if (next.units) next.units->friction = value * 2.0 * next.units->mass * next.units->omega0();
  } else {
    const NumberKey* found = nullptr;
    for (const NumberKey& k : kNumberKeys)
      if (key == k.key) found = &k;
    if (!found) return false;
    *found->field(next) = converted(c, found->quantity, value);
  }
  next.origins.set(key, origin);
  return true;
}

}  // namespace

void draw_threshold_rows_into(const ThresholdDraw& draw, int beads, const std::uint64_t* seeds,
                              std::size_t rows, double* out) {
  draw_threshold_rows(draw.dist == "normal" ? ThresholdDist::Normal : ThresholdDist::Weibull,
                      draw.scale, draw.shape, seeds, rows, beads, out);
}

void draw_thresholds_into(const ThresholdDraw& draw, int beads, double* out) {
  const auto seed = static_cast<std::uint64_t>(draw.seed);
  draw_threshold_rows_into(draw, beads, &seed, 1, out);
}

std::optional<std::uint64_t> seed_of_value(double value) {
  if (value < 0.0 || value != std::floor(value) || value > 9.0e15) return std::nullopt;
  return static_cast<std::uint64_t>(value);
}

namespace {

// Sets `scene` drawn for `seed`, its thresholds from `fill` (which writes N into its argument),
// or returns false where the scene draws none or the reader refuses the seed.
template <class Fill>
bool set_thresholds_of_seed(SceneDesc& scene, double seed, const Fill& fill) {
  const std::optional<std::uint64_t> whole = seed_of_value(seed);
  if (!scene.threshold_draw || !whole) return false;
  scene.threshold_draw->seed = static_cast<std::int64_t>(*whole);
  ChainParams& p = scene.chain;
  p.thresholds.resize(static_cast<std::size_t>(p.beads));
  fill(p.thresholds.data());
  p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
  p.normalize();
  return true;
}

}  // namespace

bool redraw_thresholds(SceneDesc& scene, double seed) {
  return set_thresholds_of_seed(scene, seed, [&](double* out) {
    draw_thresholds_into(*scene.threshold_draw, scene.chain.beads, out);
  });
}

bool set_drawn_thresholds(SceneDesc& scene, double seed, const double* row) {
  return set_thresholds_of_seed(scene, seed,
                                [&](double* out) { std::copy_n(row, scene.chain.beads, out); });
}

bool every_draw_passes(const SceneDesc& scene) {
  if (!scene.threshold_draw || scene.threshold_draw->dist != "weibull") return false;
  const ThresholdDraw& d = *scene.threshold_draw;
  if (scene.chain.hanging() || scene.chain.anharmonic() ||
      !weibull_draws_positive_finite(d.scale, d.shape))
    return false;
  // The quantile rises with u: every draw lies between these two, and the checks left
  // (Checker::coefficients: finite and above zero) read each threshold alone.
  for (const std::uint64_t bits : {std::uint64_t{0}, (std::uint64_t{1} << 53) - 1}) {
    const double phi = weibull_threshold(d.scale, d.shape, uniform_of_bits(bits));
    SceneDesc row = scene;
    row.chain.thresholds.assign(static_cast<std::size_t>(row.chain.beads), phi);
    row.chain.threshold = phi;
    row.chain.normalize();
    try {
      validate_new_thresholds(row);
    } catch (const SceneError&) {
      return false;
    }
  }
  return true;
}

bool draws_alike(const SceneDesc& a, const SceneDesc& b) {
  return a.threshold_draw && b.threshold_draw && a.chain.beads == b.chain.beads &&
         a.threshold_draw->dist == b.threshold_draw->dist &&
         a.threshold_draw->scale == b.threshold_draw->scale &&
         a.threshold_draw->shape == b.threshold_draw->shape;
}

bool set_scene_number(SceneDesc& scene, const std::string& key, double value,
                      const std::string& origin) {
  return set_scene_numbers(scene, {{key, value, origin}});
}

namespace {

// set_scene_numbers on a scene the caller throws away when it returns false or throws.
bool set_numbers_of_copy(SceneDesc& copy, const std::vector<NumberSetting>& settings) {
  for (const NumberSetting& s : settings)
    if (!assign_number(copy, s.key, s.value, s.origin)) return false;
  // Checked once all are set: values that only fit together (N and dt) are not refused
  // half way.
  validate(copy);
  return true;
}

}  // namespace

bool set_scene_numbers(SceneDesc& scene, const std::vector<NumberSetting>& settings) {
  SceneDesc next = scene;
  if (!set_numbers_of_copy(next, settings)) return false;
  scene = std::move(next);
  return true;
}

SceneVariations::SceneVariations(std::string path, std::vector<Override> overrides)
    : SceneVariations(path, read_scene_text(path), std::move(overrides)) {}

SceneVariations::SceneVariations(std::string path, std::string text,
                                 std::vector<Override> overrides)
    : path_(std::move(path)), overrides_(std::move(overrides)), text_(std::move(text)) {
  // A scene that fails alone may still pass with the varied value (a dt too large for the
  // scene's N, swept down): then each value is parsed from the text, as an override.
  try {
    base_ = parse_scene(text_, path_, overrides_);
  } catch (const SceneError&) {
    base_.reset();
  }
}

SceneDesc SceneVariations::with(const std::string& key, double value,
                                const std::string& origin) const {
  return with({{key, value, origin}});
}

SceneDesc SceneVariations::with(const std::vector<NumberSetting>& settings) const {
  if (base_) {
    SceneDesc scene = *base_;  // the one copy a point costs
    if (set_numbers_of_copy(scene, settings)) return scene;
  }
  auto overrides = overrides_;
  for (const NumberSetting& s : settings)
    overrides.push_back({s.key, scene_detail::format_exact(s.value)});
  return parse_scene(text_, path_, overrides);
}

}  // namespace cb
