// The Python module `chainbreak` (issue #15): the simulator's layers from Python and
// Jupyter. Each binding file wraps one command's producer; nothing is re-implemented here.
//   py_scene.cpp   Scene, SceneError        (src/scene: reader, overrides, validation)
//   py_run.cpp     run, Result              (app/run_rows.h: the CSV's rows)
//   py_exact.cpp   exact, continuum         (src/exact, Eq. (sum))
//   py_sweep.cpp   sweep                    (app/sweep_values.h)
//   py_frames.cpp  snapshot, render         (app/snapshot_images.h, render_scene)
#include "py_common.h"
#include "version.h"

PYBIND11_MODULE(chainbreak, m) {
  namespace d = cb::py_detail;
  m.doc() = "chainbreak: which part of a chain breaks (S. K. Baek), from Python";
  m.attr("__version__") = CHAINBREAK_VERSION;
  m.attr("__commit__") = CHAINBREAK_COMMIT;
  d::bind_scene(m);
  d::bind_run(m);
  d::bind_exact(m);
  d::bind_sweep(m);
  d::bind_frames(m);
}
