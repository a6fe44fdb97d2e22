#pragma once
/// @brief The one list of every model family a scene can name, with each model's parameters.
///
/// Three families: solid constitutive models (`model.type`), fluid equations of state
/// (`eos.type` of a fluid) and solid equations of state (`eos.type` of a solid). Each model lists
/// its parameters with whether they are required, their default and valid range, and a one-line
/// description; the solvers read exactly these names from ModelSpec::params. readModel() checks a
/// scene's model mapping against this list (unknown names list the valid ones, unknown keys get a
/// "did you mean", missing parameters are named) and fills defaults. docs/scene-reference.md
/// documents the same list (a unit test checks that every name appears there).
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "core/scene/yaml_reader.h"

namespace mpmice::core::scene_detail {

struct ParamInfo {
  enum class Need {
    Required,  // must be given
    Optional,  // `fallback` when absent
    Derived,   // filled from elsewhere in the scene when absent (see completeSolidEos)
    Elastic,   // one of the two elastic pairs: (youngs_modulus, poissons_ratio) or (bulk_modulus, shear_modulus)
  };
  std::string name;
  Need need = Need::Required;
  double fallback = 0;
  Range range;
  std::string doc;
};

/// A table parameter: a mapping of equally long number lists (e.g. hardening curve).
struct TableInfo {
  std::string key;
  std::vector<std::string> columns;  // stored in ModelSpec::tables under these names
  std::string doc;
};

struct ModelInfo {
  std::string name;
  std::string doc;
  std::vector<ParamInfo> params;
  std::vector<TableInfo> tables;
  /// Keys its scene mapping may hold: "type", the parameters and the tables.
  [[nodiscard]] std::vector<std::string> keys() const;
};

struct ModelFamily {
  std::string noun;  // in errors: "unknown <noun> 'x'"
  std::vector<ModelInfo> models;
  [[nodiscard]] const ModelInfo* find(const std::string& name) const;
  [[nodiscard]] std::vector<std::string> names() const;
};

const ModelFamily& constitutiveModels();     // linear_elastic, neo_hookean, j2_plasticity
const ModelFamily& fluidEquationsOfState();  // ideal_gas, stiffened_gas, mie_gruneisen, jwl
const ModelFamily& solidEquationsOfState();  // solid_bulk
const ModelFamily& cavitationModels();       // pressure_cutoff (a fluid's `cavitation:`)

/// Reads a model mapping `{type: name, param: value, ...}` of `family`; fills defaults and, for
/// models with elastic constants, all four of them. Derived parameters stay absent.
ModelSpec readModel(const YamlValue& v, const ModelFamily& family);

/// Fills a solid EOS's derived parameters: bulk_modulus from the constitutive model and
/// reference_density from the material density, when the scene did not give them.
void completeSolidEos(ModelSpec& eos, const ModelSpec& constitutive, double density);

/// Young's modulus and Poisson's ratio from bulk and shear moduli, and back.
void elasticFromBulkShear(double K, double G, double& E, double& nu);
void bulkShearFromElastic(double E, double nu, double& K, double& G);

}  // namespace mpmice::core::scene_detail
