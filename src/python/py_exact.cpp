// chainbreak.exact and chainbreak.continuum: the exact modal solution (src/exact; any linear
// chain, unequal beads and springs through LAPACK's modes) and the continuum's Eq. (sum) (the
// uniform chain only), evaluated at any tau, vectorised over numpy arrays of tau.
#include <pybind11/stl.h>

#include "app/run_rows.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "py_common.h"

namespace cb::py_detail {

namespace {

using TauArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// out[..., j-1] = fill(tau)[j-1] for every tau of the input: shape tau.shape + (N,).
template <class Fill>
py::array_t<double> over_tau(const TauArray& tau, int beads, Fill&& fill) {
  std::vector<py::ssize_t> shape(tau.shape(), tau.shape() + tau.ndim());
  shape.push_back(beads);
  py::array_t<double> out(shape);
  const double* in = tau.data();
  double* o = out.mutable_data();
  std::vector<double> values(beads);
  for (py::ssize_t i = 0; i < tau.size(); ++i) {
    fill(in[i], values);
    std::copy(values.begin(), values.end(), o + i * beads);
  }
  return out;
}

class Exact {
 public:
  explicit Exact(const Scene& source)
      : scene_(source.resolve()), chain_(scene_.chain, scene_.drive) {}
  py::array_t<double> phi(const TauArray& tau) const {
    return over_tau(tau, chain_.beads(),
                    [&](double t, std::vector<double>& v) { chain_.phi(t, v); });
  }
  py::array_t<double> psi(const TauArray& tau) const {
    return over_tau(tau, chain_.beads(),
                    [&](double t, std::vector<double>& v) { chain_.psi(t, v); });
  }
  py::array_t<double> velocity(const TauArray& tau) const {
    return over_tau(tau, chain_.beads(),
                    [&](double t, std::vector<double>& v) { chain_.velocity(t, v); });
  }
  // (spring, tau) of the first spring to reach its threshold up to t_end, or None.
  py::object first_break(std::optional<double> t_end) const {
    if (!scene_.chain.breakable())
      throw SceneError(scene_.path +
                       ": first_break needs chain.threshold; set it, e.g. "
                       "scene.set('chain.threshold', 1.0)");
    if (scene_.drive.type == DriveType::Expr)
      throw SceneError(scene_.path +
                       ": the exact first break has no closed form for an expr drive; use "
                       "chainbreak.run(scene) (rk4)");
    const FirstBreak b =
        exact_first_break(scene_.chain, scene_.drive, t_end.value_or(scene_.integrator.t_end));
    if (!b.broke) return py::none();
    return py::make_tuple(b.spring, b.tau);
  }
  int beads() const { return chain_.beads(); }

 private:
  SceneDesc scene_;
  ExactChain chain_;
};

class Continuum {
 public:
  explicit Continuum(const Scene& source) : scene_(source.resolve()) {
    RunRequest request;
    request.solver = "continuum";
    check_run_request(scene_, request);  // the same refusal as run(solver="continuum")
    const Forcing forcing = make_forcing(scene_.drive);
    f_ = [forcing](double tau) { return forcing(tau); };
  }
  py::array_t<double> phi(const TauArray& tau) const {
    std::vector<double> psi(scene_.chain.beads);
    return over_tau(tau, scene_.chain.beads, [&](double t, std::vector<double>& v) {
      continuum_profile(scene_.chain.beads, t, f_, psi, &v);
    });
  }
  py::array_t<double> psi(const TauArray& tau) const {
    return over_tau(tau, scene_.chain.beads, [&](double t, std::vector<double>& v) {
      continuum_profile(scene_.chain.beads, t, f_, v, nullptr);
    });
  }
  int beads() const { return scene_.chain.beads; }

 private:
  SceneDesc scene_;
  std::function<double(double)> f_;
};

}  // namespace

void bind_exact(py::module_& m) {
  py::class_<Exact>(m, "Exact",
                    "The exact solution of the unbroken chain, Eqs. (exactpsi), (exactgreen), "
                    "(exactconv); for unequal beads and springs the modes of M^-1/2 K M^-1/2 "
                    "(LAPACK). phi(tau), psi(tau), velocity(tau): shape tau.shape + (N,).")
      .def("phi", &Exact::phi, py::arg("tau"))
      .def("psi", &Exact::psi, py::arg("tau"))
      .def("velocity", &Exact::velocity, py::arg("tau"))
      .def("first_break", &Exact::first_break, py::arg("t_end") = py::none(),
           "(spring, tau) of the exact first break (per-spring thresholds) up to t_end "
           "(default the scene's), or None")
      .def_property_readonly("beads", &Exact::beads);
  m.def(
      "exact", [](const Scene& s) { return Exact(s); }, py::arg("scene"),
      "The exact modal solution of the scene's chain, equal or unequal beads and springs (no "
      "breaking).");
  py::class_<Continuum>(m, "Continuum",
                        "The continuum formula Eq. (sum): phi(tau), psi(tau) (psi sums phi).")
      .def("phi", &Continuum::phi, py::arg("tau"))
      .def("psi", &Continuum::psi, py::arg("tau"))
      .def_property_readonly("beads", &Continuum::beads);
  m.def(
      "continuum", [](const Scene& s) { return Continuum(s); }, py::arg("scene"),
      "The paper's large-N formula Eq. (sum) for the scene (a uniform chain; not for impulses).");
}

}  // namespace cb::py_detail
