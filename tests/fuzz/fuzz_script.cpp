// The viewer's --script language (parse_script), then a ScriptPlayer walking it.
// Invariants: frames never decrease, every action is handed out exactly once.
#include "fuzz_support.h"
#include "scene/scene.h"
#include "viewer/script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<cb::ScriptAction> actions;
  try {
    actions = cb::parse_script(cb::fuzz::text_of(data, size), "fuzz.script");
  } catch (const cb::SceneError&) {
    return 0;
  }
  for (std::size_t i = 1; i < actions.size(); ++i)
    FUZZ_CHECK(actions[i].frame >= actions[i - 1].frame);
  const std::size_t count = actions.size();
  cb::ScriptPlayer player(actions);
  std::size_t handed = 0;
  for (std::size_t i = 0; i < count; ++i) handed += player.take(actions[i].frame).size();
  FUZZ_CHECK(handed == count && player.finished());
  return 0;
}
