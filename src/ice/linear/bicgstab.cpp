#include "ice/linear/bicgstab.h"

#include <Eigen/Sparse>
#include <vector>

namespace mpmice::ice::linear {

using core::forEach;

LinearResult solveBicgstab(const FaceStencil& A, const core::Box& domain, const std::array<bool, 3>& periodic,
                           const std::array<bool, 6>& fixedSide, const core::Field& b, core::Field& x, double tol,
                           int maxIterations) {
  const core::Box& owned = A.owned;
  const int n = static_cast<int>(owned.numPts());
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::VectorXd rhs(n), sol(n);
  forEach(owned, [&](int i, int j, int k) {
    const int row = static_cast<int>(owned.index(i, j, k));
    double diag = A.centre(i, j, k);
    for (int d = 0; d < A.dim; ++d)
      for (int s = -1; s <= 1; s += 2) {
        int nb[3] = {i, j, k};
        nb[d] += s;
        int f[3] = {i, j, k};
        if (s > 0) f[d] += 1;
        const double c = A.coef[d](f[0], f[1], f[2]);
        if (nb[d] < domain.lo[d] || nb[d] > domain.hi[d]) {
          if (periodic[d]) {
            nb[d] = nb[d] < domain.lo[d] ? domain.hi[d] : domain.lo[d];
          } else {
            if (fixedSide[2 * d + (s > 0 ? 1 : 0)]) diag += c;
            continue;  // mirror: no coupling
          }
        }
        diag += c;
        trip.emplace_back(row, static_cast<int>(owned.index(nb[0], nb[1], nb[2])), -c);
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
