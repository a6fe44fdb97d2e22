#pragma once
/// @brief Interface mapping of surface coupling: moves data between two point clouds that do not
/// coincide (an MPM solid's surface particles and an OpenFOAM patch's face centres or points).
///
/// compute() builds, once, a linear map M from source values to target values (size nTarget x
/// nSource). Two directions use it:
///   consistent    (displacements)  u_T = M u_S      values at targets interpolate the sources
///   conservative  (forces)         f_S = M^T f_T    quantities at targets are distributed to the
///                                                   sources; keeps the total when M reproduces
///                                                   constants, the total moment when M reproduces
///                                                   linear fields
/// Values are interleaved, ncomp per point: in[i * ncomp + c].
/// Families, chosen by name in the scene's coupling.interface.mapping:
///   nearest_neighbor  each target takes its nearest source point (ties: the lower source index)
///   rbf               radial basis functions plus a linear polynomial; coupling.interface.rbf_support
///                     0 = thin-plate spline (global), R > 0 = Wendland C2 with support radius R
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "coupler/mapping/point_cloud.h"
#include "core/scene/options.h"

namespace mpmice::coupler {

class Mapping {
 public:
  virtual ~Mapping() = default;
  /// Builds M from the first dim (2 or 3) coordinates of the clouds; coordinates beyond dim are
  /// ignored. Throws std::invalid_argument for an empty cloud, a bad dim or non-finite coordinates.
  virtual void compute(const PointCloud& source, const PointCloud& target, int dim) = 0;
  /// in: nSource x ncomp source values; out: nTarget x ncomp target values (out = M in).
  void mapConsistent(const double* in, double* out, int ncomp) const;
  /// in: nTarget x ncomp target quantities; out: nSource x ncomp source quantities (out = M^T in).
  void mapConservative(const double* in, double* out, int ncomp) const;
  [[nodiscard]] virtual const char* name() const = 0;
  [[nodiscard]] std::size_t sourceSize() const { return nSource_; }
  [[nodiscard]] std::size_t targetSize() const { return nTarget_; }
  [[nodiscard]] bool computed() const { return computed_; }

 protected:
  /// Validates the clouds and dim for compute(), records the sizes and marks M as not built.
  void beginCompute(const PointCloud& source, const PointCloud& target, int dim);
  /// compute() built M.
  void endCompute() { computed_ = true; }

 private:
  // One call per map; the loops over points live in the implementations.
  virtual void applyConsistent(const double* in, double* out, int ncomp) const = 0;
  virtual void applyConservative(const double* in, double* out, int ncomp) const = 0;
  void checkApply(const double* in, const double* out, int ncomp, const char* what) const;

  std::size_t nSource_ = 0;
  std::size_t nTarget_ = 0;
  bool computed_ = false;
};

/// Creates a mapping by its scene name; rbfSupport is used by "rbf" (0: thin-plate spline, > 0:
/// Wendland C2 support radius). An unknown name throws std::invalid_argument listing the valid names.
std::unique_ptr<Mapping> makeMapping(const std::string& type, double rbfSupport);
/// The same, for the scene's parsed choice.
std::unique_ptr<Mapping> makeMapping(core::InterfaceMapping type, double rbfSupport);
const std::vector<std::string>& mappingNames();

}  // namespace mpmice::coupler
