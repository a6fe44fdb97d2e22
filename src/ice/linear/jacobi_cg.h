#pragma once
/// @brief Jacobi-preconditioned conjugate gradients over a LinearOperator, on one rank's owned
/// cells of a distributed cell field.
///
/// Solves A x = b for a symmetric positive definite A from x = 0: z = r / diag(A), the search
/// direction p = z + beta p, and stops when |r| <= tol |b| (Euclidean norms over every rank),
/// tested after each update of x; b = 0 gives x = 0 at once. The dot products are summed over
/// the communicator the solver is given (never MPI_COMM_WORLD); the operator's products do the
/// ghost exchange. The scratch vectors (r, z, q = A p, p with ghost layers like x, the diagonal)
/// are kept between solves of the same shape.
#include "core/parallel/comm.h"
#include "ice/linear/linear_operator.h"

namespace mpmice::ice::linear {

class JacobiCg {
 public:
  explicit JacobiCg(const core::Comm& comm) : comm_(comm) {}
  /// x (stored with ghosts) receives the solution over the owned cells of `owned`; b over them.
  LinearResult solve(const LinearOperator& A, const core::Field& b, core::Field& x, const core::Box& owned,
                     double tol, int maxIterations);

 private:
  [[nodiscard]] double dot(const core::Field& a, const core::Field& b, const core::Box& owned) const;

  core::Comm comm_;
  core::Field r_, z_, q_, p_, diag_;
};

}  // namespace mpmice::ice::linear
