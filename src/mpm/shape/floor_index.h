#pragma once
/// @brief floor() of a grid coordinate as an int, without the library call.
///
/// The x86-64 baseline has no rounding instruction (SSE4.1's roundsd), so std::floor compiles to
/// a sequence of about ten instructions per call; the shape functions take one per direction per
/// particle per stencil evaluation. Truncation corrected by one below zero gives the same integer
/// for every finite x within int's range (the grid coordinates of particles on the mesh), so the
/// shape functions' weights keep their bits.

namespace mpmice::mpm {

/// The largest integer not above x, for finite x with |x| < 2^31.
inline int floorIndex(double x) {
  const int t = static_cast<int>(x);  // truncates towards zero
  return x < static_cast<double>(t) ? t - 1 : t;
}

}  // namespace mpmice::mpm
