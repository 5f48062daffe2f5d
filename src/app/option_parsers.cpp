#include "app/option_parsers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "scene/scene.h"
#include "strings/split.h"

namespace cb {

namespace {

bool parse_int(std::string_view text, int& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

}  // namespace

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
