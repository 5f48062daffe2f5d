// Typed, position-aware reads of a scene table and the --set overrides (see scene_reader.h).
//
// Index: the schema table; names and suggestions; number formatting; SceneReader (positions,
// overrides, unknown keys, typed reads).
#include "scene/scene_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "scene/toml_guard.h"

namespace cb::scene_detail {

// ---- The schema: every key a scene may contain (documented in scene.cpp) -----------------

namespace {

constexpr std::array<std::string_view, 5> kSections = {"chain", "drive", "integrator", "units",
                                                       "render"};

constexpr KeySpec kSchema[] = {
    {"", "title", Kind::String, "title = \"Anomalous breaking\""},
    {"chain", "beads", Kind::Integer, "beads = 30"},
    {"chain", "gamma", Kind::Number, "gamma = 0.0"},
    {"chain", "threshold", Kind::Coefficients, "threshold = 1.0"},
    {"chain", "mass", Kind::Coefficients, "mass = { value = 4.0, at = 15 }"},
    {"chain", "stiffness", Kind::Coefficients, "stiffness = { value = 4.0, from = 1, to = 15 }"},
    {"chain", "threshold_dist", Kind::String, "threshold_dist = \"weibull\""},
    {"chain", "threshold_shape", Kind::Number, "threshold_shape = 6.0"},
    {"chain", "seed", Kind::Integer, "seed = 1"},
    {"chain", "break_on", Kind::String, "break_on = \"abs\""},
    {"chain", "pull_string", Kind::Bool, "pull_string = false"},
    {"chain", "gravity", Kind::Number, "gravity = 0.1"},
    {"chain", "fput_alpha", Kind::Number, "fput_alpha = 0.0"},
    {"chain", "fput_beta", Kind::Number, "fput_beta = 0.5"},
    {"drive", "type", Kind::String, "type = \"ramp\""},
    {"drive", "beta", Kind::Number, "beta = 0.02"},
    {"drive", "amplitude", Kind::Number, "amplitude = 1.0"},
    {"drive", "period", Kind::Number, "period = 120.0"},
    {"drive", "times", Kind::NumberArray, "times = [0.0, 30.0]"},
    {"drive", "strengths", Kind::NumberArray, "strengths = [1.0, 1.0]"},
    {"drive", "file", Kind::String, "file = \"data/smooth_pull.csv\""},
    {"drive", "points", Kind::NumberArray, "points = [0.0, 0.0, 50.0, 1.0]"},
    {"drive", "expr", Kind::String, "expr = \"0.02*t\""},
    {"drive", "t0", Kind::Number, "t0 = 0.0"},
    {"integrator", "dt", Kind::Number, "dt = 0.01"},
    {"integrator", "t_end", Kind::Number, "t_end = 400.0"},
    {"integrator", "after_break", Kind::Number, "after_break = 20.0"},
    {"units", "mass", Kind::Number, "mass = 0.05"},
    {"units", "stiffness", Kind::Number, "stiffness = 200.0"},
    {"units", "length", Kind::Number, "length = 0.01"},
    {"units", "friction", Kind::Number, "friction = 0.0"},
    {"units", "input", Kind::String, "input = \"si\""},
    {"render", "width", Kind::Integer, "width = 1280"},
    {"render", "height", Kind::Integer, "height = 720"},
    {"render", "fps", Kind::Number, "fps = 30"},
    {"render", "speed", Kind::Number, "speed = 10.0"},
    {"render", "view", Kind::String, "view = \"longitudinal\""},
    {"render", "theme", Kind::String, "theme = \"dark\""},
    {"render", "slowmo", Kind::Number, "slowmo = 0.1"},
    {"render", "slowmo_window", Kind::Number, "slowmo_window = 2.0"},
    {"render", "zoom", Kind::String, "zoom = \"auto\""},
    {"render", "caption", Kind::String, "caption = \"A slow pull breaks the pulled end\""},
    {"render", "title_card", Kind::Number, "title_card = 3.0"},
    {"render", "overlay", Kind::Bool, "overlay = true"},
    {"render", "overlay_hud", Kind::Bool, "overlay_hud = true"},
    {"render", "overlay_plots", Kind::Bool, "overlay_plots = true"},
    {"render", "overlay_spacetime", Kind::Bool, "overlay_spacetime = true"},
    {"render", "overlay_modes", Kind::Bool, "overlay_modes = true"},
};

bool is_section(std::string_view name) {
  return std::find(kSections.begin(), kSections.end(), name) != kSections.end();
}

std::vector<std::string_view> keys_of(std::string_view section) {
  std::vector<std::string_view> keys;
  for (const KeySpec& k : kSchema)
    if (k.section == section) keys.push_back(k.key);
  return keys;
}

// The section a misplaced key belongs to ("dt" written under [chain]), or "".
std::string_view home_of(std::string_view key) {
  for (const KeySpec& k : kSchema)
    if (k.key == key && !k.section.empty()) return k.section;
  return {};
}

// Optimal string alignment distance (Levenshtein plus adjacent swaps, "gmama" -> "gamma"),
// case-insensitive because "Gamma" is as much a typo as "gama".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  auto low = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Integer:
      return "an integer";
    case Kind::Number:
      return "a number";
    case Kind::Bool:
      return "true or false";
    case Kind::String:
      return "a string";
    case Kind::NumberArray:
      return "an array of numbers";
    case Kind::Coefficients:
      return "a number, an array of numbers or a pattern table";
  }
  return "a value";
}

