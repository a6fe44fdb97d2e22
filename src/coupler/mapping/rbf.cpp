#include "coupler/mapping/rbf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpmice::coupler {

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Coordinates (rows: points, columns: the first dim axes) shifted by c and divided by s.
Eigen::MatrixXd scaled(const PointCloud& p, int dim, const Eigen::VectorXd& c, double s) {
  const auto n = static_cast<Eigen::Index>(p.size());
  Eigen::MatrixXd x(n, dim);
  for (int d = 0; d < dim; ++d) {
    const auto& xd = p.x[static_cast<std::size_t>(d)];
    for (Eigen::Index i = 0; i < n; ++i) x(i, d) = (xd[static_cast<std::size_t>(i)] - c(d)) / s;
  }
  return x;
}

/// phi(r) for r >= 0: thin-plate spline if invR == 0, else Wendland C2 with support 1 / invR.
double phi(double r, double invR) {
  if (invR == 0.0) return r > 0.0 ? r * r * std::log(r) : 0.0;
  const double q = r * invR;
  if (q >= 1.0) return 0.0;
  const double a = 1.0 - q;
  return a * a * a * a * (4.0 * q + 1.0);
}

/// Matrix of phi(|a_i - b_j|).
Eigen::MatrixXd kernel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double invR) {
  Eigen::MatrixXd k(a.rows(), b.rows());
  const Eigen::Index dim = a.cols();
  for (Eigen::Index j = 0; j < b.rows(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      double r2 = 0.0;
      for (Eigen::Index d = 0; d < dim; ++d) {
        const double dx = a(i, d) - b(j, d);
        r2 += dx * dx;
      }
      k(i, j) = phi(std::sqrt(r2), invR);
    }
  return k;
}

/// Throws if two source points coincide (the same coordinates in the first dim axes): the
/// interpolation system then has two equal rows, and whether its factorisation shows that depends
/// on the order of its operations (vector width), so it is checked on the points themselves.
void rejectCoincidentPoints(const PointCloud& p, int dim) {
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto key = [&](std::size_t i) {
    std::array<double, 3> k{0.0, 0.0, 0.0};
    for (int d = 0; d < dim; ++d) k[static_cast<std::size_t>(d)] = p.x[static_cast<std::size_t>(d)][i];
    return k;
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (key(order[k]) == key(order[k - 1])) {
      const auto x = key(order[k]);
      throw std::runtime_error("rbf mapping: source points " + std::to_string(std::min(order[k], order[k - 1])) +
                               " and " + std::to_string(std::max(order[k], order[k - 1])) + " coincide at (" +
                               std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " + std::to_string(x[2]) +
                               "); remove duplicates from the source cloud");
    }
}

}  // namespace

Rbf::Rbf(double support) : support_(support) {
  if (!(support >= 0.0) || !std::isfinite(support))
    throw std::invalid_argument(
        "coupling.interface.rbf_support must be >= 0 (0: thin-plate spline, > 0: Wendland C2 "
        "support radius), got " + std::to_string(support));
}

void Rbf::compute(const PointCloud& source, const PointCloud& target, int dim) {
  beginCompute(source, target, dim);
  m_.resize(0, 0);
  linearTerms_ = 0;
  rejectCoincidentPoints(source, dim);
  const auto nS = static_cast<Eigen::Index>(source.size());
  const auto nT = static_cast<Eigen::Index>(target.size());

  // 1. Scaling: shift to the source centroid, divide by the bounding-box size of both clouds.
  Eigen::VectorXd centroid = Eigen::VectorXd::Zero(dim);
  double size = 0.0;
  for (int d = 0; d < dim; ++d) {
    const auto& xs = source.x[static_cast<std::size_t>(d)];
    const auto& xt = target.x[static_cast<std::size_t>(d)];
    for (double v : xs) centroid(d) += v;
    centroid(d) /= static_cast<double>(nS);
    const auto [sLo, sHi] = std::minmax_element(xs.begin(), xs.end());
    const auto [tLo, tHi] = std::minmax_element(xt.begin(), xt.end());
    size = std::max(size, std::max(*sHi, *tHi) - std::min(*sLo, *tLo));
  }
  if (!(size > 0.0)) size = 1.0;  // every point coincides
  const Eigen::MatrixXd xs = scaled(source, dim, centroid, size);
  const Eigen::MatrixXd xt = scaled(target, dim, centroid, size);
  const double invR = support_ > 0.0 ? size / support_ : 0.0;

  // 2. Linear polynomial along the directions the sources determine (rank of the centred
  //    coordinates, relative threshold).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(xs, Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv(k) > kRankTolerance * sv(0)) ++linearTerms_;
  const Eigen::MatrixXd dirs = svd.matrixV().leftCols(linearTerms_);
  const Eigen::Index m = 1 + linearTerms_;
  Eigen::MatrixXd pS(nS, m), pT(nT, m);
  pS.col(0).setOnes();
  pT.col(0).setOnes();
  pS.rightCols(linearTerms_) = xs * dirs;
  pT.rightCols(linearTerms_) = xt * dirs;

  // 3. System [Phi P; P^T 0] and right-hand sides [A_TS P_T]^T. The system is symmetric, so
  //    M^T = (system^-1 [A_TS P_T]^T)[:nS, :].
  const Eigen::Index n = nS + m;
  Eigen::MatrixXd sys = Eigen::MatrixXd::Zero(n, n);
  sys.topLeftCorner(nS, nS) = kernel(xs, xs, invR);
  sys.topRightCorner(nS, m) = pS;
  sys.bottomLeftCorner(m, nS) = pS.transpose();
  Eigen::MatrixXd rhs(n, nT);
  rhs.topRows(nS) = kernel(xs, xt, invR);
  rhs.bottomRows(m) = pT.transpose();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(sys);
  Eigen::MatrixXd sol = lu.solve(rhs);
  m_ = sol.topRows(nS).transpose();

  // 4. A singular system (coincident source points) shows as a map that no longer reproduces
  //    its polynomial.
  const double defect = (m_ * pS - pT).cwiseAbs().maxCoeff();
  if (!m_.allFinite() || !(defect < 1e-6)) {
    m_.resize(0, 0);
    throw std::runtime_error(
        "rbf mapping: the interpolation system is singular or too ill-conditioned (polynomial "
        "reproduction defect " + std::to_string(defect) +
        "); are there coincident source points? Remove duplicates from the source cloud");
  }
  endCompute();
}

void Rbf::applyConsistent(const double* in, double* out, int ncomp) const {
  const Eigen::Map<const RowMajor> f(in, m_.cols(), ncomp);
  Eigen::Map<RowMajor> u(out, m_.rows(), ncomp);
  u.noalias() = m_ * f;
}

void Rbf::applyConservative(const double* in, double* out, int ncomp) const {
  const Eigen::Map<const RowMajor> f(in, m_.rows(), ncomp);
  Eigen::Map<RowMajor> u(out, m_.cols(), ncomp);
  u.noalias() = m_.transpose() * f;
}

}  // namespace mpmice::coupler
