#include "core/scene/model_catalog.h"

#include <algorithm>

namespace mpmice::core::scene_detail {

namespace {

using Need = ParamInfo::Need;

ParamInfo required(std::string name, Range r, std::string doc) {
  return {std::move(name), Need::Required, 0, r, std::move(doc)};
}
ParamInfo optional(std::string name, double fallback, Range r, std::string doc) {
  return {std::move(name), Need::Optional, fallback, r, std::move(doc)};
}
ParamInfo derived(std::string name, Range r, std::string doc) {
  return {std::move(name), Need::Derived, 0, r, std::move(doc)};
}

std::vector<ParamInfo> elasticConstants() {
  return {
      {"youngs_modulus", Need::Elastic, 0, Range::positive(), "Young's modulus E [Pa]"},
      {"poissons_ratio", Need::Elastic, 0, Range::open(-1.0, 0.5), "Poisson's ratio nu"},
      {"bulk_modulus", Need::Elastic, 0, Range::positive(), "bulk modulus K [Pa]"},
      {"shear_modulus", Need::Elastic, 0, Range::positive(), "shear modulus G [Pa]"},
  };
}

TableInfo hardeningTable() {
  return {"hardening", {"plastic_strain", "stress"},
          "flow stress [Pa] against equivalent plastic strain (piecewise linear; strains start at 0 and increase)"};
}

std::vector<ParamInfo> with(std::vector<ParamInfo> a, const std::vector<ParamInfo>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// Exactly one elastic pair given: fill the other pair.
void completeElasticConstants(ModelSpec& m, const YamlMap& map) {
  const bool e = m.has("youngs_modulus"), nu = m.has("poissons_ratio");
  const bool k = m.has("bulk_modulus"), g = m.has("shear_modulus");
  const std::string pairs = "give exactly one pair of elastic constants: (youngs_modulus, "
                            "poissons_ratio) or (bulk_modulus, shear_modulus)";
  std::string given;
  for (const char* key : {"youngs_modulus", "poissons_ratio", "bulk_modulus", "shear_modulus"})
    if (m.has(key)) given += std::string(given.empty() ? "" : ", ") + key;
  if (given.empty()) map.fail(pairs + "; none given");
  if (e && nu && !k && !g) {
    bulkShearFromElastic(m.params["youngs_modulus"], m.params["poissons_ratio"], m.params["bulk_modulus"],
                         m.params["shear_modulus"]);
  } else if (k && g && !e && !nu) {
    elasticFromBulkShear(m.params["bulk_modulus"], m.params["shear_modulus"], m.params["youngs_modulus"],
                         m.params["poissons_ratio"]);
  } else {
    map.fail(pairs + "; got " + given);
  }
}

void readTable(ModelSpec& m, const TableInfo& t, const YamlValue& v) {
  const YamlMap map = v.map();
  map.allow(t.columns);
  std::size_t n = 0;
  for (const auto& col : t.columns) {
    const YamlValue list = map.required(col);
    auto values = list.numbers(Range::nonNegative());
    if (values.empty()) list.fail("expected at least one number");
    if (n != 0 && values.size() != n)
      list.fail("expected " + std::to_string(n) + " numbers (as many as " + t.columns.front() + "), got " +
                std::to_string(values.size()));
    n = values.size();
    m.tables[col] = std::move(values);
  }
  // The first column is the abscissa: starts at 0 and increases.
  const auto& x = m.tables[t.columns.front()];
  const YamlValue xs = map.required(t.columns.front());
  if (x.front() != 0.0) xs.fail("must start at 0, got " + formatNumber(x.front()));
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1])) xs.fail("must increase, but entry " + std::to_string(i) + " (" +
                                    formatNumber(x[i]) + ") is not above the one before");
}

/// j2_plasticity's parameters (cowper_symonds adds its rate constants).
std::vector<ParamInfo> j2Params() {
  return with(elasticConstants(),
              {required("yield_stress", Range::positive(), "initial yield stress [Pa]"),
               optional("hardening_modulus", 0, Range::nonNegative(),
                        "linear isotropic hardening modulus [Pa] (or the `hardening` table)"),
               optional("failure_strain", 0, Range::nonNegative(), "equivalent plastic strain at failure (0 = no failure)")});
}

}  // namespace

std::vector<std::string> ModelInfo::keys() const {
  std::vector<std::string> k{"type"};
  for (const auto& p : params) k.push_back(p.name);
  for (const auto& t : tables) k.push_back(t.key);
  return k;
}

const ModelInfo* ModelFamily::find(const std::string& name) const {
  for (const auto& m : models)
    if (m.name == name) return &m;
  return nullptr;
}

