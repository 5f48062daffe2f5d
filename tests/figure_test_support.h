// Shared by the figure tests: each figure built once per test run (the RK4 maps take a
// second), and a series looked up by its legend label or failed.
#pragma once

#include <catch2/catch.hpp>
#include <map>
#include <string>

#include "figures/figure_specs.h"

namespace cb::test {

inline const Figure& built_figure(const std::string& name) {
  static std::map<std::string, Figure> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  for (const FigureEntry& e : figure_entries())
    if (e.name == name) return cache.emplace(name, e.build(FigureOptions{})).first->second;
  FAIL("no figure " << name);
  return cache[name];  // not reached: FAIL throws
}

inline const Series& series_of(const Figure& f, const std::string& label, std::size_t panel = 0) {
  REQUIRE(panel < f.panels.size());
  const Series* s = find_series(f.panels[panel], label);
  INFO(f.name << ": series '" << label << "'");
  REQUIRE(s != nullptr);
  return *s;
}

}  // namespace cb::test
