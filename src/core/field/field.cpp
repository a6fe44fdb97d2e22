#include "core/field/field.h"

#include <stdexcept>

namespace mpmice::core {

Field::Field(std::string name, Centering c, const Box& stored, int ncomp, int nghost, double init)
    : name_(std::move(name)), centering_(c), box_(stored), ncomp_(ncomp), nghost_(nghost),
      npts_(stored.numPts()), data_(static_cast<std::size_t>(stored.numPts() * ncomp), init) {
  if (ncomp < 1) throw std::invalid_argument("Field '" + name_ + "': ncomp must be >= 1");
  if (stored.ok()) {
    sy_ = stored.length(0);
    sz_ = sy_ * stored.length(1);
    origin_ = -(stored.lo[0] + sy_ * stored.lo[1] + sz_ * stored.lo[2]);
  }
}

View Field::view(int c) {
  return View{data(c), box_.lo, box_.length(0), std::int64_t(box_.length(0)) * box_.length(1)};
}

ConstView Field::view(int c) const {
  return ConstView{data(c), box_.lo, box_.length(0), std::int64_t(box_.length(0)) * box_.length(1)};
}

void Field::fill(double v, int c) {
  double* p = data(c);
  for (std::int64_t n = 0; n < npts_; ++n) p[n] = v;
}

void Field::copyRegion(const Field& from, const Box& src, const Box& dst) {
  const IntVect off{src.lo[0] - dst.lo[0], src.lo[1] - dst.lo[1], src.lo[2] - dst.lo[2]};
  for (int c = 0; c < ncomp_; ++c) {
    View to = view(c);
    ConstView fr = from.view(c);
    forEach(dst, [&](int i, int j, int k) { to(i, j, k) = fr(i + off[0], j + off[1], k + off[2]); });
  }
}

void Field::pack(const Box& b, std::vector<double>& buf) const {
  for (int c = 0; c < ncomp_; ++c) {
    ConstView v = view(c);
    forEach(b, [&](int i, int j, int k) { buf.push_back(v(i, j, k)); });
  }
}

std::size_t Field::unpack(const Box& b, const double* buf, bool add) {
  std::size_t n = 0;
  for (int c = 0; c < ncomp_; ++c) {
    View v = view(c);
    if (add)
      forEach(b, [&](int i, int j, int k) { v(i, j, k) += buf[n++]; });
    else
      forEach(b, [&](int i, int j, int k) { v(i, j, k) = buf[n++]; });
  }
  return n;
}

}  // namespace mpmice::core
