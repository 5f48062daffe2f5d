// Which inputs made an output: FNV-1a over the scene file's bytes and the --set overrides,
// as 16 hex digits. Recorded in render sidecars and sweep records; `merge` compares them.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace cb {

std::string scene_hash(const std::string& scene_path, const std::vector<Override>& overrides);

}  // namespace cb
