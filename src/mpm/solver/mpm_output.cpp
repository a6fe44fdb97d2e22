#include "mpm/solver/mpm_output.h"

#include <algorithm>
#include <span>
#include <stdexcept>

namespace mpmice::mpm {

const std::vector<std::string>& MpmOutput::fieldNames() {
  static const std::vector<std::string> names = {
      "mass", "velocity", "stress", "deformation_gradient", "plastic_strain", "volume", "material", "id"};
  return names;
}

MpmOutput::MpmOutput(const MpmSolver& solver)
    : writer_(solver.comm(), solver.decomposition(), solver.scene().output.directory, solver.scene().name),
      fields_(solver.scene().output.fields),
      particles_(solver.scene().output.particles) {
  const auto& valid = fieldNames();
  for (const auto& f : fields_)
    if (std::find(valid.begin(), valid.end(), f) == valid.end()) {
      std::string list;
      for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
      throw std::invalid_argument("output.fields: mpm_solver offers no field '" + f + "'; valid names: " + list +
                                  " (or leave the list empty for all)");
    }
}

bool MpmOutput::wanted(const std::string& name) const {
  return fields_.empty() || std::find(fields_.begin(), fields_.end(), name) != fields_.end();
}

std::string MpmOutput::write(const MpmSolver& solver) {
  const ParticleSet& p = solver.particles();
  const Grid& g = solver.grid();
  std::vector<const core::Field*> grid;
  if (wanted("mass")) grid.push_back(&g.mass);
  if (wanted("velocity")) {
    // The grid holds the mesh's components; the file holds three (an XDMF Vector), the others 0.
    const core::Field& v = g.velocity;
    if (v.ncomp() < 3) {
      if (nodeVelocity3_.npts() != v.npts())
        nodeVelocity3_ = core::Field(v.name(), v.centering(), v.box(), 3, v.nghost());
      for (int c = 0; c < 3; ++c) {
        double* to = nodeVelocity3_.data(c);
        if (c < v.ncomp())
          std::copy(v.data(c), v.data(c) + v.npts(), to);
        else
          std::fill(to, to + v.npts(), 0.0);
      }
      grid.push_back(&nodeVelocity3_);
    } else {
      grid.push_back(&v);
    }
  }
  if (!particles_) return writer_.writeStep(static_cast<int>(solver.stepCount()), solver.time(), grid);

  const std::size_t n = p.size();
  using S = std::span<const double>;
  core::ParticleOutput out;
  out.count = static_cast<std::int64_t>(n);
  for (int d = 0; d < 3; ++d) out.position[d] = S(p.x[d]);
  if (wanted("velocity")) out.addVector("velocity", {S(p.v[0]), S(p.v[1]), S(p.v[2])});
  if (wanted("stress")) {
    std::vector<S> c;
    for (int k = 0; k < 6; ++k) c.emplace_back(p.column(p.stress[k]));
    out.addVector("stress", std::move(c));
  }
  if (wanted("deformation_gradient")) {
    std::vector<S> c;
    for (int k = 0; k < 9; ++k) c.emplace_back(p.column(p.F[k]));
    out.addVector("deformation_gradient", std::move(c));
  }
  if (wanted("plastic_strain")) out.addScalar("plastic_strain", S(p.column(p.eqps)));
  if (wanted("mass")) out.addScalar("mass", S(p.mass));
  if (wanted("volume")) out.addScalar("volume", S(p.vol));
  if (wanted("material")) {
    materialId_.assign(p.material.begin(), p.material.end());
    out.addScalar("material", S(materialId_));
  }
  if (wanted("id")) {
    id_.resize(n);
    for (std::size_t i = 0; i < n; ++i) id_[i] = static_cast<double>(p.id[i]);
    out.addScalar("id", S(id_));
  }
  return writer_.writeStep(static_cast<int>(solver.stepCount()), solver.time(), grid, &out);
}

}  // namespace mpmice::mpm
