#include "core/mesh/box.h"

#include <algorithm>
#include <sstream>

namespace mpmice::core {

Box Box::grow(int n, int dim) const {
  Box b = *this;
  for (int d = 0; d < dim; ++d) {
    b.lo[d] -= n;
    b.hi[d] += n;
  }
  return b;
}

Box Box::growDir(int d, int n) const {
  Box b = *this;
  b.lo[d] -= n;
  b.hi[d] += n;
  return b;
}

Box Box::growHi(int d, int n) const {
  Box b = *this;
  b.hi[d] += n;
  return b;
}

Box Box::growLo(int d, int n) const {
  Box b = *this;
  b.lo[d] -= n;
  return b;
}

Box Box::shift(const IntVect& s) const {
  Box b = *this;
  for (int d = 0; d < 3; ++d) {
    b.lo[d] += s[d];
    b.hi[d] += s[d];
  }
  return b;
}

Box Box::surroundingNodes(int dim) const {
  Box b = *this;
  for (int d = 0; d < dim; ++d) b.hi[d] += 1;
  return b;
}

Box operator&(const Box& a, const Box& b) {
  Box r;
  for (int d = 0; d < 3; ++d) {
    r.lo[d] = std::max(a.lo[d], b.lo[d]);
    r.hi[d] = std::min(a.hi[d], b.hi[d]);
  }
  if (!r.ok()) return Box{};
  return r;
}

std::string Box::str() const {
  std::ostringstream os;
  os << *this;
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const Box& b) {
  if (!b.ok()) return os << "[empty]";
  return os << "[(" << b.lo[0] << "," << b.lo[1] << "," << b.lo[2] << ")..(" << b.hi[0] << ","
            << b.hi[1] << "," << b.hi[2] << ")]";
}

}  // namespace mpmice::core