std::vector<std::string> ModelFamily::names() const {
  std::vector<std::string> n;
  for (const auto& m : models) n.push_back(m.name);
  return n;
}

const ModelFamily& constitutiveModels() {
  static const ModelFamily f{
      "constitutive model",
      {
          {"linear_elastic", "small-strain isotropic linear elasticity (Hooke), Jaumann-rate update",
           elasticConstants(), {}},
          {"neo_hookean", "compressible neo-Hookean hyperelasticity", elasticConstants(), {}},
          {"j2_plasticity", "von Mises plasticity with isotropic hardening, radial return",
           j2Params(), {hardeningTable()}},
          {"cowper_symonds",
           "von Mises plasticity whose flow stress is scaled by the Cowper-Symonds factor 1 + (rate/C)^(1/p) "
           "(rate: the equivalent strain rate)",
           with(j2Params(), {required("rate_c", Range::positive(), "Cowper-Symonds C [1/s]"),
                             required("rate_p", Range::positive(), "Cowper-Symonds p")}),
           {hardeningTable()}},
          {"crushable_foam",
           "Deshpande-Fleck crushable foam: elliptic yield surface in mean and von Mises stress, volumetric "
           "hardening to densification",
           with(elasticConstants(),
                {required("plateau_stress", Range::positive(), "plateau (initial) yield stress sigma_p [Pa]"),
                 required("densification_strain", Range::positive(),
                          "densification strain eps_D = -(9 + alpha^2)/(3 alpha^2) ln(rho_foam/rho_solid)"),
                 required("densified_bulk_modulus", Range::positive(),
                          "bulk modulus K_s of the compacted foam (its cell walls' solid) [Pa], at V/V0 <= "
                          "rho_foam/rho_solid"),
                 optional("plastic_poissons_ratio", 0, Range::open(-1.0, 0.5),
                          "plastic Poisson's ratio nu_p (sets alpha)"),
                 optional("hardening_gamma", 0, Range::nonNegative(), "linear hardening gamma [Pa]"),
                 required("hardening_alpha2", Range::positive(), "densification hardening alpha_2 [Pa]"),
                 optional("hardening_beta", 1, Range::positive(), "densification exponent beta")}),
           {}},
      }};
  return f;
}

const ModelFamily& fluidEquationsOfState() {
  static const ModelFamily f{
      "equation of state",
      {
          {"ideal_gas", "p = (gamma - 1) rho e",
           {required("gamma", Range::above(1.0), "ratio of specific heats")}, {}},
          {"stiffened_gas", "p = (gamma - 1) rho e - gamma p_inf",
           {required("gamma", Range::above(1.0), "ratio of specific heats"),
            required("p_inf", Range::nonNegative(), "stiffening pressure [Pa]")},
           {}},
          {"mie_gruneisen", "Mie-Gruneisen with a linear Us-up Hugoniot as reference curve",
           {required("reference_density", Range::positive(), "rho0 [kg/m^3]"),
            required("sound_speed", Range::positive(), "bulk sound speed c0 [m/s]"),
            required("slope", Range::nonNegative(), "Hugoniot slope s (Us = c0 + s up)"),
            required("gruneisen", Range::positive(), "Gruneisen coefficient Gamma0"),
            optional("reference_pressure", 0, Range::any(), "pressure at rho0 [Pa]"),
            optional("reference_temperature", 0, Range::nonNegative(), "temperature of the reference state [K]")},
           {}},
          {"jwl", "Jones-Wilkins-Lee (detonation products)",
           {required("A", Range::positive(), "[Pa]"), required("B", Range::positive(), "[Pa]"),
            required("R1", Range::positive(), "dimensionless"), required("R2", Range::positive(), "dimensionless"),
            required("omega", Range::positive(), "Gruneisen-like coefficient"),
            required("reference_density", Range::positive(), "rho0 [kg/m^3]")},
           {}},
      }};
  return f;
}

