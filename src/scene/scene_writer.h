// Scene files from a SceneDesc: the inverse of parse_scene, so that the viewer's "Save scene"
// writes what the user set up in the same TOML schema (scene.cpp) any command reads.
//
// Design note: a SceneDesc holds dimensionless numbers (an SI scene was converted on load),
// so the file is written with units.input = "dimensionless" and every number in tau and f.
// Numbers are written in their shortest round-trip form, so parse_scene(write_scene(s))
// gives back s exactly (tests/test_scene_writer.cpp).
#pragma once

#include <string>

#include "scene/scene.h"

namespace cb {

// The scene as TOML text. A table drive's file is written as an absolute path (resolved
// against scene.path's folder), so the file may be saved anywhere.
std::string write_scene(const SceneDesc& scene);

}  // namespace cb
