#include "app/option_parsers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "scene/scene.h"

namespace cb {

namespace {

bool parse_double(std::string_view text, double& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

bool parse_int(std::string_view text, int& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const auto end = text.find(sep, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

}  // namespace

double Vary::value(int i) const {
  if (count == 1) return lo;
  const double w = static_cast<double>(i) / (count - 1);
  return log ? std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo))) : lo + w * (hi - lo);
}

Vary parse_vary(const std::string& text) {
  const std::string usage =
      "--vary " + text + ": expected KEY=LO:HI:COUNT[:log], e.g. --vary chain.threshold=1:300:420";
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError(usage);
  Vary v;
  v.key = text.substr(0, eq);
  const auto parts = split(std::string_view(text).substr(eq + 1), ':');
  double count = 0;
  if (parts.size() < 3 || parts.size() > 4 || !parse_double(parts[0], v.lo) ||
      !parse_double(parts[1], v.hi) || !parse_double(parts[2], count) || count < 1 ||
      count != std::floor(count) || (parts.size() == 4 && parts[3] != "log"))
    throw SceneError(usage);
  if (count > kMaxSweepValues)
    throw SceneError("--vary " + text + ": COUNT must be 1 to " + std::to_string(kMaxSweepValues) +
                     "; split a larger sweep into several --vary ranges");
  v.count = static_cast<int>(count);
  v.log = parts.size() == 4;
  if (v.log && (v.lo <= 0 || v.hi <= 0))
    throw SceneError("--vary " + text + ": a log sweep needs LO and HI above zero");
  return v;
}

std::pair<int, int> parse_shard(const std::string& text, int count) {
  const auto parts = split(text, '/');
  double i = 0, s = 0;
  if (parts.size() != 2 || !parse_double(parts[0], i) || !parse_double(parts[1], s) || s < 1 ||
      i < 1 || i > s || i != std::floor(i) || s != std::floor(s) || s > kMaxSweepValues)
    throw SceneError("--shard " + text + ": expected I/S with 1 <= I <= S <= " +
                     std::to_string(kMaxSweepValues) + ", e.g. --shard 2/8");
  const long n = count, si = static_cast<long>(s), ii = static_cast<long>(i) - 1;
  return {static_cast<int>(n * ii / si), static_cast<int>(n * (ii + 1) / si)};
}

std::vector<double> parse_times(const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, end - start);
    char* stop = nullptr;
    const double t = std::strtod(part.c_str(), &stop);
    if (part.empty() || *stop != '\0' || !(t >= 0.0) || !std::isfinite(t))
      throw SceneError("--at " + text +
                       ": expected times tau >= 0 separated by commas, e.g. --at 0,30,60.5");
    out.push_back(t);
    start = end + 1;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::pair<int, int> parse_size(const std::string& text) {
  const auto parts = split(text, 'x');
  int w = 0, h = 0;
  if (parts.size() != 2 || !parse_int(parts[0], w) || !parse_int(parts[1], h) || w < 16 || h < 16 ||
      w > 16384 || h > 16384)
    throw SceneError("--size " + text +
                     ": expected WIDTHxHEIGHT in pixels, 16..16384, e.g. 1920x1080");
  return {w, h};
}

}  // namespace cb
