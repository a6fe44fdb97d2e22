#pragma once
/// @brief Q R of a tall matrix whose rows are distributed over ranks, kept up to date as columns
/// come and go: a column inserted at the front costs one orthogonalisation (modified Gram-Schmidt,
/// twice, with global inner products) and m Givens rotations, a column deleted anywhere the
/// rotations that restore the triangle, never a rebuild (what preCICE's QRFactorization does).
///
/// Column 0 is the newest. R(j, j) is the norm of column j's part orthogonal to columns 0..j-1,
/// which is what a QR filter compares with the column's norm.
#include <vector>

#include <Eigen/Dense>

#include "core/parallel/comm.h"

namespace mpmice::coupler {

class QrFactorization {
 public:
  explicit QrFactorization(core::Comm comm) : comm_(comm) {}
  /// Inserts `column` (this rank's rows) as column 0.
  void pushFront(const Eigen::VectorXd& column);
  /// Deletes column j.
  void erase(int j);
  void clear();
  [[nodiscard]] int cols() const { return static_cast<int>(q_.size()); }
  /// |R(j, j)|.
  [[nodiscard]] double diagonal(int j) const { return std::abs(r_(j, j)); }
  /// The least-squares coefficients a minimising ||A a - rhs|| (R a = Q^T rhs).
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  [[nodiscard]] const Eigen::MatrixXd& r() const { return r_; }
  [[nodiscard]] const std::vector<Eigen::VectorXd>& q() const { return q_; }
  /// A restart: the factorisation as q() and r() were (exactly, not rebuilt).
  void restore(std::vector<Eigen::VectorXd> q, Eigen::MatrixXd r) {
    q_ = std::move(q);
    r_ = std::move(r);
  }

 private:
  /// A Givens rotation of rows/columns (k, k + 1) by (c, s).
  struct Rotation {
    int k;
    double c, s;
  };
  /// Rotates rows (i, k) of R (columns from `from`) and columns (i, k) of Q by (c, s).
  void rotate(int i, int k, double c, double s, int from);
  /// Rows (i, k) of R only.
  void rotateR(int i, int k, double c, double s, int from);
  /// Columns (k, k + 1) of Q by each rotation of `chain` in turn (one pass over the rows).
  void rotateQ(const std::vector<Rotation>& chain);
  core::Comm comm_;
  std::vector<Eigen::VectorXd> q_;  // orthonormal columns (this rank's rows)
  Eigen::MatrixXd r_;               // upper triangular, cols x cols (the same on every rank)
};

}  // namespace mpmice::coupler
