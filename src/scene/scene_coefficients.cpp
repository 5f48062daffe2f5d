// chain.mass, chain.stiffness, chain.threshold: read and written (scene_coefficients.h).
#include "scene/scene_coefficients.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cb::scene_detail {

namespace {

constexpr std::array<std::string_view, 7> kPatternKeys = {"base", "value",      "at",      "from",
                                                          "to",   "from_value", "to_value"};

// The forms, for every hint: what a user can paste.
std::string forms(const CoefficientKey& spec) {
  const std::string k(spec.key), base = spec.base ? "" : "base = 1.0, ";
  return "write e.g. " + k + " = { " + base + "value = 0.5, at = 15 } (one " +
         std::string(spec.element) + "), " + k + " = { " + base +
         "value = 2.0, from = 16, to = 30 } (a segment), " + k +
         " = { from_value = 1.0, to_value = 2.0 } (linear) or an array of N numbers";
}

// The pattern table of `spec`, expanded to `beads` values, or nullopt (noted).
std::optional<std::vector<double>> read_pattern(const SceneReader& r, const toml::table& table,
                                                const CoefficientKey& spec, int beads,
                                                bool beads_ok, const Conversion& c) {
  const std::string name = "chain." + std::string(spec.key);
  bool bad = false;
  auto fail = [&](const toml::source_region& at, const std::string& what) {
    r.fail_at(name, at, what);
    bad = true;
  };
  for (auto&& [k, v] : table)
    if (std::find(kPatternKeys.begin(), kPatternKeys.end(), k.str()) == kPatternKeys.end())
      fail(k.source(), "unknown key '" + std::string(k.str()) + "' in the " + name + " pattern; " +
                           suggest(k.str(), {kPatternKeys.begin(), kPatternKeys.end()}));
  // A number of the pattern, converted to Eq. (dimless) form.
  auto number = [&](std::string_view key) -> std::optional<double> {
    const toml::node* n = table.get(key);
    if (!n) return std::nullopt;
    std::optional<double> v;
    if (auto i = n->value_exact<std::int64_t>()) v = static_cast<double>(*i);
    if (auto f = n->value_exact<double>(); f && std::isfinite(*f)) v = *f;
    if (!v) {
      fail(n->source(), name + "." + std::string(key) + " must be a finite number; " + forms(spec));
      return std::nullopt;
    }
    return spec.convert(c, *v);
  };
  // A bead or spring number 1..N.
  auto index = [&](std::string_view key, int fallback) -> int {
    const toml::node* n = table.get(key);
    if (!n) return fallback;
    const auto i = n->value_exact<std::int64_t>();
    if (!i) {
      fail(n->source(), name + "." + std::string(key) + " must be a " + std::string(spec.element) +
                            " number (an integer 1..N); " + forms(spec));
    } else if (beads_ok && (*i < 1 || *i > beads)) {
      fail(n->source(), name + "." + std::string(key) + " = " + std::to_string(*i) + " is not a " +
                            std::string(spec.element) + " of this chain (1.." +
                            std::to_string(beads) + "); give a " + std::string(spec.element) +
                            " number from 1 to N = " + std::to_string(beads));
    } else {
      return static_cast<int>(*i);
    }
    return fallback;
  };

  const auto base = number("base"), value = number("value");
  const auto from_value = number("from_value"), to_value = number("to_value");
  const bool has_at = table.contains("at"),
             has_range = table.contains("from") || table.contains("to");
  const int at = index("at", 1), from = index("from", 1), to = index("to", beads);
  const auto& where = table.source();
  if (bad) return std::nullopt;

  const bool gradient = table.contains("from_value") || table.contains("to_value");
  if (gradient) {
    if (table.contains("value") || table.contains("base") || has_at || has_range)
      fail(where, "a linear " + name + " { from_value, to_value } runs from " +
                      std::string(spec.element) +
                      " 1 to N and takes no other keys; use a segment " +
                      "{ value, from, to } over a base, or an array, for anything else");
    else if (!from_value || !to_value)
      fail(where, "a linear " + name + " needs both from_value (" + std::string(spec.element) +
                      " 1) and to_value (" + std::string(spec.element) +
                      " N), e.g. { from_value = 1.0, to_value = 2.0 }");
  } else if (!table.contains("value")) {
    fail(where, "the " + name +
                    " pattern needs value (with at or from/to) or from_value and "
                    "to_value; " +
                    forms(spec));
  } else if (has_at && has_range) {
    fail(where, "give " + name + " either at (one " + std::string(spec.element) +
                    ") or from/to (a segment), not both");
  } else if (!base && !spec.base) {
    fail(where, "the " + name +
                    " pattern needs base, the threshold of every other spring, "
                    "e.g. threshold = { base = 1.0, value = 0.5, at = 15 }");
  } else if (has_range && from > to) {
    fail(where, name + " from = " + std::to_string(from) + " is after to = " + std::to_string(to) +
                    "; give from <= to");
  }
  if (bad || !beads_ok) return std::nullopt;  // a wrong N is validate()'s to report
  if (beads > kMaxCoefficientBeads) {
    fail(where, "a " + name + " pattern needs N <= " + std::to_string(kMaxCoefficientBeads) +
                    " beads, got N = " + std::to_string(beads) + "; use fewer beads");
    return std::nullopt;
  }

  std::vector<double> out(static_cast<std::size_t>(beads));
  if (gradient) {
    for (int j = 1; j <= beads; ++j) out[j - 1] = gradient_value(*from_value, *to_value, j, beads);
    return out;
  }
  std::fill(out.begin(), out.end(), base ? *base : spec.convert(c, *spec.base));
  const int first = has_at ? at : from, last = has_at ? at : to;
  std::fill(out.begin() + (first - 1), out.begin() + last, *value);
  return out;
}

}  // namespace

