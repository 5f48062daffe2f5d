// Scene text (parse_scene): TOML syntax (toml++), the schema, units, drives and their checks.
// Invariant: a scene that parses is written back (write_scene) to text that parses to the
// same scene, i.e. writing it again gives the same text (the writer's contract).
#include "fuzz_support.h"
#include "scene/scene.h"
#include "scene/scene_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cb::SceneDesc scene;
  try {
    scene = cb::parse_scene(cb::fuzz::text_of(data, size), "fuzz.toml");
  } catch (const cb::SceneError&) {
    return 0;
  } catch (const cb::DriveError&) {
    return 0;
  }
  FUZZ_CHECK(scene.chain.beads >= 1);
  FUZZ_CHECK(scene.integrator.dt > 0 && scene.integrator.t_end > 0);
  const std::string written = cb::write_scene(scene);
  cb::SceneDesc again;
  try {
    again = cb::parse_scene(written, "fuzz.toml");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_scene wrote a scene parse_scene refuses: %s\n%s\n", e.what(),
                 written.c_str());
    std::abort();
  }
  FUZZ_CHECK(cb::write_scene(again) == written);
  return 0;
}
