#include "core/mesh/mesh.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mpmice::core {

Mesh::Mesh(int dim, RealVect origin, RealVect spacing, IntVect cells)
    : dim_(dim), origin_(origin), dx_(spacing), n_(cells) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("Mesh: dim must be 1, 2 or 3");
  for (int d = 0; d < 3; ++d) {
    if (d >= dim) {
      n_[d] = 1;
      origin_[d] = 0.0;
      if (!(dx_[d] > 0)) dx_[d] = 1.0;
      continue;
    }
    if (n_[d] < 1) throw std::invalid_argument("Mesh: cell count must be >= 1");
    if (!(dx_[d] > 0)) throw std::invalid_argument("Mesh: spacing must be > 0");
  }
}

int Mesh::cellOf(int d, double x) const {
  return static_cast<int>(std::floor((x - origin_[d]) / dx_[d]));
}

bool Mesh::insideDomain(const RealVect& x) const {
  for (int d = 0; d < dim_; ++d)
    if (x[d] < origin_[d] || x[d] > upper(d)) return false;
  return true;
}

std::string Mesh::describe() const {
  std::ostringstream os;
  os << dim_ << "D, ";
  for (int d = 0; d < dim_; ++d) os << (d ? " x " : "") << n_[d];
  os << " cells (" << numCells() << "), spacing";
  for (int d = 0; d < dim_; ++d) os << (d ? " x " : " ") << dx_[d];
  os << ", domain";
  for (int d = 0; d < dim_; ++d) os << (d ? " x " : " ") << "[" << origin_[d] << ", " << upper(d) << "]";
  return os.str();
}

}  // namespace mpmice::core
