// chainbreak.run and chainbreak.Result: the rows `chainbreak run` writes as CSV, as numpy
// arrays, from the same producer (app/run_rows.h) and the same RunRow values.
#include <pybind11/stl.h>

#include <cmath>

#include "app/csv.h"
#include "app/h5_run_file.h"
#include "app/run_rows.h"
#include "interruptible.h"
#include "physics/energy.h"
#include "py_common.h"

namespace cb::py_detail {

namespace {

// Rows straight into vectors reserved once; handed to numpy without a copy at the end.
class ArraySink : public RowSink {
 public:
  void begin(int beads, bool with_psi, std::int64_t max_rows) override {
    beads_ = beads;
    with_psi_ = with_psi;
    // Reserve when it is modest (a run that stops at a break keeps fewer rows); beyond
    // that, let the vectors grow.
    constexpr double kReserveLimit = 1u << 30;  // bytes
    const double row_bytes = 8.0 * beads * (with_psi ? 2 : 1) + 40.0;
    if (static_cast<double>(max_rows) * row_bytes <= kReserveLimit) {
      const auto rows = static_cast<std::size_t>(max_rows);
      for (auto* v : {&tau, &f, &energy, &kinetic, &potential}) v->reserve(rows);
      phi.reserve(rows * beads);
      if (with_psi) psi.reserve(rows * beads), psi_dot.reserve(rows * beads);
    }
  }
  void row(const RunRow& r) override {
    tau.push_back(r.tau);
    f.push_back(r.f);
    energy.push_back(r.energy);
    kinetic.push_back(r.kinetic);
    potential.push_back(r.potential);
    phi.insert(phi.end(), r.phi->begin(), r.phi->end());
    if (r.psi) psi.insert(psi.end(), r.psi->begin(), r.psi->end());
    if (r.vel) psi_dot.insert(psi_dot.end(), r.vel->begin(), r.vel->end());
  }
  int beads_ = 0;
  bool with_psi_ = false;
  std::vector<double> tau, f, energy, kinetic, potential, phi, psi, psi_dot;
};

struct Result {
  std::string scene, title, solver;
  int beads = 0;
  double gamma = 0, dt = 0;
  std::optional<double> threshold;
  std::optional<std::vector<double>> thresholds;  // phi_c,j when not all equal (issue #23)
  std::int64_t steps = 0;
  double tau_end = 0;
  py::object tau, f, energy, kinetic, potential, phi, psi = py::none(), psi_dot = py::none();
  std::vector<std::pair<int, double>> breaks;
  std::optional<std::pair<int, double>> exact_first_break;
  std::optional<double> energy_balance_error;
  int every = 1;
  // What Result.save writes besides the arrays (app/h5_run_file.h).
  RunDescription description;
  RunOutcome outcome;
};

// The Result of a run (its arrays handed to numpy without a copy).
Result make_result(RunDescription d, RunOutcome outcome, std::vector<double> tau,
                   std::vector<double> f, std::vector<double> energy, std::vector<double> kinetic,
                   std::vector<double> potential, std::vector<double> phi, std::vector<double> psi,
                   std::vector<double> psi_dot) {
  Result r;
  r.scene = d.scene;
  r.title = d.title;
  r.solver = solver_name(d.solver);
  r.beads = d.beads;
  r.gamma = d.gamma;
  r.dt = d.dt;
  r.every = d.every;
  r.threshold = d.threshold;
  if (!d.thresholds.empty()) r.thresholds = d.thresholds;
  r.steps = outcome.steps;
  r.tau_end = outcome.tau_end;
  const auto rows = static_cast<py::ssize_t>(tau.size());
  const py::ssize_t n = d.beads;
  r.tau = to_numpy(std::move(tau), {rows});
  r.f = to_numpy(std::move(f), {rows});
  r.energy = to_numpy(std::move(energy), {rows});
  r.kinetic = to_numpy(std::move(kinetic), {rows});
  r.potential = to_numpy(std::move(potential), {rows});
  r.phi = to_numpy(std::move(phi), {rows, n});
  if (d.psi) {
    r.psi = to_numpy(std::move(psi), {rows, n});
    r.psi_dot = to_numpy(std::move(psi_dot), {rows, n});
  }
  for (const BreakEvent& b : outcome.breaks) r.breaks.emplace_back(b.spring, b.tau);
  if (outcome.exact_break && outcome.exact_break->broke)
    r.exact_first_break = std::make_pair(outcome.exact_break->spring, outcome.exact_break->tau);
  if (outcome.books) r.energy_balance_error = outcome.books->balance_error;
  r.description = std::move(d);
  r.outcome = std::move(outcome);
  return r;
}

std::vector<double> values_of(const py::object& array) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  return {a.data(), a.data() + a.size()};
}

// Result.save(path, compress=0): the HDF5 file `run --h5` writes for the same run.
void save(const Result& r, const std::string& path, int compress) {
  if (compress < 0 || compress > 9)
    throw SceneError("save: compress " + std::to_string(compress) + ": expected 0 (none) to 9");
  LoadedRun run;
  run.description = r.description;
  run.outcome = r.outcome;
  run.rows = static_cast<std::uint64_t>(py::len(r.tau));
  run.tau = values_of(r.tau);
  run.f = values_of(r.f);
  run.energy = values_of(r.energy);
  run.kinetic = values_of(r.kinetic);
  run.potential = values_of(r.potential);
  run.phi = values_of(r.phi);
  if (r.description.psi) run.psi = values_of(r.psi), run.psi_dot = values_of(r.psi_dot);
  py::gil_scoped_release release;
  save_h5_run(path, run, compress);
}

// chainbreak.load(path): a Result from a file of `run --h5` or Result.save.
Result load(const std::string& path) {
  LoadedRun run = load_h5_run(path);
  return make_result(std::move(run.description), std::move(run.outcome), std::move(run.tau),
                     std::move(run.f), std::move(run.energy), std::move(run.kinetic),
                     std::move(run.potential), std::move(run.phi), std::move(run.psi),
                     std::move(run.psi_dot));
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

// Jupyter's summary of a Result: the scene, the run, the breaks, the arrays' shapes.
std::string result_html(const Result& r) {
  auto row = [](const std::string& k, const std::string& v) {
    return "<tr><th style=\"text-align:left\">" + k + "</th><td style=\"text-align:left\">" + v +
           "</td></tr>";
  };
  std::string h = "<div><b>chainbreak.Result</b>: " + html_escape(r.title) + " (" +
                  html_escape(r.scene) + ")<table>";
  h += row("solver", r.solver);
  h += row("N, &gamma;, &phi;<sub>c</sub>", std::to_string(r.beads) + ", " + number_text(r.gamma) +
                                                ", " +
                                                (r.threshold ? number_text(*r.threshold) : "none"));
  h += row("&tau;", "0 &hellip; " + number_text(r.tau_end) + " in " + std::to_string(r.steps) +
                        " steps of " + number_text(r.dt) + ", a row every " +
                        std::to_string(r.every));
  h += row("rows", std::to_string(py::len(r.tau)) +
                       " (phi: " + py::str(r.phi.attr("shape")).cast<std::string>() +
                       (r.psi.is_none() ? "" : ", psi") + ")");
  std::string breaks;
  for (std::size_t i = 0; i < r.breaks.size() && i < 8; ++i)
    breaks += (i ? ", " : "") + std::string("spring ") + std::to_string(r.breaks[i].first) +
              " at &tau; = " + number_text(r.breaks[i].second);
  if (r.breaks.size() > 8) breaks += ", &hellip; (" + std::to_string(r.breaks.size()) + ")";
  h += row("breaks", breaks.empty() ? "none" : breaks);
  if (r.exact_first_break)
    h += row("exact first break", "spring " + std::to_string(r.exact_first_break->first) +
                                      " at &tau; = " + number_text(r.exact_first_break->second));
  if (r.energy_balance_error)
    h += row("energy balance error", number_text(*r.energy_balance_error));
  return h + "</table></div>";
}

Result run(const Scene& source, const std::string& solver, int every, bool psi, int threads) {
  const SceneDesc scene = source.resolve();
  RunRequest request;
  request.solver = parse_solver(solver);
  request.every = every;
  request.psi = psi;
  request.threads = threads;
  request.stop = &g_interrupted;
  check_run_request(scene, request);
  ArraySink sink;
  const RunOutcome outcome = interruptible([&] { return run_scene(scene, request, &sink); });
  if (outcome.status == 1) throw std::runtime_error("chainbreak.run: " + outcome.error);
  if (outcome.status != 0) {  // stopped from elsewhere (another call saw Ctrl-C)
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return make_result(describe_run(scene, source.overrides(), request.solver, every, psi), outcome,
                     std::move(sink.tau), std::move(sink.f), std::move(sink.energy),
                     std::move(sink.kinetic), std::move(sink.potential), std::move(sink.phi),
                     std::move(sink.psi), std::move(sink.psi_dot));
}

}  // namespace

void bind_run(py::module_& m) {
  py::class_<Result>(m, "Result",
                     "The rows of a run, as `chainbreak run --csv` writes them, bit for bit.")
      .def_readonly("scene", &Result::scene)
      .def_readonly("title", &Result::title)
      .def_readonly("solver", &Result::solver)
      .def_readonly("beads", &Result::beads)
      .def_readonly("gamma", &Result::gamma)
      .def_readonly("threshold", &Result::threshold)
      .def_readonly("thresholds", &Result::thresholds,
                    "[phi_c,1, ..., phi_c,N] when the springs' thresholds are not all equal "
                    "(drawn by chain.seed, or chain.thresholds), else None (all `threshold`)")
      .def_readonly("dt", &Result::dt)
      .def_readonly("every", &Result::every)
      .def_readonly("steps", &Result::steps)
      .def_readonly("tau_end", &Result::tau_end)
      .def_readonly("tau", &Result::tau, "tau of each row")
      .def_readonly("f", &Result::f, "the force f(tau) on bead N")
      .def_readonly("energy", &Result::energy, "energy per particle, Eq. (energy)")
      .def_readonly("kinetic", &Result::kinetic)
      .def_readonly("potential", &Result::potential)
      .def_readonly("phi", &Result::phi, "[rows, N]: phi[:, j-1] is spring j's extension")
      .def_readonly("psi", &Result::psi, "[rows, N] with psi=True, else None")
      .def_readonly("psi_dot", &Result::psi_dot,
                    "[rows, N]: d psi / d tau with psi=True, else None")
      .def_readonly("breaks", &Result::breaks, "[(spring, tau), ...] in order (rk4)")
      .def_readonly("exact_first_break", &Result::exact_first_break,
                    "(spring, tau) of the exact solution (solver='exact' with a threshold)")
      .def_readonly("energy_balance_error", &Result::energy_balance_error)
      .def("save", &save, py::arg("path"), py::arg("compress") = 0,
           "Write the run as HDF5, as `chainbreak run --h5` does (compress: deflate level 1-9, "
           "0 none); chainbreak.load(path) reads it back.")
      .def("_repr_html_", &result_html)
      .def("__repr__", [](const Result& r) {
        return "<chainbreak.Result " + r.scene + " " + r.solver + ": " +
               std::to_string(py::len(r.tau)) + " rows, N=" + std::to_string(r.beads) + ", " +
               std::to_string(r.breaks.size()) + " breaks>";
      });
  m.def("load", &load, py::arg("path"),
        "A Result from an HDF5 file written by `chainbreak run --h5` or Result.save.");
  m.def("run", &run, py::arg("scene"), py::arg("solver") = "rk4", py::arg("every") = 1,
        py::arg("psi") = false, py::arg("threads") = 1,
        "Run a scene like `chainbreak run`: solver 'rk4' (with breaking), 'exact' or "
        "'continuum'; one row every `every` steps; psi=True adds psi. Releases the GIL; "
        "Ctrl-C raises KeyboardInterrupt.");
}

}  // namespace cb::py_detail