// "3.5 (a floating-point number)": what the user actually wrote, for type errors.
std::string describe(const toml::node& n) {
  std::ostringstream text;
  if (auto s = n.value_exact<std::string>()) {
    text << '"' << *s << "\" (a string)";
  } else if (auto i = n.value_exact<std::int64_t>()) {
    text << *i << " (an integer)";
  } else if (auto f = n.value_exact<double>()) {
    text << format_exact(*f) << " (a floating-point number)";
  } else if (auto b = n.value_exact<bool>()) {
    text << (*b ? "true" : "false") << " (a boolean)";
  } else if (n.is_array()) {
    text << "an array";
  } else if (n.is_table()) {
    text << "a table";
  } else {
    text << "a " << n.type() << " value";
  }
  return text.str();
}

}  // namespace

std::string dotted(std::string_view section, std::string_view key) {
  return section.empty() ? std::string(key) : std::string(section) + "." + std::string(key);
}

const KeySpec* find_key_spec(std::string_view section, std::string_view key) {
  for (const KeySpec& k : kSchema)
    if (k.section == section && k.key == key) return &k;
  return nullptr;
}

std::string suggest(std::string_view unknown, const std::vector<std::string_view>& valid,
                    std::string_view quote_open, std::string_view quote_close) {
  std::string list;
  std::string_view best;
  std::size_t best_distance = SIZE_MAX;
  for (std::string_view v : valid) {
    list += (list.empty() ? "" : ", ") + std::string(quote_open) + std::string(v) +
            std::string(quote_close);
    const std::size_t d = edit_distance(unknown, v);
    if (d < best_distance) {
      best_distance = d;
      best = v;
    }
  }
  // Only suggest what is plausibly a typo; otherwise the list is the better hint.
  const std::size_t n = unknown.size();
  const std::size_t allowed = n <= 3 ? 1 : n <= 8 ? 2 : 3;
  if (best_distance <= allowed)
    return "did you mean " + std::string(quote_open) + std::string(best) +
           std::string(quote_close) + "? (valid: " + list + ")";
  return "valid names are " + list;
}

std::string format_exact(double v) {
  std::array<char, 64> buf{};
  auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return ec == std::errc() ? std::string(buf.data(), end) : std::to_string(v);
}

std::string format_approx(double v) {
  std::array<char, 64> buf{};
  std::snprintf(buf.data(), buf.size(), "%.4g", v);
  return buf.data();
}

// ---- SceneReader --------------------------------------------------------------------------

SceneReader::SceneReader(std::string path, toml::table root)
    : path_(std::move(path)), root_(std::move(root)) {}

std::string SceneReader::position(const toml::source_region& region) const {
  return path_ + ":" + std::to_string(region.begin.line) + ":" +
         std::to_string(region.begin.column);
}

const toml::node* SceneReader::node(std::string_view section, std::string_view key) const {
  if (section.empty()) return root_.get(key);
  const toml::table* table = root_.get_as<toml::table>(section);
  return table ? table->get(key) : nullptr;
}

std::string SceneReader::where(std::string_view section, std::string_view key) const {
  if (auto it = origin_.find(dotted(section, key)); it != origin_.end()) return it->second;
  if (const toml::node* n = node(section, key); n && n->source().begin.line > 0)
    return position(n->source());
  return section_where(section);
}

// Where a missing key of `section` would go: its table, which may itself come from an
// override, or the top of the file.
std::string SceneReader::section_where(std::string_view section) const {
  if (const toml::node* table = section.empty() ? &root_ : root_.get(section)) {
    if (table->source().begin.line > 0) return position(table->source());
    for (const auto& [name, text] : origin_)
      if (name.rfind(std::string(section) + ".", 0) == 0) return text;
  }
  return path_ + ":1:1";
}

KeyOrigins SceneReader::origins() const {
  KeyOrigins::Map out;
  out[""] = path_ + ":1:1";
  for (std::string_view section : kSections) out[std::string(section)] = section_where(section);
  for (const KeySpec& k : kSchema)
    if (has(k.section, k.key)) out[dotted(k.section, k.key)] = where(k.section, k.key);
  return KeyOrigins(std::move(out));
}

