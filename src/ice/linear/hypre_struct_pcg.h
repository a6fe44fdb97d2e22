#pragma once
/// @brief hypre's structured-grid PCG, preconditioned by one V-cycle of PFMG (or SMG), on the
/// assembled FaceStencil over any number of ranks.
///
/// Each rank gives hypre its one owned box of the decomposition (global cell indices) on the
/// solver's communicator; periodic directions are hypre's periodic grid; the other sides of the
/// mesh are folded into the matrix as ice/linear/assembled_rows.h does it (the coupling to a
/// cell outside the mesh is always zero). The stencil has 2 dim + 1 points (centre, then low and
/// high neighbour per direction); a 1D mesh is given to hypre as one row of a 2D grid (5 points,
/// the y couplings zero: PFMG and SMG have no 1D operators). The stopping test is JacobiCg's: |r| <= tol |b| in Euclidean
/// norms over every rank (hypre's two-norm option), from the x given (the semi-implicit solve
/// passes the previous step's pressure increment, which the restart checkpoint keeps: 11 % fewer
/// iterations on the flap); b = 0 gives x = 0 at once.
///
/// The grid, stencil, matrix and vectors are built once (the first solve) and reused while the
/// owned box stays. PFMG (Galerkin coarse operators, red-black Gauss-Seidel) is the default; SMG
/// (plane smoothing, costlier per cycle) is the fallback where PFMG's pointwise smoother struggles
/// with anisotropy or jumps.
///
/// The lagged hierarchy: hypre's PFMG / SMG set-up (coarse grids, their communication, the
/// Galerkin coarse operators) costs several V-cycles and cannot be re-run on an existing solver
/// object, so it is built from one solve's matrix and kept for at most `reuse` solves (the key
/// ice.preconditioner_reuse). Each solve writes its own matrix into hypre's: PCG's products and
/// the fine-level smoothing use the current operator, the coarse levels lag. The preconditioner
/// stays symmetric positive definite (symmetric smoothing, Galerkin coarse operators of an SPD
/// matrix), so PCG still stops at |r| <= tol |b| of the current system; only its iteration count
/// can grow. It is rebuilt at once when a solve takes more than twice the iterations of the first
/// solve after the set-up, plus 2, and a solve that fails to converge with the lagged hierarchy is
/// repeated with a fresh one before it is reported. The restart checkpoint keeps the set-up's
/// matrix and counters (setupState / restoreSetupState), so a resumed run rebuilds the same
/// hierarchy and continues bit for bit.
#include <memory>
#include <vector>

#include "core/parallel/comm.h"
#include "ice/linear/assembled_rows.h"

namespace mpmice::ice::linear {

enum class StructPreconditioner { Pfmg, Smg };

class HypreStructPcg {
 public:
  /// reuse >= 1: the most solves one multigrid set-up serves (1: a fresh hierarchy every solve).
  HypreStructPcg(const core::Comm& comm, StructPreconditioner preconditioner, int reuse = 1);
  ~HypreStructPcg();
  HypreStructPcg(const HypreStructPcg&) = delete;
  HypreStructPcg& operator=(const HypreStructPcg&) = delete;

  /// x (stored with ghosts): the initial guess over A.owned on entry, the solution on return;
  /// b over A.owned. Collective.
  /// error: the final relative residual |r| / |b|.
  LinearResult solve(const FaceStencil& A, const StencilBoundary& bc, const core::Field& b, core::Field& x,
                     double tol, int maxIterations);

  /// The lagged hierarchy's restart state on this rank: {solves since the set-up, iterations of
  /// the first of them, rebuild-next flag, then the set-up's matrix values}; empty before the
  /// first set-up. restoreSetupState gives it back (the next solve first rebuilds the hierarchy
  /// from those values). Set-ups served since the start: setups().
  [[nodiscard]] std::vector<double> setupState() const;
  void restoreSetupState(std::vector<double> state);
  [[nodiscard]] long setups() const { return setups_; }

 private:
  struct Objects;  // hypre's handles (kept out of this header)
  core::Comm comm_;
  StructPreconditioner pre_;
  int reuse_;
  long setups_ = 0;
  std::vector<double> pending_;  // a restored setupState, applied by the next solve
  std::unique_ptr<Objects> h_;
};

}  // namespace mpmice::ice::linear
