#pragma once
/// @brief The equilibrium pressure of each cell over all materials: sum_r rho_r / rho_r^micro(p, e_r) = 1.
///
/// rho_r is material r's density per cell volume (mass / V) and e_r its specific internal energy,
/// held fixed. f(p) = 1 - sum_r rho_r / rho_r^micro(p) increases with p. The search never leaves
/// the admissible interval: its lower end is the largest of the present materials' pressure
/// floors at their e (Eos::pressureFloor: 0 for an ideal gas and a solid_bulk solid, -p_inf for a stiffened gas, none
/// for Mie-Gruneisen); below a root lie pressures where f < 0 or some material has no density
/// (rho^micro <= 0), above it f > 0. All cells iterate in lockstep (one batch EOS call per
/// material per sweep, over the still-active cells): Newton steps, replaced by bisection
/// (geometric across decades, measured from the floor; from the floor itself, while no iterate
/// below the root has been seen, by steps of 2^-1, 2^-2, 2^-4, ... of the distance to it, so a
/// root hundreds of decades above the floor is bracketed in about ten, the smallest normal double
/// above the floor the lowest such step) or bracket expansion
/// whenever they leave the bracket, so every iterate is admissible. The iteration count per cell is returned as a
/// diagnostic. A cell without a root is a failure saying why: a material with no admissible
/// state at its energy (e.g. e <= 0), or f > 0 all the way down to the floor (the materials
/// cannot fill the cell at any admissible pressure), or no convergence in the iteration limit.
/// A single material without an external partner takes p = EOS(rho, e) directly (0 iterations).
///
/// Cavitation (docs/ice.md "Cavitation"; Eos::cavitationPressure): a liquid with a cut-off p_c
/// admits p = p_c at every density up to rho_c(e), the density where its law reaches p_c, and no
/// pressure below. Its floor in the cell is p_c. When it sets the cell's floor F (above every other
/// material's floor) and at F, with the liquid at rho_c, the materials fill at most the cell
/// (f(F) >= 0), the cell cavitates: p = F, the other materials take their volumes at F and the
/// liquid the rest (its density falls below rho_c: the cavity). Otherwise the root lies above F
/// and is found as usual. A cell of one material takes max(EOS(rho, e), p_c). cavitated() lists
/// the (material, cell) pairs: zero sound speed, infinite compressibility in the step.
///
/// Traces (ice.trace_mass_fraction, docs/ice.md "Traces"): a fluid whose mass is below the
/// fraction Y_t of the cell's fluid mass may be compressed by the cell's pressure but not pulled
/// beyond the specific volume it carries into the step. For p below its own pressure at that
/// volume, p_own = EOS(1 / v_carried, e), its volume is held at v_carried (d rho / d p = 0), and
/// its pressure floor does not bound the cell's admissible interval. Above p_own it is an
/// ordinary material, so a cell in pressure equilibrium is solved exactly as without the rule.
/// Without it, a trace of gas (1e-15 of a cell's mass) beside water in tension (p < 0) must fill
/// the water's volume deficit at p > 0: its specific volume grows to 1e8 m^3/kg and the cell
/// blows up a few hundred steps later. An external material (a solid) below Y_t of the cell's
/// fluid mass is held the same way at the specific volume its solver gives it: a solid_bulk
/// solid has no state at p <= 0, so a polymer particle's smear of 1e-15 kg in a cell of silicone
/// in tension had to fill the liquid's deficit on its tension branch at p ~ 1e-460 Pa, below every
/// double, and stopped the run (the filled lattices, docs/slides.md).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ice/eos/eos.h"
#include "ice/state/owned_cells.h"

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
  /// fluid[r]: material r is a fluid (the traces' reference is the cell's fluid mass; any present
  /// material below Y_t of it is a trace); traceMassFraction: Y_t (0: no trace rule).
  EquilibriumPressure(std::vector<const Eos*> eos, double tolerance, int maxIterations,
                      std::vector<bool> fluid = {}, double traceMassFraction = 0.0);

  /// cells: linear indices into the arrays; rho[r], e[r]: per material; p: in guess, out result;
  /// rhoMicro[r]: out; iters: out (the iterations per cell; nullptr: not kept, only their most,
  /// lastMostIterations). carriedVolume[r] (may
  /// alias rhoMicro[r]: it is read first): each material's specific volume carried into the step,
  /// needed by the trace rule (nullptr: no trace rule). Returns the failures. The cells are
  /// solved in blocks of kBlock (scratch of the block's size, not the mesh's; each cell's
  /// iteration is its own, so the result does not depend on the blocks).
  std::vector<EquilibriumFailure> solve(const std::vector<std::int64_t>& cells, const std::vector<const double*>& rho,
                                        const std::vector<const double*>& e, double* p,
                                        const std::vector<double*>& rhoMicro, int* iters,
                                        const std::vector<const double*>* carriedVolume = nullptr);
  /// The same over the owned cells (their indices made a block at a time: the same blocks).
  std::vector<EquilibriumFailure> solve(const OwnedCells& cells, const std::vector<const double*>& rho,
                                        const std::vector<const double*>& e, double* p,
                                        const std::vector<double*>& rhoMicro, int* iters,
                                        const std::vector<const double*>* carriedVolume = nullptr);

  [[nodiscard]] double traceMassFraction() const { return traceY_; }

  /// The most iterations any cell of the last solve() took.
  [[nodiscard]] int lastMostIterations() const { return mostIt_; }

  /// The (material, cell) pairs the last solve() held at their carried volume (traces below their
  /// own pressure): their compressibility is 0 in the step.
  [[nodiscard]] const std::vector<std::pair<int, std::int64_t>>& heldTraces() const { return held_; }

  /// The (material, cell) pairs the last solve() left cavitated (at their cut-off pressure with a
  /// density below the law's density there): their sound speed is 0 in the step.
  [[nodiscard]] const std::vector<std::pair<int, std::int64_t>>& cavitated() const { return cavitated_; }

 private:
  static constexpr std::size_t kBlock = 1024;
  void solveBlock(const std::vector<std::int64_t>& cells, const std::vector<const double*>& rho,
                  const std::vector<const double*>& e, double* p, const std::vector<double*>& rhoMicro,
                  int* iters, const std::vector<const double*>* carriedVolume,
                  std::vector<EquilibriumFailure>& failures);
  /// Both solve()s: n cells in blocks of kBlock, fill(first, count, out) writing a block's indices.
  template <class Fill>
  std::vector<EquilibriumFailure> solveInBlocks(std::size_t n, Fill&& fill, const std::vector<const double*>& rho,
                                                const std::vector<const double*>& e, double* p,
                                                const std::vector<double*>& rhoMicro, int* iters,
                                                const std::vector<const double*>* carriedVolume);
  std::vector<const Eos*> eos_;
  double tol_;
  int maxIt_;
  int mostIt_ = 0;  // the most iterations of a cell in the last solve()
  std::vector<bool> fluid_;
  double traceY_;
  // Trace rule per material, indexed by cell - c0_: p_own (-inf: not held) and the carried density.
  std::int64_t c0_ = 0;
  std::vector<std::int64_t> block_;
  std::vector<std::vector<double>> pHold_, rhoHold_;
  std::vector<std::int64_t> all_;
  // The block's traces with an admissible carried state: (material, cell, p_own, carried density).
  struct HoldCandidate {
    std::size_t r;
    std::int64_t c;
    double p, rho;
  };
  std::vector<HoldCandidate> holdCand_;
  std::vector<std::pair<int, std::int64_t>> held_, cavitated_;
  std::vector<double> pCav_;  // per material: the cut-off (-inf: none)
  // Scratch over the active cells.
  std::vector<std::int64_t> active_;
  std::vector<double> pa_, ea_, ra_, da_, f_, df_, lo_, hi_, floor_, pf_, next_;
  std::vector<double> fluidMass_;  // the trace rule: each active cell's fluid mass (per unit volume)
  std::vector<int> floorMat_;
  std::vector<unsigned char> down_;  // consecutive steps towards the floor with nothing below the root seen
  std::vector<unsigned char> up_;    // consecutive slow steps up with nothing above the root seen
  std::vector<char> bad_, cavFloor_;  // cavFloor_: F is a cavitating liquid's cut-off and f(F) < 0
};

}  // namespace mpmice::ice
