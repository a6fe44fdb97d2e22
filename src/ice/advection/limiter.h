#pragma once
/// @brief Slope limiters of the second-order advection (scene key ice.limiter): minmod,
/// van_leer, superbee. limitedSlope(dl, dr) returns the limited cell slope from the left and
/// right differences; zero at extrema, so a constant field keeps a zero slope exactly.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "ice/state/lanes.h"

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

/// limitedSlope<L> at four faces (the lanes, lanes.h): the same operations, the branches selects
/// (std::min(a, b) is b < a ? b : a, std::max(a, b) a < b ? b : a).
template <Limiter L>
inline lanes::v4d limitedSlopeLanes(lanes::v4d dl, lanes::v4d dr) {
  using lanes::sel, lanes::splat;
  lanes::v4d s;
  if constexpr (L == Limiter::Minmod) {
    s = sel(lanes::abs(dl) < lanes::abs(dr), dl, dr);
  } else if constexpr (L == Limiter::VanLeer) {
    s = 2.0 * dl * dr / (dl + dr);
  } else {
    const lanes::v4d sg = sel(dl > 0, splat(1.0), splat(-1.0));
    const lanes::v4d a = lanes::abs(dl), b = lanes::abs(dr);
    const lanes::v4d a2 = 2 * a, b2 = 2 * b;
    const lanes::v4d m1 = sel(b < a2, b, a2), m2 = sel(b2 < a, b2, a);  // min(2a, b), min(a, 2b)
    s = sg * sel(m1 < m2, m2, m1);
  }
  return sel(dl * dr <= 0, splat(0.0), s);
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
