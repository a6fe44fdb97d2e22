#pragma once
/// @brief The operator interface of ICE's linear solvers, and the face stencil the semi-implicit
/// pressure solve assembles.
///
/// A LinearOperator acts on cell fields over one rank's owned cells; apply() fills the ghosts of
/// its argument first (a ghost exchange, hence collective over the operator's communicator), so
/// a solver over it needs nothing but the products, the diagonal and the solver's own sums.
/// FaceStencil is the (2 dim + 1)-point operator
///     (A x)_c = centre_c x_c + sum_faces coef_f (x_c - x_neighbour)
/// with one coefficient per face (faces normal to direction d: face index i = low face of cell
/// i), symmetric positive definite for centre >= 0, coef >= 0 and centre > 0 somewhere. libice
/// only: nothing here knows of the coupling.
#include <array>
#include <functional>

#include "core/field/field.h"

namespace mpmice::ice::linear {

class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  /// Fills the ghosts of x, then y = A x over the owned cells.
  virtual void apply(core::Field& x, core::Field& y) const = 0;
  /// d = diag(A) over the owned cells (the Jacobi preconditioner).
  virtual void diagonal(core::Field& d) const = 0;
};

/// What a linear solve reports: converged (the stopping test met), iterations taken, and the
/// solver's own error estimate where it gives one.
struct LinearResult {
  bool converged = false;
  int iterations = 0;
  double error = 0;
};

struct FaceStencil final : LinearOperator {
  core::Box owned;
  int dim = 1;
  core::Field centre;               // per owned cell
  std::array<core::Field, 3> coef;  // per face normal to each direction d < dim
  std::function<void(core::Field&)> fillGhosts;

  /// Allocates centre and coef over `owned` (their values are the assembler's).
  void allocate(const core::Box& ownedBox, int dimension);
  void apply(core::Field& x, core::Field& y) const override;
  void diagonal(core::Field& d) const override;
};

}  // namespace mpmice::ice::linear
