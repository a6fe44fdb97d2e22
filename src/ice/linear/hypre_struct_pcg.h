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
/// owned box stays; each solve sets the values and rebuilds the PCG and its multigrid hierarchy
/// (hypre's PFMG/SMG set-up builds the coarse operators from the matrix values and cannot be
/// re-run on an existing solver object). PFMG (Galerkin coarse operators, red-black Gauss-Seidel)
/// is the default; SMG (plane smoothing, costlier per cycle) is the fallback where PFMG's
/// pointwise smoother struggles with anisotropy or jumps.
#include <memory>

#include "core/parallel/comm.h"
#include "ice/linear/assembled_rows.h"

namespace mpmice::ice::linear {

enum class StructPreconditioner { Pfmg, Smg };

class HypreStructPcg {
 public:
  HypreStructPcg(const core::Comm& comm, StructPreconditioner preconditioner);
  ~HypreStructPcg();
  HypreStructPcg(const HypreStructPcg&) = delete;
  HypreStructPcg& operator=(const HypreStructPcg&) = delete;

  /// x (stored with ghosts): the initial guess over A.owned on entry, the solution on return;
  /// b over A.owned. Collective.
  /// error: the final relative residual |r| / |b|.
  LinearResult solve(const FaceStencil& A, const StencilBoundary& bc, const core::Field& b, core::Field& x,
                     double tol, int maxIterations);

 private:
  struct Objects;  // hypre's handles (kept out of this header)
  core::Comm comm_;
  StructPreconditioner pre_;
  std::unique_ptr<Objects> h_;
};

}  // namespace mpmice::ice::linear
