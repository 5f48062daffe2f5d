// The problems of one scene in file order (scene_problems.h).
#include "scene/scene_problems.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <utility>

#include "scene/scene.h"

namespace cb::scene_detail {

namespace {

// "path:12:5" -> (12, 5); anything else (a --set, an in-memory scene) -> (LONG_MAX, 0), after
// every position of the file. The path itself may contain colons, so read from the right.
std::pair<long, long> order_of(const std::string& where) {
  const std::pair<long, long> after_file{LONG_MAX, 0};
  if (where.rfind("--set ", 0) == 0) return after_file;
  auto number_before = [&](std::size_t end, std::size_t& start) -> long {
    start = end;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(where[start - 1]))) --start;
    if (start == end || end - start > 9) return -1;
    return std::stol(where.substr(start, end - start));
  };
  std::size_t col_start = 0, line_start = 0;
  const long column = number_before(where.size(), col_start);
  if (column < 0 || col_start == 0 || where[col_start - 1] != ':') return after_file;
  const long line = number_before(col_start - 1, line_start);
  if (line < 0 || line_start == 0 || where[line_start - 1] != ':') return after_file;
  return {line, column};
}

}  // namespace

void Problems::add(std::string_view key, const std::string& where, const std::string& what) {
  if (failed(key)) return;
  if (!key.empty()) failed_.emplace(key);
  problems_.push_back({where, what});
}

bool Problems::failed(std::string_view key) const {
  if (key.empty()) return false;
  if (failed_.count(key)) return true;
  const auto dot = key.find('.');
  return dot != std::string_view::npos && failed_.count(key.substr(0, dot));
}

std::vector<std::string> Problems::messages() const {
  std::vector<std::size_t> order(problems_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return order_of(problems_[a].where) < order_of(problems_[b].where);
  });
  std::vector<std::string> out;
  for (std::size_t i : order) {
    const Problem& p = problems_[i];
    out.push_back(p.where.empty() ? p.what : p.where + ": " + p.what);
  }
  return out;
}

void Problems::throw_if_any() const {
  if (!problems_.empty()) throw SceneError(messages());
}

}  // namespace cb::scene_detail
