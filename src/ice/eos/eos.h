#pragma once
/// @brief The equation-of-state interface of ICE materials, evaluated over whole arrays.
///
/// Every material has one Eos, chosen by its scene name through makeEos() (registry.cpp):
/// ideal_gas, stiffened_gas, mie_gruneisen, jwl, and solid_bulk for external (solid) materials.
/// The batch calls take n entries and are called once per material per sweep, so there is no
/// virtual call per cell. Quantities: rho = material (micro) density, e = specific internal
/// energy, p = pressure. density() inverts pressure() at fixed e and returns rho <= 0 where p
/// lies below the range the EOS can reach (the equilibrium-pressure bracket uses that).
/// Temperature: T = (e - e_cold(rho)) / cv; e_cold is zero for the ideal gas (stiffened gas: p_inf / rho;
/// Mie-Grueneisen: -cv T0; JWL: the energy of its exponential cold terms).
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::ice {

class Eos {
 public:
  explicit Eos(double cv) : cv_(cv) {}
  virtual ~Eos() = default;

  [[nodiscard]] virtual const char* name() const = 0;
  /// p(rho, e).
  virtual void pressure(std::size_t n, const double* rho, const double* e, double* p) const = 0;
  /// rho(p, e) and d rho / d p at fixed e (rho <= 0: p out of range).
  virtual void density(std::size_t n, const double* p, const double* e, double* rho,
                       double* drhodp) const = 0;
  /// Isentropic sound speed squared c^2(rho, e).
  virtual void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const = 0;
  /// e(rho, p).
  [[nodiscard]] virtual double internalEnergy(double rho, double p) const = 0;
  /// The admissible pressures at fixed specific internal energy e form the open interval
  /// (pmin, inf): pmin per entry (-inf where the law has no lower end; +inf where no state with
  /// this e is admissible, e.g. e <= 0 for an ideal gas). The equilibrium pressure never leaves it.
  virtual void pressureFloor(std::size_t n, const double* e, double* pmin) const;
  /// Part of e that does not depend on temperature (e = cv T + coldEnergy(rho)).
  [[nodiscard]] virtual double coldEnergy(double /*rho*/) const { return 0.0; }
  /// Whether coldEnergy is not identically zero (the thermal-energy guards then subtract it).
  [[nodiscard]] virtual bool hasColdEnergy() const { return false; }

  /// Cavitation (docs/ice.md "Cavitation", a fluid's `cavitation: {model: pressure_cutoff}`): the
  /// cut-off p_c below which the liquid's pressure does not fall (-inf: none). The law above is
  /// unchanged; the equilibrium pressure (EquilibriumPressure) applies the cut-off: at p = p_c the
  /// liquid's density may fall below the density where its law reaches p_c (the cell opens a
  /// cavity), with zero sound speed (infinite compressibility) while it does.
  [[nodiscard]] double cavitationPressure() const { return pCav_; }
  [[nodiscard]] bool cavitates() const { return pCav_ > -std::numeric_limits<double>::infinity(); }
  void setCavitationPressure(double pc) { pCav_ = pc; }

  [[nodiscard]] double cv() const { return cv_; }
  [[nodiscard]] double temperature(double rho, double e) const { return (e - coldEnergy(rho)) / cv_; }
  [[nodiscard]] double energyFromTemperature(double rho, double T) const { return cv_ * T + coldEnergy(rho); }
  /// Scalar conveniences.
  [[nodiscard]] double pressure(double rho, double e) const;
  [[nodiscard]] double density(double p, double e) const;
  [[nodiscard]] double soundSpeed2(double rho, double e) const;
  /// Density at pressure p and temperature T (fixed point on rho = density(p, e(rho, T))).
  [[nodiscard]] double densityFromPT(double p, double T) const;

 private:
  double cv_;
  double pCav_ = -std::numeric_limits<double>::infinity();
};

/// Builds the EOS named spec.type with spec's parameters (throws std::invalid_argument naming
/// the valid EOS names when the name is unknown, or the missing / bad parameter).
std::unique_ptr<Eos> makeEos(const core::ModelSpec& spec, double cv);
/// The names makeEos() accepts.
const std::vector<std::string>& eosNames();

/// Solves p(rho) = target for rho > 0 with a safeguarded Newton iteration on an increasing
/// pressure law; pdp(rho, &p, &dpdrho). Used by EOS without a closed-form inverse.
/// rhoMax: the law's largest density (p -> inf there; infinity when it has none).
template <class PDp>
double invertPressure(double target, double guess, PDp&& pdp, double rhoMax);

}  // namespace mpmice::ice

#include "ice/eos/invert_pressure.h"
