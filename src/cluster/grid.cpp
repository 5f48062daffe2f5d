#include "cluster/grid.h"

#include <charconv>
#include <cmath>

#include "resources/resources.h"  // kMaxSweepValues
#include "strings/split.h"

namespace cb {

namespace {

bool parse_double(std::string_view text, double& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(out);
}

// "KEY=REST" -> key and rest, or GridError with `usage`.
std::pair<std::string, std::string_view> split_key(const std::string& text,
                                                   const std::string& usage) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) throw GridError(usage);
  return {text.substr(0, eq), std::string_view(text).substr(eq + 1)};
}

std::string number_text_of(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return std::string(buf, r.ptr);
}

}  // namespace

std::size_t Grid::size() const {
  if (axes.empty()) return 0;
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<double> Grid::point(std::size_t index) const {
  std::vector<double> p;
  point_into(index, p);
  return p;
}

void Grid::point_into(std::size_t index, std::vector<double>& values) const {
  values.resize(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {  // last axis fastest
    const std::size_t n = axes[k].values.size();
    values[k] = axes[k].values[index % n];
    index /= n;
  }
}

std::size_t Grid::index_on(std::size_t index, const std::vector<bool>& kept) const {
  std::size_t on = 0, stride = 1;
  for (std::size_t k = axes.size(); k-- > 0;) {  // as point(): last axis fastest
    const std::size_t n = axes[k].values.size();
    if (kept[k]) {
      on += index % n * stride;
      stride *= n;
    }
    index /= n;
  }
  return on;
}

std::string Grid::csv_header() const {
  if (axes.size() == 1) return "value,spring,tau";
  std::string h;
  for (const auto& a : axes) h += a.key + ",";
  return h + "spring,tau";
}

bool whole_number_key(const std::string& key) {
  return key == "chain.seed" || key == "chain.beads" || key == "render.width" ||
         key == "render.height";
}

GridAxis parse_vary(const std::string& text) {
  const std::string spec = "--vary " + text;
  const std::string usage =
      spec + ": expected KEY=LO:HI:COUNT[:log], e.g. --vary chain.threshold=1:300:420";
  const auto [key, rest] = split_key(text, usage);
  const auto parts = split(rest, ':');
  double lo = 0, hi = 0, count = 0;
  if (parts.size() < 3 || parts.size() > 4 || !parse_double(parts[0], lo) ||
      !parse_double(parts[1], hi) || !parse_double(parts[2], count) ||
      (parts.size() == 4 && parts[3] != "log"))
    throw GridError(usage);
  // Checked as a double, before it becomes an integer (1e12 would overflow an int).
  if (count > kMaxSweepValues)
    throw GridError(spec + ": COUNT = " + std::string(parts[2]) +
                    " values is more than the limit of " + std::to_string(kMaxSweepValues) +
                    "; use fewer values, or split the range over several sweeps (--shard)");
  if (count < 1 || count != std::floor(count))
    throw GridError(spec + ": COUNT must be a whole number of values, at least 1 (got " +
                    std::string(parts[2]) + "); e.g. " + key + "=" + std::string(parts[0]) + ":" +
                    std::string(parts[1]) + ":10");
  const bool log = parts.size() == 4;
  if (log && (lo <= 0 || hi <= 0))
    throw GridError(spec +
                    ": a :log axis needs LO and HI above zero (the values are spaced "
                    "geometrically); drop :log for a linear axis, or start above zero, e.g. " +
                    key + "=0.001:" + std::string(parts[1]) + ":" + std::string(parts[2]) + ":log");
  GridAxis axis{key, {}, spec};
  const auto n = static_cast<std::size_t>(count);
  axis.values.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (n == 1) {
      axis.values.push_back(lo);
      break;
    }
    // The ends are LO and HI exactly, not exp(log(LO)) or LO + (n-1) * step rounded.
    const double w = static_cast<double>(i) / static_cast<double>(n - 1);
    axis.values.push_back(i == 0       ? lo
                          : i + 1 == n ? hi
                          : log        ? std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo)))
                                       : lo + w * (hi - lo));
  }
  if (whole_number_key(key)) {
    for (double& v : axis.values) v = std::round(v);
    for (std::size_t i = 1; i < axis.values.size(); ++i)
      if (axis.values[i] == axis.values[i - 1])
        throw GridError(spec + ": " + key + " takes whole numbers, and " + std::string(parts[0]) +
                        ":" + std::string(parts[1]) + " holds fewer than " + std::string(parts[2]) +
                        " of them (" + number_text_of(axis.values[i]) +
                        " twice); use a wider range or a smaller COUNT");
  }
  return axis;
}

GridAxis parse_values(const std::string& text) {
  const std::string spec = "--values " + text;
  const std::string usage =
      spec + ": expected KEY=V1,V2,..., e.g. --values drive.beta=0.01,0.02,0.05";
  const auto [key, rest] = split_key(text, usage);
  GridAxis axis{key, {}, spec};
  for (const auto part : split(rest, ',')) {
    double v = 0;
    if (!parse_double(part, v))
      throw GridError(spec + ": '" + std::string(part) + "' is not a number; " +
                      usage.substr(spec.size() + 2));
    axis.values.push_back(v);
  }
  return axis;
}

void add_axis(Grid& grid, GridAxis axis) {
  for (const auto& a : grid.axes)
    if (a.key == axis.key)
      throw GridError(axis.spec + ": " + axis.key + " is already varied by " + a.spec +
                      "; vary each key once (list all its values in one --values " + axis.key +
                      "=V1,V2,...)");
  grid.axes.push_back(std::move(axis));
}

void check_grid_size(const Grid& grid, std::size_t limit) {
  std::size_t n = 1;
  std::string specs;
  for (const auto& a : grid.axes) {
    specs += (specs.empty() ? "" : " ") + a.spec;
    if (a.values.size() > limit / n)
      throw GridError(specs + ": the grid has more than " + std::to_string(limit) +
                      " points; use fewer values per axis");
    n *= a.values.size();
  }
}

}  // namespace cb
