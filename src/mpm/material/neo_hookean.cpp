#include "mpm/material/neo_hookean.h"

#include <cmath>

#include "mpm/material/tensor.h"

namespace mpmice::mpm {

void NeoHookean::updateStress(ParticleSet& p, std::size_t begin, std::size_t end,
                              double dt) const {
  const double lam = c_.lambda(), G = c_.G;
  for (std::size_t i = begin; i < end; ++i) {
    const Mat3 F = loadF(p, i);
    const double J = det(F);
    const double invJ = 1.0 / J;
    // b = F F^T (symmetric).
    auto bij = [&](int a, int b) {
      return F[3 * a] * F[3 * b] + F[3 * a + 1] * F[3 * b + 1] + F[3 * a + 2] * F[3 * b + 2];
    };
    const double pr = lam * std::log(J) * invJ;
    const Sym3 n = {G * invJ * (bij(0, 0) - 1.0) + pr, G * invJ * (bij(1, 1) - 1.0) + pr,
                    G * invJ * (bij(2, 2) - 1.0) + pr, G * invJ * bij(0, 1),
                    G * invJ * bij(1, 2), G * invJ * bij(0, 2)};
    const Sym3 s = loadStress(p, i);
    p.work[i] += stressWork(s, n, symPart(loadL(p, i)), p.vol[i], dt);
    storeStress(p, i, n);
  }
}

}  // namespace mpmice::mpm
