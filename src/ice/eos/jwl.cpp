#include "ice/eos/jwl.h"

#include <cmath>

namespace mpmice::ice {

void Jwl::cold(double rho, double* pc, double* dpc) const {
  const double V = rho0_ / rho;
  const double ea = std::exp(-R1_ * V), eb = std::exp(-R2_ * V);
  const double ta = 1.0 - w_ / (R1_ * V), tb = 1.0 - w_ / (R2_ * V);
  *pc = A_ * ta * ea + B_ * tb * eb;
  // d/dV of A (1 - w/(R1 V)) exp(-R1 V) = A exp(-R1 V) (w/(R1 V^2) - R1 (1 - w/(R1 V)))
  const double dpdV = A_ * ea * (w_ / (R1_ * V * V) - R1_ * ta) + B_ * eb * (w_ / (R2_ * V * V) - R2_ * tb);
  *dpc = dpdV * (-V / rho);
}

void Jwl::eval(double rho, double e, double* p, double* dpdrho) const {
  double pc, dpc;
  cold(rho, &pc, &dpc);
  *p = pc + w_ * rho * e;
  *dpdrho = dpc + w_ * e;
}

double Jwl::coldEnergy(double rho) const {
  const double V = rho0_ / rho;
  return A_ / (R1_ * rho0_) * std::exp(-R1_ * V) + B_ / (R2_ * rho0_) * std::exp(-R2_ * V);
}

double Jwl::internalEnergy(double rho, double p) const {
  double pc, dpc;
  cold(rho, &pc, &dpc);
  return (p - pc) / (w_ * rho);
}

}  // namespace mpmice::ice
