#include "mpm/material/linear_elastic.h"

#include <cmath>

#include "mpm/material/tensor.h"

namespace mpmice::mpm {

void LinearElastic::updateStress(ParticleSet& p, std::size_t begin, std::size_t end,
                                 double dt) const {
  const double lam = c_.lambda(), twoG = 2.0 * c_.G;
  for (std::size_t i = begin; i < end; ++i) {
    const Mat3 L = loadMat(p.L, i);
    const Sym3 D = symPart(L);
    const Sym3 s = loadStress(p, i);
    const Sym3 spin = jaumannSpin(L, s);
    const double lt = lam * trace(D);
    Sym3 n;
    for (int k = 0; k < 6; ++k) n[k] = s[k] + dt * (twoG * D[k] + (k < 3 ? lt : 0.0) + spin[k]);
    p.work[i] += stressWork(s, n, D, p.vol[i], dt);
    storeStress(p, i, n);
  }
}

}  // namespace mpmice::mpm
