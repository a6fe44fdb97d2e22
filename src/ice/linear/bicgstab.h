#pragma once
/// @brief Eigen's BiCGSTAB (diagonal preconditioner) on the assembled FaceStencil, one rank.
///
/// The stencil is assembled over the owned cells, which must be the whole mesh (`domain`): a
/// neighbour across a periodic direction is its periodic image; across any other side it is a
/// mirror (no coupling), except where the side holds a fixed pressure (the increment is zero
/// there: the face's coefficient stays on the diagonal). Eigen's stopping test is its own
/// (relative residual <= tol). The alternative to JacobiCg for comparisons, not for parallel runs.
#include <array>

#include "ice/linear/linear_operator.h"

namespace mpmice::ice::linear {

/// x over the owned cells of A; fixedSide[2 d + (0 low, 1 high)].
LinearResult solveBicgstab(const FaceStencil& A, const core::Box& domain, const std::array<bool, 3>& periodic,
                           const std::array<bool, 6>& fixedSide, const core::Field& b, core::Field& x, double tol,
                           int maxIterations);

}  // namespace mpmice::ice::linear
