// Splitting option and grid specs ("800x600", "KEY=LO:HI:N", "a,b,c") into their fields.
#pragma once

#include <string_view>
#include <vector>

namespace cb {

// The fields of `text` between `sep`s, empty ones included: "a,,b" -> {"a", "", "b"},
// "" -> {""}. The views point into `text`.
inline std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const auto end = text.find(sep, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

}  // namespace cb
