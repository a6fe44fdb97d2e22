#pragma once
/// @brief The component arrays of a vector field for the hot loops (kernels take double* [3]):
/// null beyond the field's components. Vectors with the mesh's dimension of components (MPM's
/// node fields, ICE's cell velocities: 2D holds no z) are read and written through it.
#include <array>

#include "core/field/field.h"

namespace mpmice::core {

inline std::array<double*, 3> components(Field& f) {
  std::array<double*, 3> c{nullptr, nullptr, nullptr};
  for (int d = 0; d < f.ncomp() && d < 3; ++d) c[static_cast<std::size_t>(d)] = f.data(d);
  return c;
}
inline std::array<const double*, 3> components(const Field& f) {
  std::array<const double*, 3> c{nullptr, nullptr, nullptr};
  for (int d = 0; d < f.ncomp() && d < 3; ++d) c[static_cast<std::size_t>(d)] = f.data(d);
  return c;
}

}  // namespace mpmice::core
