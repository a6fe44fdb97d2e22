#pragma once
/// @brief The constitutive-model family: a tiny interface updating the stress of a whole range
/// of particles of one material, and the one registry that builds a model from its scene name.
///
/// Virtual dispatch happens once per material per step, never per particle. Before the call the
/// solver has set each particle's velocity gradient L (for this step), its new deformation
/// gradient F = (I + dt L) F_old and its new volume V = V0 det F. A model updates the Cauchy
/// stress (and its history: plastic strain, failure) and adds the step's stress work to `work`
/// (midpoint rule; with mpm.stress_work grid the solver replaces it by the work the particle's
/// internal force did on the nodes, MpmSolver::addStressWork).
///
/// Scene names: linear_elastic, neo_hookean, j2_plasticity, cowper_symonds (j2_plasticity.h),
/// crushable_foam (parameters: see each header).
/// An unknown name is an error listing the valid names.
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "mpm/material/signal_speed.h"
#include "mpm/particles/particle_set.h"
#include "core/scene/scene.h"

namespace mpmice::mpm {

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;
  [[nodiscard]] virtual const char* name() const = 0;
  /// Whether the model keeps a plastic history (the particle columns eqps and failed).
  [[nodiscard]] virtual bool plasticHistory() const { return false; }
  /// Stress update of particles [begin, end) over dt.
  virtual void updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const = 0;
  /// Dilatational (P-) wave speed at density rho, for the time step.
  [[nodiscard]] virtual double waveSpeed(double rho) const = 0;
  /// The CFL signal speed of particles [begin, end): max of waveSpeed(m / V) + |v| (the first `dim`
  /// velocity components), 0 if the range is empty; `*arg` (when asked for) the first particle
  /// reaching it (end if none). One virtual call per material: ElasticWaveModel implements it with
  /// maxSignalSpeedOver().
  [[nodiscard]] virtual double maxSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim,
                                              std::size_t* arg = nullptr) const = 0;
};

/// Elastic constants read from a ModelSpec (bulk_modulus and shear_modulus, or youngs_modulus and
/// poissons_ratio); `what` names the material in errors.
struct ElasticConstants {
  double K = 0, G = 0;
  [[nodiscard]] double lambda() const { return K - 2.0 * G / 3.0; }
  /// The P-wave modulus K + 4 G / 3.
  [[nodiscard]] double pWaveModulus() const { return K + 4.0 * G / 3.0; }
  /// The P-wave speed sqrt((K + 4 G / 3) / rho).
  [[nodiscard]] double pWaveSpeed(double rho) const { return std::sqrt(pWaveModulus() / rho); }
  static ElasticConstants fromSpec(const core::ModelSpec& spec, const std::string& what);
};

/// A model whose CFL wave speed is the P-wave speed of its elastic constants: waveSpeed and
/// maxSignalSpeed (the loop with the speed inlined) written once for every such model.
class ElasticWaveModel : public ConstitutiveModel {
 public:
  explicit ElasticWaveModel(const ElasticConstants& c) : c_(c) {}
  [[nodiscard]] double waveSpeed(double rho) const final { return c_.pWaveSpeed(rho); }
  [[nodiscard]] double maxSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim,
                                      std::size_t* arg = nullptr) const final {
    return maxElasticSignalSpeed(p, begin, end, dim, arg, c_.pWaveModulus());
  }
  [[nodiscard]] const ElasticConstants& constants() const { return c_; }

 protected:
  ElasticConstants c_;
};

/// A parameter of a ModelSpec; missing -> std::invalid_argument naming model and key.
double modelParam(const core::ModelSpec& spec, const std::string& key, const std::string& what);
double modelParam(const core::ModelSpec& spec, const std::string& key, double fallback);

/// Valid scene names, in registry order.
const std::vector<std::string>& constitutiveModelNames();
/// Builds the model named spec.type; `what` names the material for errors.
std::unique_ptr<ConstitutiveModel> createConstitutiveModel(const core::ModelSpec& spec,
                                                           const std::string& what);

}  // namespace mpmice::mpm
