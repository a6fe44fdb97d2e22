#include "ice/linear/bicgstab.h"

#include <Eigen/Sparse>
#include <vector>

namespace mpmice::ice::linear {

using core::forEach;

LinearResult solveBicgstab(const FaceStencil& A, const StencilBoundary& bc, const core::Field& b, core::Field& x,
                           double tol, int maxIterations) {
  const core::Box& owned = A.owned;
  const int n = static_cast<int>(owned.numPts());
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::VectorXd rhs(n), sol(n);
  forEachRow(A, bc, [&](int i, int j, int k, double diag, const std::array<double, 6>& off) {
    const int row = static_cast<int>(owned.index(i, j, k));
    for (int d = 0; d < A.dim; ++d)
      for (int s = 0; s < 2; ++s) {
        if (off[2 * d + s] == 0) continue;
        int nb[3] = {i, j, k};
        nb[d] += s ? 1 : -1;
        if (nb[d] < bc.domain.lo[d]) nb[d] = bc.domain.hi[d];  // periodic image
        if (nb[d] > bc.domain.hi[d]) nb[d] = bc.domain.lo[d];
        trip.emplace_back(row, static_cast<int>(owned.index(nb[0], nb[1], nb[2])), -off[2 * d + s]);
      }
    trip.emplace_back(row, row, diag);
    rhs[row] = b(i, j, k);
  });
  Eigen::SparseMatrix<double> Am(n, n);
  Am.setFromTriplets(trip.begin(), trip.end());
  Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>> solver;
  solver.setTolerance(tol);
  solver.setMaxIterations(maxIterations);
  solver.compute(Am);
  sol = solver.solve(rhs);
  LinearResult res;
  res.converged = solver.info() == Eigen::Success;
  res.iterations = static_cast<int>(solver.iterations());
  res.error = solver.error();
  if (res.converged) forEach(owned, [&](int i, int j, int k) { x(i, j, k) = sol[owned.index(i, j, k)]; });
  return res;
}

}  // namespace mpmice::ice::linear
