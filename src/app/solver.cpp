#include "app/solver.h"

namespace cb {

const char* solver_name(Solver solver) {
  switch (solver) {
    case Solver::Rk4:
      return "rk4";
    case Solver::Exact:
      return "exact";
    case Solver::Continuum:
      return "continuum";
  }
  return "rk4";  // unreachable: every enumerator is handled above
}

std::vector<std::string> run_solver_names() {
  return {solver_name(Solver::Rk4), solver_name(Solver::Exact), solver_name(Solver::Continuum)};
}

std::vector<std::string> sweep_solver_names() {
  return {solver_name(Solver::Rk4), solver_name(Solver::Exact)};
}

Solver parse_solver(const std::string& name) {
  for (Solver s : {Solver::Rk4, Solver::Exact, Solver::Continuum})
    if (name == solver_name(s)) return s;
  throw SceneError("--solver " + name + ": expected rk4, exact or continuum");
}

void check_sweep_solver(Solver solver) {
  if (solver == Solver::Continuum)
    throw SceneError(std::string("--solver ") + solver_name(solver) +
                     ": sweep supports rk4 or exact");
}

}  // namespace cb