void SceneReader::fail(std::string_view section, std::string_view key,
                       const std::string& what) const {
  problems_.add(dotted(section, key), where(section, key), what);
}

void SceneReader::fail_at(std::string_view key, const toml::source_region& at,
                          const std::string& what) const {
  // A value from --set has no position of its own: name the override.
  const auto origin = origin_.find(key);
  problems_.add(key, origin != origin_.end() ? origin->second : position(at), what);
}

bool SceneReader::failed(std::string_view section, std::string_view key) const {
  return problems_.failed(key.empty() ? std::string(section) : dotted(section, key));
}

void SceneReader::fail_missing(std::string_view section, std::string_view key,
                               const std::string& why) const {
  if (has(section, key) || failed(section)) return;  // present but wrong: noted already
  const KeySpec* spec = find_key_spec(section, key);
  std::string what = "missing key '" + std::string(key) + "' in [" + std::string(section) + "]";
  if (!why.empty()) what += " " + why;
  what += "; add e.g. " + std::string(spec ? spec->example : key);
  if (!has_section(section)) what += " under a [" + std::string(section) + "] section";
  fail(section, key, what);
}

void SceneReader::fail_type(std::string_view section, std::string_view key, const toml::node& n,
                            std::string_view wanted) const {
  const KeySpec* spec = find_key_spec(section, key);
  std::string hint = "write e.g. " + std::string(spec ? spec->example : key);
  if (n.is_string() && wanted != "a string") hint += " (without quotes)";
  if (wanted == "a string") hint += " (strings need double quotes)";
  fail(section, key,
       dotted(section, key) + " must be " + std::string(wanted) + ", got " + describe(n) + "; " +
           hint);
}

void SceneReader::apply(const Override& o) {
  const std::string text = "--set " + o.key + "=" + o.value;
  // Each refused override is one problem; the file is still read for its own.
  struct Refused {};
  auto fail_here = [&](const std::string& what) {
    problems_.add({}, text, what);
    throw Refused{};
  };
  try {
    apply_checked(o, text, fail_here);
  } catch (const Refused&) {
  }
}

template <class Fail>
void SceneReader::apply_checked(const Override& o, const std::string& text, Fail&& fail_here) {
  const std::size_t dot = o.key.find('.');
  const std::string section = dot == std::string::npos ? "" : o.key.substr(0, dot);
  const std::string key = dot == std::string::npos ? o.key : o.key.substr(dot + 1);
  if (section.empty() && is_section(key))
    fail_here("[" + key + "] is a section; set one of its keys, e.g. --set " + key + "." +
              std::string(keys_of(key).front()) + "=...");
  if (!section.empty() && !is_section(section))
    fail_here("unknown section [" + section + "]; " +
              suggest(section, {kSections.begin(), kSections.end()}, "[", "]"));
  const KeySpec* spec = find_key_spec(section, key);
  if (!spec) {
    const std::string_view home = home_of(key);
    if (section.empty() && !home.empty())
      fail_here("'" + key + "' belongs in [" + std::string(home) + "]; write --set " +
                std::string(home) + "." + key + "=" + o.value);
    fail_here("unknown key '" + key + "'" + (section.empty() ? "" : " in [" + section + "]") +
              "; " + suggest(key, keys_of(section)));
  }

  // The value is TOML when it parses as one ("0.01", "true", "[0, 30]", "\"ramp\""); a bare
  // word such as `step` is not, and is taken as a string. String keys always take the text
  // itself unless it is quoted, so drive.expr=1 means the expression "1".
  std::optional<toml::table> parsed;
  try {
    const std::string text = "v = " + o.value;
    check_toml_text(text, "--set");  // what toml++ cannot read safely is not TOML either
    parsed = toml::parse(text, std::string_view("--set"));
  } catch (const toml::parse_error&) {
    parsed.reset();
  } catch (const SceneError&) {
    parsed.reset();
  }
  const toml::node* value = parsed && parsed->size() == 1 ? parsed->get("v") : nullptr;
  const bool as_text = !value || (spec->kind == Kind::String && !value->is_string());

  toml::table* table = &root_;
  if (!section.empty()) {
    if (!root_.contains(section)) root_.insert(section, toml::table{});
    table = root_.get_as<toml::table>(section);
    if (!table) {
      problems_.add(
          section, position(root_.get(section)->source()),
          "[" + section + "] must be a table (a [" + section + "] header followed by its keys)");
      return;
    }
  }
  if (as_text)
    table->insert_or_assign(key, o.value);
  else
    value->visit([&](auto&& v) { table->insert_or_assign(key, v); });
  origin_[dotted(section, key)] = text;
}

