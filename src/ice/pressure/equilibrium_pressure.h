#pragma once
/// @brief The equilibrium pressure of each cell over all materials: sum_r rho_r / rho_r^micro(p, e_r) = 1.
///
/// rho_r is material r's density per cell volume (mass / V) and e_r its specific internal energy,
/// held fixed. f(p) = 1 - sum_r rho_r / rho_r^micro(p) increases with p. The search never leaves
/// the admissible interval: its lower end is the largest of the present materials' pressure
/// floors at their e (Eos::pressureFloor: 0 for an ideal gas, -p_inf for a stiffened gas, none
/// for Mie-Gruneisen); below a root lie pressures where f < 0 or some material has no density
/// (rho^micro <= 0), above it f > 0. All cells iterate in lockstep (one batch EOS call per
/// material per sweep, over the still-active cells): Newton steps, replaced by bisection
/// (geometric across decades, measured from the floor) or bracket expansion whenever they leave
/// the bracket, so every iterate is admissible. The iteration count per cell is returned as a
/// diagnostic. A cell without a root is a failure saying why: a material with no admissible
/// state at its energy (e.g. e <= 0), or f > 0 all the way down to the floor (the materials
/// cannot fill the cell at any admissible pressure), or no convergence in the iteration limit.
/// A single material without an external partner takes p = EOS(rho, e) directly (0 iterations).
#include <cstdint>
#include <string>
#include <vector>

#include "ice/eos/eos.h"

namespace mpmice::ice {

struct EquilibriumFailure {
  enum class Kind {
    NotConverged,       // the iteration limit was reached
    NoAdmissibleState,  // material has no admissible state at its e (its floor is +inf)
    NoRootAboveFloor,   // f > 0 down to the floor that material sets: no admissible root
  };
  std::int64_t cell = -1;  // linear index in the arrays passed to solve()
  double p = 0, lo = 0, hi = 0, residual = 0;
  int iterations = 0;
  Kind kind = Kind::NotConverged;
  int material = -1;  // the material the failure is about (NoAdmissibleState, NoRootAboveFloor)
  double floor = 0;   // the admissible interval's lower end
};

class EquilibriumPressure {
 public:
  EquilibriumPressure(std::vector<const Eos*> eos, double tolerance, int maxIterations);

  /// cells: linear indices into the arrays; rho[r], e[r]: per material; p: in guess, out result;
  /// rhoMicro[r]: out; iters: out (as double, it is written to a field). Returns the failures.
  std::vector<EquilibriumFailure> solve(const std::vector<std::int64_t>& cells, const std::vector<const double*>& rho,
                                        const std::vector<const double*>& e, double* p,
                                        const std::vector<double*>& rhoMicro, double* iters);

 private:
  std::vector<const Eos*> eos_;
  double tol_;
  int maxIt_;
  // Scratch over the active cells.
  std::vector<std::int64_t> active_;
  std::vector<double> pa_, ea_, ra_, da_, f_, df_, lo_, hi_, floor_, pf_;
  std::vector<int> floorMat_;
  std::vector<char> bad_;
};

}  // namespace mpmice::ice
