#pragma once
/// @brief Slope limiters of the second-order advection (scene key ice.limiter): minmod,
/// van_leer, superbee. limitedSlope(dl, dr) returns the limited cell slope from the left and
/// right differences; zero at extrema, so a constant field keeps a zero slope exactly.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mpmice::ice {

enum class Limiter { Minmod, VanLeer, Superbee };

inline Limiter limiterFromName(const std::string& n) {
  if (n == "minmod") return Limiter::Minmod;
  if (n == "van_leer") return Limiter::VanLeer;
  if (n == "superbee") return Limiter::Superbee;
  throw std::invalid_argument("ice.limiter: unknown limiter '" + n + "'; valid names: minmod, van_leer, superbee");
}

/// The limited slope of limiter L (chosen at compile time: the advection's face loops are
/// instantiated per limiter, no switch per face).
template <Limiter L>
inline double limitedSlope(double dl, double dr) {
  if (dl * dr <= 0) return 0.0;
  if constexpr (L == Limiter::Minmod) {
    return std::abs(dl) < std::abs(dr) ? dl : dr;
  } else if constexpr (L == Limiter::VanLeer) {
    return 2.0 * dl * dr / (dl + dr);
  } else {
    const double s = dl > 0 ? 1.0 : -1.0;
    const double a = std::abs(dl), b = std::abs(dr);
    return s * std::max(std::min(2 * a, b), std::min(a, 2 * b));
  }
}

inline double limitedSlope(Limiter l, double dl, double dr) {
  switch (l) {
    case Limiter::Minmod: return limitedSlope<Limiter::Minmod>(dl, dr);
    case Limiter::VanLeer: return limitedSlope<Limiter::VanLeer>(dl, dr);
    case Limiter::Superbee: return limitedSlope<Limiter::Superbee>(dl, dr);
  }
  return 0.0;
}

}  // namespace mpmice::ice
