#pragma once
/// @brief Eigen's BiCGSTAB (diagonal preconditioner) on the assembled FaceStencil, one rank.
///
/// The stencil is assembled over the owned cells, which must be the whole mesh (bc.domain), with
/// the boundary folded in as ice/linear/assembled_rows.h does it. Eigen's stopping test is its own
/// (relative residual <= tol). The alternative to JacobiCg for comparisons, not for parallel runs.
#include "ice/linear/assembled_rows.h"

namespace mpmice::ice::linear {

/// x over the owned cells of A.
LinearResult solveBicgstab(const FaceStencil& A, const StencilBoundary& bc, const core::Field& b, core::Field& x,
                           double tol, int maxIterations);

}  // namespace mpmice::ice::linear
