// What a script's actions do (script.h): the same edits and requests as the controls and the
// keyboard make, so a scripted run exercises the viewer's own paths. No GL.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "viewer/script.h"
#include "viewer/viewer_model.h"

namespace cb {

// Applies one displayed frame's actions: `set` edits the draft scene (the loop applies it,
// restarting the run) or the model; the rest become requests. Throws SceneError for a `set`
// whose value is not a number.
void apply_script(const std::vector<ScriptAction>& actions, SceneDesc& draft, ViewerModel& model,
                  ViewerRequests& requests);

}  // namespace cb
