// Internal to src/scene: one reader per section of the schema (documented in scene.cpp).
// Each reads its section (types, missing keys, names) and returns it in the dimensionless
// form of Eq. (dimless); validate() checks the values afterwards.
#pragma once

#include <optional>
#include <string>

#include "drive/drive.h"
#include "physics/chain.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"
#include "scene/scene_units.h"

namespace cb::scene_detail {

std::optional<Units> read_units(const SceneReader& r);
// Also settles chain.gamma against units.friction and fills in the other one.
// `draw`: the drawn thresholds' keys, when chain.threshold_dist gave them.
ChainParams read_chain(const SceneReader& r, std::optional<Units>& units, const Conversion& c,
                       std::optional<ThresholdDraw>& draw);
// scene_dir: where drive.file is looked up when it is a relative path.
DriveDesc read_drive(const SceneReader& r, const Conversion& c, const std::string& scene_dir);
RenderDesc read_render(const SceneReader& r, const ChainParams& chain);
IntegratorDesc read_integrator(const SceneReader& r, const Conversion& c);

// validate()'s checks, adding to `problems` and skipping keys that already have one (their
// values are stand-ins). parse_scene calls it with the reader's problems.
void check_values(const SceneDesc& scene, Problems& problems);

}  // namespace cb::scene_detail
