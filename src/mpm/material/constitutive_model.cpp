#include "mpm/material/constitutive_model.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "core/scene/model_catalog.h"
#include "mpm/material/crushable_foam.h"
#include "mpm/material/j2_plasticity.h"
#include "mpm/material/linear_elastic.h"
#include "mpm/material/neo_hookean.h"

namespace mpmice::mpm {

double modelParam(const core::ModelSpec& spec, const std::string& key, const std::string& what) {
  auto it = spec.params.find(key);
  if (it == spec.params.end())
    throw std::invalid_argument(what + ": constitutive model '" + spec.type + "' needs parameter '" +
                                key + "', which the scene does not give");
  return it->second;
}

double modelParam(const core::ModelSpec& spec, const std::string& key, double fallback) {
  auto it = spec.params.find(key);
  return it == spec.params.end() ? fallback : it->second;
}

ElasticConstants ElasticConstants::fromSpec(const core::ModelSpec& spec, const std::string& what) {
  ElasticConstants c;
  if (spec.params.count("bulk_modulus") && spec.params.count("shear_modulus")) {
    c.K = modelParam(spec, "bulk_modulus", what);
    c.G = modelParam(spec, "shear_modulus", what);
  } else {
    const double E = modelParam(spec, "youngs_modulus", what);
    const double nu = modelParam(spec, "poissons_ratio", what);
    if (!(nu > -1.0 && nu < 0.5))
      throw std::invalid_argument(what + ": poissons_ratio must lie in (-1, 0.5), got " +
                                  std::to_string(nu));
    c.K = E / (3.0 * (1.0 - 2.0 * nu));
    c.G = E / (2.0 * (1.0 + nu));
  }
  if (!(c.K > 0) || !(c.G > 0))
    throw std::invalid_argument(what + ": bulk and shear moduli must be > 0 (got K = " +
                                std::to_string(c.K) + ", G = " + std::to_string(c.G) + ")");
  // The constants the models and the scene derive from K and G must exist as numbers too: moduli
  // near the largest double overflow them (K = 1e308 gives E = inf / inf).
  double E = 0, nu = 0;
  core::scene_detail::elasticFromBulkShear(c.K, c.G, E, nu);
  const double derived[4] = {E, nu, c.lambda(), c.K + 4.0 * c.G / 3.0};
  const char* names[4] = {"Young's modulus", "Poisson's ratio", "Lame's first parameter", "P-wave modulus K + 4G/3"};
  for (int d = 0; d < 4; ++d)
    if (!std::isfinite(derived[d])) {
      std::ostringstream os;
      os << what << ": the elastic constants K = " << c.K << " Pa, G = " << c.G << " Pa give a " << names[d]
         << " of " << derived[d] << "; expected finite elastic constants (moduli in Pa, far below 1e308)";
      throw std::invalid_argument(os.str());
    }
  return c;
}

namespace {

using Factory = std::function<std::unique_ptr<ConstitutiveModel>(const core::ModelSpec&,
                                                                 const std::string&)>;
struct Entry {
  const char* name;
  Factory make;
};

/// j2_plasticity and cowper_symonds: linear hardening or the hardening table, failure strain.
std::unique_ptr<J2Plasticity> makeJ2(const core::ModelSpec& s, const std::string& w) {
  std::vector<double> te, ts;
  if (auto it = s.tables.find("plastic_strain"); it != s.tables.end()) te = it->second;
  if (auto it = s.tables.find("stress"); it != s.tables.end()) ts = it->second;
  const double sy = te.empty() ? modelParam(s, "yield_stress", w) : modelParam(s, "yield_stress", 0.0);
  return std::make_unique<J2Plasticity>(ElasticConstants::fromSpec(s, w), sy, modelParam(s, "hardening_modulus", 0.0),
                                        modelParam(s, "failure_strain", 0.0), te, ts);
}

// The one registry of constitutive models, keyed by scene name.
const std::vector<Entry>& registry() {
  static const std::vector<Entry> r = {
      {"linear_elastic",
       [](const core::ModelSpec& s, const std::string& w) {
         return std::unique_ptr<ConstitutiveModel>(
             std::make_unique<LinearElastic>(ElasticConstants::fromSpec(s, w)));
       }},
      {"neo_hookean",
       [](const core::ModelSpec& s, const std::string& w) {
         return std::unique_ptr<ConstitutiveModel>(
             std::make_unique<NeoHookean>(ElasticConstants::fromSpec(s, w)));
       }},
      {"j2_plasticity",
       [](const core::ModelSpec& s, const std::string& w) {
         return std::unique_ptr<ConstitutiveModel>(makeJ2(s, w));
       }},
      {"cowper_symonds",
       [](const core::ModelSpec& s, const std::string& w) {
         auto m = makeJ2(s, w);
         m->setRateDependence(modelParam(s, "rate_c", w), modelParam(s, "rate_p", w));
         return std::unique_ptr<ConstitutiveModel>(std::move(m));
       }},
      {"crushable_foam",
       [](const core::ModelSpec& s, const std::string& w) {
         CrushableFoamParams f;
         f.plateau = modelParam(s, "plateau_stress", w);
         f.densification = modelParam(s, "densification_strain", w);
         f.plasticPoisson = modelParam(s, "plastic_poissons_ratio", 0.0);
         f.gamma = modelParam(s, "hardening_gamma", 0.0);
         f.alpha2 = modelParam(s, "hardening_alpha2", w);
         f.beta = modelParam(s, "hardening_beta", 1.0);
         f.denseBulk = modelParam(s, "densified_bulk_modulus", w);
         return std::unique_ptr<ConstitutiveModel>(std::make_unique<CrushableFoam>(ElasticConstants::fromSpec(s, w), f));
       }},
  };
  return r;
}

}  // namespace

const std::vector<std::string>& constitutiveModelNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& e : registry()) n.emplace_back(e.name);
    return n;
  }();
  return names;
}

std::unique_ptr<ConstitutiveModel> createConstitutiveModel(const core::ModelSpec& spec,
                                                           const std::string& what) {
  for (const auto& e : registry())
    if (spec.type == e.name) return e.make(spec, what);
  std::string valid;
  for (const auto& n : constitutiveModelNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument(what + ": unknown constitutive model '" + spec.type +
                              "'; valid choices: " + valid);
}

}  // namespace mpmice::mpm
