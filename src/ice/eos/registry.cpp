// The one registry of ICE equations of state, keyed by the scene name (eos: type:).
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

#include "ice/eos/eos.h"
#include "ice/eos/external.h"
#include "ice/eos/ideal_gas.h"
#include "ice/eos/jwl.h"
#include "ice/eos/mie_gruneisen.h"
#include "ice/eos/stiffened_gas.h"

namespace mpmice::ice {

double Eos::pressure(double rho, double e) const {
  double p;
  pressure(1, &rho, &e, &p);
  return p;
}
double Eos::density(double p, double e) const {
  double r, d;
  density(1, &p, &e, &r, &d);
  return r;
}
double Eos::soundSpeed2(double rho, double e) const {
  double c2;
  soundSpeed2(1, &rho, &e, &c2);
  return c2;
}
void Eos::pressureFloor(std::size_t n, const double* e, double* pmin) const {
  (void)e;
  for (std::size_t i = 0; i < n; ++i) pmin[i] = -std::numeric_limits<double>::infinity();
}
double Eos::densityFromPT(double p, double T) const {
  double e = cv_ * T;
  double rho = density(p, e);
  for (int it = 0; it < 100 && rho > 0; ++it) {
    const double e2 = energyFromTemperature(rho, T);
    const double r2 = density(p, e2);
    if (!(r2 > 0)) break;
    const bool done = std::abs(r2 - rho) <= 1e-14 * rho;
    rho = r2;
    if (done) break;
  }
  return rho;
}

namespace {

using Maker = std::function<std::unique_ptr<Eos>(const core::ModelSpec&, double)>;

double param(const core::ModelSpec& s, const char* key, bool positive) {
  if (!s.has(key))
    throw std::invalid_argument("eos '" + s.type + "' needs the parameter '" + key + "'" +
                                (s.where.line ? " (" + s.where.str() + ")" : std::string()));
  const double v = s.get(key);
  if (!std::isfinite(v) || (positive && !(v > 0)))
    throw std::invalid_argument("eos '" + s.type + "': parameter '" + key + "' must be " +
                                (positive ? "a positive number" : "finite") + ", got " + std::to_string(v));
  return v;
}

const std::map<std::string, Maker>& registry() {
  static const std::map<std::string, Maker> r = {
      {"ideal_gas",
       [](const core::ModelSpec& s, double cv) {
         const double g = param(s, "gamma", true);
         if (!(g > 1)) throw std::invalid_argument("eos 'ideal_gas': gamma must be > 1, got " + std::to_string(g));
         return std::unique_ptr<Eos>(new IdealGas(g, cv));
       }},
      {"stiffened_gas",
       [](const core::ModelSpec& s, double cv) {
         const double g = param(s, "gamma", true);
         if (!(g > 1)) throw std::invalid_argument("eos 'stiffened_gas': gamma must be > 1, got " + std::to_string(g));
         return std::unique_ptr<Eos>(new StiffenedGas(g, param(s, "p_inf", false), cv));
       }},
      {"mie_gruneisen",
       [](const core::ModelSpec& s, double cv) {
         return std::unique_ptr<Eos>(new MieGruneisen(param(s, "reference_density", true), param(s, "sound_speed", true),
                                                      param(s, "slope", false), param(s, "gruneisen", true),
                                                      param(s, "reference_pressure", false), cv,
                                                      s.has("reference_temperature") ? param(s, "reference_temperature", false) : 0.0));
       }},
      {"jwl",
       [](const core::ModelSpec& s, double cv) {
         return std::unique_ptr<Eos>(new Jwl(param(s, "A", false), param(s, "B", false), param(s, "R1", true),
                                             param(s, "R2", true), param(s, "omega", true),
                                             param(s, "reference_density", true), cv));
       }},
      {"solid_bulk",
       [](const core::ModelSpec& s, double cv) {
         core::SolidBulkEos law(param(s, "bulk_modulus", true), param(s, "threshold_pressure", true),
                                param(s, "reference_density", true));
         return std::unique_ptr<Eos>(new ExternalSolidEos<core::SolidBulkEos>(law, "solid_bulk", cv));
       }},
      {"crush_curve",
       [](const core::ModelSpec& s, double cv) {
         core::FoamCrushParams f;
         f.bulkModulus = param(s, "bulk_modulus", true);
         f.thresholdPressure = param(s, "threshold_pressure", true);
         f.referenceDensity = param(s, "reference_density", true);
         core::FoamHardening& y = f.hardening;
         y.plateau = param(s, "plateau_stress", true);
         y.densification = param(s, "densification_strain", true);
         y.plasticPoisson = param(s, "plastic_poissons_ratio", false);
         y.gamma = param(s, "hardening_gamma", false);
         y.alpha2 = param(s, "hardening_alpha2", false);
         y.beta = param(s, "hardening_beta", true);
         y.denseBulk = param(s, "densified_bulk_modulus", true);
         return std::unique_ptr<Eos>(new ExternalSolidEos<core::FoamCrushCurve>(core::FoamCrushCurve(f), "crush_curve", cv));
       }},
  };
  return r;
}

}  // namespace

const std::vector<std::string>& eosNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [k, v] : registry()) n.push_back(k);
    return n;
  }();
  return names;
}

std::unique_ptr<Eos> makeEos(const core::ModelSpec& spec, double cv) {
  const auto it = registry().find(spec.type);
  if (it == registry().end()) {
    std::string valid;
    for (const auto& n : eosNames()) valid += (valid.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown eos type '" + spec.type + "'" +
                                (spec.where.line ? " at " + spec.where.str() : std::string()) +
                                "; valid names: " + valid);
  }
  if (!(cv > 0)) throw std::invalid_argument("eos '" + spec.type + "': specific_heat must be > 0, got " + std::to_string(cv));
  return it->second(spec, cv);
}

}  // namespace mpmice::ice
