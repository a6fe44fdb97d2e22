#pragma once
/// @brief Radial basis function interface mapping with a linear polynomial.
///
/// The interpolant of source values f is s(y) = sum_j a_j phi(|y - x_j|) + p(y), p linear, with
///   [Phi P; P^T 0] [a; b] = [f; 0].
/// phi: support 0 = thin-plate spline r^2 log r (global); support R > 0 = Wendland C2
/// (1 - r/R)^4_+ (4 r/R + 1). Coordinates are shifted to the source centroid and divided by the
/// bounding-box size of both clouds (conditioning of the thin-plate spline; it leaves the
/// interpolant unchanged). Linear terms the sources do not determine (all on a line or a plane,
/// or too few points) are dropped: the polynomial uses only the principal directions of the
/// centred sources whose singular value exceeds kRankTolerance times the largest; the
/// interpolant is then constant across those directions.
/// compute() stores the dense nTarget x nSource matrix M = [A_TS P_T] inverse(system)[:, :nS]
/// (one LU of the system, O(nS^3 + nS^2 nT)); both directions are then a matrix product.
#include <Eigen/Dense>

#include "coupler/mapping/mapping.h"

namespace mpmice::coupler {

class Rbf final : public Mapping {
 public:
  /// Relative singular-value threshold below which a linear polynomial term is dropped.
  static constexpr double kRankTolerance = 1e-8;

  /// support: 0 for the thin-plate spline, > 0 for the Wendland C2 support radius (in the
  /// clouds' length unit). Throws std::invalid_argument if negative or not finite.
  explicit Rbf(double support);
  /// Also throws std::runtime_error if the system is singular (coincident source points).
  void compute(const PointCloud& source, const PointCloud& target, int dim) override;
  [[nodiscard]] const char* name() const override { return "rbf"; }
  [[nodiscard]] double support() const { return support_; }
  /// Number of linear polynomial terms kept by the last compute() (0 .. dim; the constant is
  /// always kept).
  [[nodiscard]] int linearTerms() const { return linearTerms_; }
  /// M, nTarget x nSource.
  [[nodiscard]] const Eigen::MatrixXd& matrix() const { return m_; }

 private:
  void applyConsistent(const double* in, double* out, int ncomp) const override;
  void applyConservative(const double* in, double* out, int ncomp) const override;

  double support_;
  int linearTerms_ = 0;
  Eigen::MatrixXd m_;
};

}  // namespace mpmice::coupler
