// The options with a small language of their own (app/option_parsers.h). The first byte picks
// the option: 0 --vary then --shard ("VARY|SHARD", as sweep uses them), 1 --at, 2 --size.
// Invariants: the results lie in the ranges the messages promise.
#include <cmath>

#include "app/option_parsers.h"
#include "cluster/grid.h"
#include "cluster/shard.h"
#include "fuzz_support.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = cb::fuzz::text_of(data + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        const auto bar = text.find('|');
        // The sweep's own parsers (src/cluster): an axis, then a shard of its points.
        const cb::GridAxis axis = cb::parse_vary(text.substr(0, bar));
        FUZZ_CHECK(!axis.values.empty());
        const cb::Shard shard =
            cb::parse_shard(bar == std::string::npos ? "1/1" : text.substr(bar + 1));
        const cb::PointRange r = cb::shard_points(axis.values.size(), shard);
        FUZZ_CHECK(r.first <= r.last && r.last <= axis.values.size());
        break;
      }
      case 1: {
        const std::vector<double> times = cb::parse_times(text);
        FUZZ_CHECK(!times.empty());
        for (std::size_t i = 0; i < times.size(); ++i) {
          FUZZ_CHECK(std::isfinite(times[i]) && times[i] >= 0);
          if (i > 0) FUZZ_CHECK(times[i] > times[i - 1]);
        }
        break;
      }
      case 2: {
        const auto [w, h] = cb::parse_size(text);
        FUZZ_CHECK(w >= 16 && w <= 16384 && h >= 16 && h <= 16384);
        break;
      }
    }
  } catch (const cb::GridError&) {
  } catch (const cb::SceneError&) {
  }
  return 0;
}
