// `--set KEY=VALUE` overrides (parse_override, then SceneReader::apply through parse_scene):
// each line of the input is one --set on a valid base scene.
#include <vector>

#include "fuzz_support.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = cb::fuzz::text_of(data, size);
  std::vector<cb::Override> overrides;
  try {
    for (std::size_t start = 0; start <= text.size();) {
      const auto end = std::min(text.find('\n', start), text.size());
      overrides.push_back(cb::parse_override(text.substr(start, end - start)));
      start = end + 1;
    }
    const cb::SceneDesc scene = cb::parse_scene(cb::fuzz::kBaseScene, "base.toml", overrides);
    FUZZ_CHECK(scene.chain.beads >= 1 && scene.integrator.dt > 0);
  } catch (const cb::SceneError&) {
  } catch (const cb::DriveError&) {
  }
  return 0;
}
