#include "coupler/mapping/mapping.h"

#include <cmath>
#include <stdexcept>

#include "coupler/mapping/nearest_neighbor.h"
#include "coupler/mapping/rbf.h"

namespace mpmice::coupler {

namespace {
void checkCloud(const PointCloud& c, int dim, const char* which) {
  if (c.size() == 0)
    throw std::invalid_argument(std::string("interface mapping: the ") + which +
                                " point cloud is empty; both sides of the interface need points");
  for (int d = 0; d < dim; ++d) {
    const auto& xd = c.x[static_cast<std::size_t>(d)];
    if (xd.size() != c.size())
      throw std::invalid_argument(std::string("interface mapping: the ") + which +
                                  " point cloud has coordinate arrays of different lengths");
    for (double v : xd)
      if (!std::isfinite(v))
        throw std::invalid_argument(std::string("interface mapping: the ") + which +
                                    " point cloud has a non-finite coordinate");
  }
}
}  // namespace

void Mapping::beginCompute(const PointCloud& source, const PointCloud& target, int dim) {
  computed_ = false;
  nSource_ = nTarget_ = 0;
  if (dim != 2 && dim != 3)
    throw std::invalid_argument("interface mapping: dim must be 2 or 3, got " + std::to_string(dim));
  checkCloud(source, dim, "source");
  checkCloud(target, dim, "target");
  nSource_ = source.size();
  nTarget_ = target.size();
}

void Mapping::checkApply(const double* in, const double* out, int ncomp, const char* what) const {
  if (!computed_)
    throw std::logic_error(std::string(name()) + " mapping: " + what + " before compute()");
  if (ncomp < 1)
    throw std::invalid_argument(std::string(name()) + " mapping: ncomp must be >= 1, got " +
                                std::to_string(ncomp));
  if (in == nullptr || out == nullptr)
    throw std::invalid_argument(std::string(name()) + " mapping: null data pointer");
}

void Mapping::mapConsistent(const double* in, double* out, int ncomp) const {
  checkApply(in, out, ncomp, "mapConsistent");
  applyConsistent(in, out, ncomp);
}

void Mapping::mapConservative(const double* in, double* out, int ncomp) const {
  checkApply(in, out, ncomp, "mapConservative");
  applyConservative(in, out, ncomp);
}

const std::vector<std::string>& mappingNames() {
  static const std::vector<std::string> names{"nearest_neighbor", "rbf"};
  return names;
}

std::unique_ptr<Mapping> makeMapping(core::InterfaceMapping type, double rbfSupport) {
  switch (type) {
    case core::InterfaceMapping::NearestNeighbor: return std::make_unique<NearestNeighbor>();
    case core::InterfaceMapping::Rbf: return std::make_unique<Rbf>(rbfSupport);
  }
  throw std::logic_error("makeMapping: no such mapping");
}

std::unique_ptr<Mapping> makeMapping(const std::string& type, double rbfSupport) {
  if (type == "nearest_neighbor") return std::make_unique<NearestNeighbor>();
  if (type == "rbf") return std::make_unique<Rbf>(rbfSupport);
  std::string valid;
  for (const auto& n : mappingNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown coupling.interface.mapping '" + type + "'; valid: " + valid);
}

}  // namespace mpmice::coupler