const ModelFamily& solidEquationsOfState() {
  static const ModelFamily f{
      "solid equation of state",
      {
          {"solid_bulk",
           "bulk-modulus law p = p_ref + K/2 (rho/rho0 - rho0/rho) above the threshold pressure p_ref, "
           "a smooth power-law tension branch below it (seed paper; src/core/material/solid_bulk_eos.h)",
           {derived("bulk_modulus", Range::positive(), "bulk modulus K [Pa] (default: the model's)"),
            optional("threshold_pressure", 101325.0, Range::positive(),
                     "pressure below which the tension branch applies [Pa]"),
            derived("reference_density", Range::positive(),
                    "rho0 [kg/m^3] (default: the material density)")},
           {}},
          {"crush_curve",
           "a crushable foam's hydrostatic crush curve: elastic with K to the plateau, the model's hardening "
           "to full density V/V0 = J_d, then the compacted solid's bulk modulus; solid_bulk's tension branch "
           "below the threshold pressure (crushable_foam solids only; "
           "src/core/material/foam_crush_curve.h)",
           {derived("bulk_modulus", Range::positive(), "bulk modulus K [Pa] (default: the model's)"),
            optional("threshold_pressure", 101325.0, Range::positive(),
                     "pressure at which the foam is stress-free; the tension branch below it [Pa]"),
            derived("reference_density", Range::positive(), "rho0 [kg/m^3] (default: the material density)"),
            derived("plateau_stress", Range::positive(), "sigma_p [Pa] (default: the model's)"),
            derived("densification_strain", Range::positive(), "eps_D (default: the model's)"),
            derived("plastic_poissons_ratio", Range::open(-1.0, 0.5), "nu_p (default: the model's)"),
            derived("hardening_gamma", Range::nonNegative(), "gamma [Pa] (default: the model's)"),
            derived("hardening_alpha2", Range::nonNegative(), "alpha_2 [Pa] (default: the model's)"),
            derived("hardening_beta", Range::positive(), "beta (default: the model's)"),
            derived("densified_bulk_modulus", Range::positive(), "K_s [Pa] (default: the model's)")},
           {}},
      }};
  return f;
}

const ModelFamily& cavitationModels() {
  static const ModelFamily f{
      "cavitation model",
      {
          {"pressure_cutoff",
           "one-fluid cavitation: the liquid's pressure does not fall below the cut-off; below the density "
           "where its EOS reaches it the cell opens a cavity at that pressure (docs/ice.md \"Cavitation\")",
           {required("pressure", Range::any(),
                     "cut-off pressure p_c [Pa]: the vapour pressure (~2.3e3 for water at 20 C), 0, or a "
                     "tensile limit (< 0); below the liquid's initial pressure")},
           {}},
      }};
  return f;
}

ModelSpec readModel(const YamlValue& v, const ModelFamily& family) {
  if (v.isScalar())
    v.fail("expected a mapping with the " + family.noun + " and its parameters, such as {type: " +
           (family.find(v.node().Scalar()) ? v.node().Scalar() : family.models.front().name) +
           ", ...}; got " + v.shown());
  const YamlMap map = v.map();
  ModelSpec m;
  m.where = v.loc();
  m.type = map.required("type").choice(family.names(), family.noun);
  const ModelInfo& info = *family.find(m.type);
  map.allow(info.keys());
  bool elastic = false;
  for (const auto& p : info.params) {
    const auto value = map.get(p.name);
    if (value) {
      m.params[p.name] = value->number(p.range);
    } else if (p.need == Need::Required) {
      map.fail("missing required parameter '" + p.name + "' of " + family.noun + " '" + m.type + "' (" +
               p.doc + ", " + p.range.describe() + ")");
    } else if (p.need == Need::Optional) {
      m.params[p.name] = p.fallback;
    }
    elastic = elastic || p.need == Need::Elastic;
  }
  for (const auto& t : info.tables)
    if (const auto value = map.get(t.key)) readTable(m, t, *value);
  if (elastic) completeElasticConstants(m, map);
  // j2_plasticity: a hardening table replaces the hardening modulus.
  if (!m.tables.empty() && map.has("hardening_modulus"))
    map.required("hardening_modulus").fail("give either hardening_modulus or the hardening table, not both");
  if (!m.tables.empty()) m.params.erase("hardening_modulus");
  return m;
}

void completeSolidEos(ModelSpec& eos, const ModelSpec& constitutive, double density) {
  if (eos.type.empty()) {
    eos.type = "solid_bulk";
    eos.where = constitutive.where;
  }
  // A derived parameter the scene leaves out is the material density (reference_density) or the
  // constitutive model's parameter of the same name (bulk_modulus; crush_curve's hardening keys).
  const ModelInfo& info = *solidEquationsOfState().find(eos.type);
  for (const auto& p : info.params) {
    if (eos.has(p.name)) continue;
    if (p.need == Need::Optional) eos.params[p.name] = p.fallback;
    else if (p.name == "reference_density") eos.params[p.name] = density;
    else if (p.need == Need::Derived && constitutive.has(p.name)) eos.params[p.name] = constitutive.get(p.name);
  }
}

void elasticFromBulkShear(double K, double G, double& E, double& nu) {
  E = 9.0 * K * G / (3.0 * K + G);
  nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
}

void bulkShearFromElastic(double E, double nu, double& K, double& G) {
  K = E / (3.0 * (1.0 - 2.0 * nu));
  G = E / (2.0 * (1.0 + nu));
}

}  // namespace mpmice::core::scene_detail
