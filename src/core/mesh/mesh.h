#pragma once
/// @brief The shared structured background mesh: origin, spacing and cell counts in 1D, 2D or 3D.
///
/// MPM and ICE live on the same mesh. Cells are indexed 0..n-1 per direction, nodes 0..n, faces
/// normal to direction d 0..n_d. Directions beyond `dim` have one cell of unit thickness (so cell
/// volumes in 2D are areas times 1, plane strain).
#include <array>
#include <string>

#include "core/mesh/box.h"

namespace mpmice::core {

using RealVect = std::array<double, 3>;

class Mesh {
 public:
  Mesh() = default;
  /// dim in 1..3; cells[d] >= 1 for d < dim; spacing[d] > 0.
  Mesh(int dim, RealVect origin, RealVect spacing, IntVect cells);

  [[nodiscard]] int dim() const { return dim_; }
  [[nodiscard]] const RealVect& origin() const { return origin_; }
  [[nodiscard]] const RealVect& spacing() const { return dx_; }
  [[nodiscard]] double dx(int d) const { return dx_[d]; }
  [[nodiscard]] const IntVect& cells() const { return n_; }
  [[nodiscard]] std::int64_t numCells() const { return cellBox().numPts(); }
  [[nodiscard]] double cellVolume() const { return dx_[0] * dx_[1] * dx_[2]; }

  [[nodiscard]] Box cellBox() const { return Box({0, 0, 0}, {n_[0] - 1, n_[1] - 1, n_[2] - 1}); }
  [[nodiscard]] Box nodeBox() const { return cellBox().surroundingNodes(dim_); }
  [[nodiscard]] Box faceBox(int d) const { return cellBox().faces(d); }

  [[nodiscard]] double cellCenter(int d, int i) const { return origin_[d] + (i + 0.5) * dx_[d]; }
  [[nodiscard]] double node(int d, int i) const { return origin_[d] + i * dx_[d]; }
  [[nodiscard]] double upper(int d) const { return origin_[d] + n_[d] * dx_[d]; }
  /// Cell holding coordinate x in direction d (may lie outside 0..n-1 for points off the mesh).
  [[nodiscard]] int cellOf(int d, double x) const;
  [[nodiscard]] bool insideDomain(const RealVect& x) const;
  /// Calls f(x, sub) at the centres of the n[0] x n[1] x n[2] equal sub-cells of cell ijk (sub the
  /// sub-cell's index per direction, the first fastest; coordinates beyond dim are 0): the particle
  /// points of a cell, or sample points.
  template <class F>
  void forSubcellCentres(const int ijk[3], const int n[3], F&& f) const {
    for (int c = 0; c < n[2]; ++c)
      for (int b = 0; b < n[1]; ++b)
        for (int a = 0; a < n[0]; ++a) {
          const int sub[3] = {a, b, c};
          RealVect x{0, 0, 0};
          for (int d = 0; d < dim_; ++d) x[d] = node(d, ijk[d]) + (sub[d] + 0.5) * dx_[d] / n[d];
          f(x, sub);
        }
  }
  [[nodiscard]] std::string describe() const;

  friend bool operator==(const Mesh& a, const Mesh& b) {
    return a.dim_ == b.dim_ && a.origin_ == b.origin_ && a.dx_ == b.dx_ && a.n_ == b.n_;
  }

 private:
  int dim_ = 0;
  RealVect origin_{0, 0, 0};
  RealVect dx_{1, 1, 1};
  IntVect n_{1, 1, 1};
};

}  // namespace mpmice::core
