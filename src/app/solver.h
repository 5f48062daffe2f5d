// The solvers, as a type: `run` takes any of them, `sweep` (first breaks) rk4 or exact. The
// command line, the Python module, the JSON summary and the sweep's record name them with
// solver_name(), so the word and the value cannot drift apart.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace cb {

enum class Solver {
  Rk4,        // fixed-step RK4 with breaking (physics/integrator.h)
  Exact,      // the unbroken chain by normal modes, Eqs. (exactpsi)-(exactconv)
  Continuum,  // the large-N formula Eq. (sum)
};

// "rk4", "exact" or "continuum".
const char* solver_name(Solver solver);
// The names `run` takes, and those `sweep` takes (rk4, exact), in that order.
std::vector<std::string> run_solver_names();
std::vector<std::string> sweep_solver_names();
// The solver called `name`; SceneError "--solver NAME: expected rk4, exact or continuum".
Solver parse_solver(const std::string& name);
// SceneError "--solver NAME: sweep supports rk4 or exact" for a solver that finds no first
// break (continuum).
void check_sweep_solver(Solver solver);

}  // namespace cb
