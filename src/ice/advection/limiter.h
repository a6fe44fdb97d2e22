#pragma once
/// @brief Slope limiters of the second-order advection (scene key ice.limiter): minmod,
/// van_leer, superbee. limitedSlope(dl, dr) returns the limited cell slope from the left and
/// right differences; zero at extrema, so a constant field keeps a zero slope exactly.
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

inline double limitedSlope(Limiter l, double dl, double dr) {
  if (dl * dr <= 0) return 0.0;
  switch (l) {
    case Limiter::Minmod: return std::abs(dl) < std::abs(dr) ? dl : dr;
    case Limiter::VanLeer: return 2.0 * dl * dr / (dl + dr);
    case Limiter::Superbee: {
      const double s = dl > 0 ? 1.0 : -1.0;
      const double a = std::abs(dl), b = std::abs(dr);
      return s * std::max(std::min(2 * a, b), std::min(a, 2 * b));
    }
  }
  return 0.0;
}

}  // namespace mpmice::ice