std::string length_problem(std::string_view key, std::string_view element, std::size_t got,
                           int beads) {
  const std::string k(key), e(element);
  return "chain." + k + " has " + std::to_string(got) + " value" + (got == 1 ? "" : "s") +
         " but the chain has N = " + std::to_string(beads) + " " + e + "s; give one per " + e +
         " 1..N, or a pattern such as " + k + " = { " + (k == "threshold" ? "base = 1.0, " : "") +
         "value = " + (k == "threshold" ? "0.5" : "4.0") + ", at = 15 }";
}

double gradient_value(double a, double b, int j, int n) {
  if (n <= 1) return a;
  // (1 - t) a + t b is exact at both ends (t = 0 and t = 1), so bead N gets b itself.
  const double t = static_cast<double>(j - 1) / static_cast<double>(n - 1);
  return (1.0 - t) * a + t * b;
}

std::optional<Coefficients> read_coefficients(const SceneReader& r, const CoefficientKey& spec,
                                              int beads, bool beads_ok, const Conversion& c) {
  const toml::node* n = r.node("chain", spec.key);
  if (!n) return std::nullopt;
  const std::string name = "chain." + std::string(spec.key);
  Coefficients out;
  if (n->is_number()) {
    const auto v = r.number("chain", spec.key);
    if (!v) return std::nullopt;
    const double value = spec.convert(c, *v);
    if (!spec.base) {  // a threshold: one value, as the paper's chain has
      out.scalar = value;
      return out;
    }
    if (value == *spec.base) return out;  // the uniform chain: no array
    if (!beads_ok) return std::nullopt;
    if (beads > kMaxCoefficientBeads) {
      r.fail("chain", spec.key,
             name + " other than " + format_exact(*spec.base) +
                 " needs N <= " + std::to_string(kMaxCoefficientBeads) +
                 " beads, got N = " + std::to_string(beads) + "; use fewer beads");
      return std::nullopt;
    }
    out.values.assign(static_cast<std::size_t>(beads), value);
    return out;
  }
  if (n->is_array()) {
    auto values = r.numbers("chain", spec.key);
    if (!values) return std::nullopt;
    if (values->empty()) {  // would read as the uniform chain: say so instead
      r.fail("chain", spec.key, length_problem(spec.key, spec.element, 0, beads));
      return std::nullopt;
    }
    for (double& v : *values) v = spec.convert(c, v);
    out.values = std::move(*values);
    return out;
  }
  if (const toml::table* table = n->as_table()) {
    auto values = read_pattern(r, *table, spec, beads, beads_ok, c);
    if (!values) return std::nullopt;
    out.values = std::move(*values);
    return out;
  }
  r.fail_type(
      "chain", spec.key, *n,
      "a number, an array of N numbers or a pattern table such as { value = 0.5, at = 15 }");
  return std::nullopt;
}

std::string coefficients_text(const std::vector<double>& values, std::optional<double> default_base,
                              std::string (*number)(double)) {
  const std::size_t n = values.size();
  if (n == 0) return "[]";
  auto all_equal = [&](std::size_t i, std::size_t k, double v) {
    return std::all_of(values.begin() + i, values.begin() + k + 1,
                       [v](double x) { return x == v; });
  };
  if (all_equal(0, n - 1, values[0])) return number(values[0]);
  // One run of one value over a base: a defect (at) or a segment (from, to). The base is
  // the last value or the first; the shorter text wins ([1, 1, 4] is { value = 4.0, at = 3 }).
  std::string run;
  for (const double base : {values[n - 1], values[0]}) {
    std::size_t i = 0, k = n - 1;
    while (values[i] == base) ++i;
    while (values[k] == base) --k;
    if (!all_equal(i, k, values[i])) continue;
    std::string out = "{ ";
    if (!default_base || *default_base != base) out += "base = " + number(base) + ", ";
    out += "value = " + number(values[i]);
    if (i == k) {
      out += ", at = " + std::to_string(i + 1);
    } else {
      if (i != 0) out += ", from = " + std::to_string(i + 1);
      if (k != n - 1) out += ", to = " + std::to_string(k + 1);
    }
    out += " }";
    if (run.empty() || out.size() < run.size()) run = out;
  }
  if (!run.empty()) return run;
  const int count = static_cast<int>(n);
  bool linear = true;
  for (int j = 1; j <= count && linear; ++j)
    linear = values[j - 1] == gradient_value(values[0], values[n - 1], j, count);
  if (linear)
    return "{ from_value = " + number(values[0]) + ", to_value = " + number(values[n - 1]) + " }";
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) out += (i ? ", " : "") + number(values[i]);
  return out + "]";
}

}  // namespace cb::scene_detail
