// chainbreak.sweep: which spring breaks first over a grid of scene values, by the per-value
// work of `chainbreak sweep` (app/sweep_values.h).
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "app/csv.h"
#include "app/sweep_values.h"
#include "cluster/grid.h"
#include "interruptible.h"
#include "py_common.h"
#include "resources/resources.h"  // kMaxSweepValues

namespace cb::py_detail {

namespace {

using Values = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::dict sweep(const Scene& source, const py::dict& vary, const std::string& solver_name,
               int jobs) {
  if (vary.empty())
    throw SceneError("sweep: vary is empty; give e.g. vary={'drive.beta': numpy.linspace(...)}");
  // The grid is `chainbreak sweep`'s (cluster/grid.h): the cartesian product of the keys'
  // values, the first key varying slowest (numpy's meshgrid(..., indexing="ij") flattened).
  Grid grid;
  for (const auto& [key, values] : vary) {
    const std::string name = py::str(key).cast<std::string>();
    const Values array = Values::ensure(values);
    if (!array || array.ndim() > 1 || array.size() == 0)
      throw SceneError("sweep: vary['" + name + "'] must be a non-empty 1-D sequence of numbers");
    add_axis(grid, {name, {array.data(), array.data() + array.size()}, "vary['" + name + "']"});
  }
  check_grid_size(grid, static_cast<std::size_t>(kMaxSweepValues));
  const Solver solver = parse_solver(solver_name);
  // Every point is set in memory on the scene read once, and checked before any work: a bad
  // value fails now, named by its key and value.
  const SweepPoints points = sweep_points(
      source.variations(), grid, {0, grid.size()}, solver, jobs,
      [](const GridAxis& axis, double v) { return axis.spec + " = " + number_text(v); });
  const std::vector<FirstBreak> breaks =
      interruptible([&] { return sweep_first_breaks(points, solver, jobs, &g_interrupted, {}); });
  if (g_interrupted) {  // stopped from elsewhere (another call saw Ctrl-C)
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  const auto n = static_cast<py::ssize_t>(grid.size());
  py::dict out;
  for (std::size_t k = 0; k < grid.axes.size(); ++k) {
    std::vector<double> column(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) column[i] = grid.point(i)[k];
    out[py::str(grid.axes[k].key)] = to_numpy(std::move(column), {n});
  }
  std::vector<std::int64_t> spring(grid.size(), -1);
  std::vector<double> tau(grid.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < breaks.size(); ++i)
    if (breaks[i].broke) {
      spring[i] = breaks[i].spring;
      tau[i] = breaks[i].tau;
    }
  out["spring"] = to_numpy(std::move(spring), {n});
  out["tau"] = to_numpy(std::move(tau), {n});
  return out;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("scene"), py::arg("vary"), py::arg("solver") = "rk4",
        py::arg("jobs") = 0,
        "The first break over a grid, like `chainbreak sweep`: vary={'drive.beta': values, ...} "
        "(several keys: their cartesian product, the first key slowest). Returns a dict of "
        "arrays: one column per key, 'spring' (0 = the pull string, -1 = nothing broke by "
        "t_end) and 'tau' (NaN when nothing broke). solver 'rk4' or 'exact'; jobs threads "
        "(0: all cores). Releases the GIL; Ctrl-C raises KeyboardInterrupt.");
}

}  // namespace cb::py_detail