void SceneReader::check_known_keys() {
  // Every unknown name is noted (sorted into file order with the rest later); a section that
  // is not a table counts as failed, so that its keys are not reported missing as well.
  auto note = [&](const toml::source_region& at, std::string what) {
    problems_.add({}, position(at), what);
  };
  for (auto&& [name, value] : root_) {
    const std::string key(name.str());
    if (find_key_spec("", key)) continue;
    if (is_section(key)) {
      const toml::table* table = value.as_table();
      if (!table) {
        problems_.add(key, position(value.source()),
                      "[" + key + "] must be a table, got " + describe(value) + "; write a [" +
                          key + "] header followed by its keys");
        continue;
      }
      for (auto&& [inner, inner_value] : *table) {
        const std::string k(inner.str());
        if (find_key_spec(key, k)) continue;
        const std::string_view home = home_of(k);
        if (!home.empty())
          note(inner.source(), "key '" + k + "' does not belong in [" + key + "]; move it to [" +
                                   std::string(home) + "]");
        else
          note(inner.source(),
               "unknown key '" + k + "' in [" + key + "]; " + suggest(k, keys_of(key)));
      }
    } else if (value.is_table()) {
      note(name.source(), "unknown section [" + key + "]; " +
                              suggest(key, {kSections.begin(), kSections.end()}, "[", "]"));
    } else if (const std::string_view home = home_of(key); !home.empty()) {
      note(name.source(),
           "key '" + key + "' must be inside a section; move it under [" + std::string(home) + "]");
    } else {
      note(name.source(), "unknown key '" + key + "'; " + suggest(key, keys_of("")) +
                              " (everything else goes in a [section])");
    }
  }
}

bool SceneReader::has_section(std::string_view section) const {
  return section.empty() || root_.get_as<toml::table>(section) != nullptr;
}

bool SceneReader::has(std::string_view section, std::string_view key) const {
  return node(section, key) != nullptr;
}

std::optional<double> SceneReader::number(std::string_view section, std::string_view key) const {
  const toml::node* n = node(section, key);
  if (!n) return std::nullopt;
  if (auto i = n->value_exact<std::int64_t>()) return static_cast<double>(*i);
  const auto f = n->value_exact<double>();
  if (!f) {
    fail_type(section, key, *n, kind_name(Kind::Number));
    return std::nullopt;
  }
  if (!std::isfinite(*f)) {
    fail(section, key,
         dotted(section, key) + " must be a finite number, got " + format_exact(*f) +
             "; write e.g. " + std::string(find_key_spec(section, key)->example));
    return std::nullopt;
  }
  return *f;
}

std::optional<std::int64_t> SceneReader::integer(std::string_view section,
                                                 std::string_view key) const {
  const toml::node* n = node(section, key);
  if (!n) return std::nullopt;
  const auto i = n->value_exact<std::int64_t>();
  if (!i) fail_type(section, key, *n, "an integer (a whole number, no decimal point)");
  return i;
}

std::optional<bool> SceneReader::boolean(std::string_view section, std::string_view key) const {
  const toml::node* n = node(section, key);
  if (!n) return std::nullopt;
  const auto b = n->value_exact<bool>();
  if (!b) fail_type(section, key, *n, kind_name(Kind::Bool));
  return b;
}

std::optional<std::string> SceneReader::string(std::string_view section,
                                               std::string_view key) const {
  const toml::node* n = node(section, key);
  if (!n) return std::nullopt;
  auto s = n->value_exact<std::string>();
  if (!s) fail_type(section, key, *n, kind_name(Kind::String));
  return s;
}

std::optional<std::vector<double>> SceneReader::numbers(std::string_view section,
                                                        std::string_view key) const {
  const toml::node* n = node(section, key);
  if (!n) return std::nullopt;
  const toml::array* array = n->as_array();
  if (!array) {
    fail_type(section, key, *n, kind_name(Kind::NumberArray));
    return std::nullopt;
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& e = *array->get(i);
    std::optional<double> v;
    if (auto k = e.value_exact<std::int64_t>()) v = static_cast<double>(*k);
    if (auto f = e.value_exact<double>(); f && std::isfinite(*f)) v = *f;
    if (!v) {
      fail(section, key,
           dotted(section, key) + "[" + std::to_string(i) + "] must be a finite number, got " +
               describe(e) + "; write e.g. " + std::string(find_key_spec(section, key)->example));
      return std::nullopt;
    }
    out.push_back(*v);
  }
  return out;
}

std::optional<double> SceneReader::require_number(std::string_view section, std::string_view key,
                                                  const std::string& why) const {
  const auto v = number(section, key);
  if (!v) fail_missing(section, key, why);
  return v;
}

std::optional<std::string> SceneReader::require_string(std::string_view section,
                                                       std::string_view key,
                                                       const std::string& why) const {
  auto v = string(section, key);
  if (!v) fail_missing(section, key, why);
  return v;
}

}  // namespace cb::scene_detail
