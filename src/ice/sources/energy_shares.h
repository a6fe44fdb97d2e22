#pragma once
/// @brief Giving a cell's energy correction to its materials without draining a fluid.
///
/// The Lagrangian phase's correction (the flux form's p dV work less what the materials took) is
/// given to a cell's materials in shares (lagrangian_phase.cpp); in a cell with a solid and a
/// momentum exchange it is given after the exchange, together with the drag heat (exchange_phase.cpp,
/// "deferred correction"). A fluid refuses a share that would take its thermal energy e - e_cold
/// below kMinEnergyShare of what it had, or any negative share once it is at or below its cold
/// energy; what fluids refuse goes to the fluids that took theirs, by heat capacity; what none of
/// them can take is returned (the caller audits it: it is not conserved). An external material (a
/// solid) takes its share whole: its own solver's energy (dEn).
#include <cmath>

#include "ice/ice_constants.h"

namespace mpmice::ice {

/// One material of one cell as the shares see it.
struct ShareTaker {
  double mass = 0, cv = 0;
  double* e = nullptr;     // its specific internal energy (the Lagrangian one), updated
  double cold = 0;         // its cold energy at its Lagrangian volume (0 without one, or absent; a
                           // Mie-Gruneisen liquid with a reference temperature T0 has e = 0 at T0:
                           // e < 0 is a state below T0, not below 0 K)
  bool external = false;   // a solid: takes its share whole
  double* dEn = nullptr;   // external: its exchange energy [J], the share added
};

struct SharesGiven {
  double lost = 0;    // [J] what no fluid could take
  int refused = 0;    // the shares refused (each a fallback)
  int worst = -1;     // the material with the largest refused share
};

/// Gives share[r] [J] to material r of the n in `t`.
inline SharesGiven giveShares(int n, const ShareTaker* t, const double* share) {
  auto give = [&](int r, double s) {
    const ShareTaker& T = t[r];
    const double e0 = *T.e;
    const double e1 = T.mass > 0 ? e0 + s / T.mass : e0;
    if (e0 - T.cold > 0 && e1 - T.cold < kMinEnergyShare * (e0 - T.cold)) return false;
    if (!(e0 - T.cold > 0) && s < 0) return false;  // at or below its cold energy already: no further drain
    *T.e = e1;
    return true;
  };
  SharesGiven g;
  double left = 0, leftMax = 0;
  unsigned took = 0;  // the fluids that took theirs (bit r)
  for (int r = 0; r < n; ++r) {
    const ShareTaker& T = t[r];
    if (T.external) {
      if (T.mass > 0) {
        *T.e += share[r] / T.mass;
        *T.dEn += share[r];
      }
      continue;
    }
    if (give(r, share[r])) {
      took |= 1u << r;
    } else {
      ++g.refused;
      left += share[r];
      if (std::abs(share[r]) > leftMax) leftMax = std::abs(share[r]), g.worst = r;
    }
  }
  if (left == 0) return g;
  double Cf = 0;
  for (int r = 0; r < n; ++r)
    if (took >> r & 1u) Cf += t[r].mass * t[r].cv;
  if (!(Cf > 0)) {
    g.lost = left;
    return g;
  }
  for (int r = 0; r < n; ++r)
    if (took >> r & 1u) {
      const double s2 = t[r].mass * t[r].cv / Cf * left;
      if (!give(r, s2)) g.lost += s2;
    }
  return g;
}

}  // namespace mpmice::ice
