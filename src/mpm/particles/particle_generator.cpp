#include "mpm/particles/particle_generator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/scene/shape.h"
#include "mpm/mpm_constants.h"

namespace mpmice::mpm {

void generateParticles(const core::Scene& scene, const core::Box& cells, ParticleSet& out,
                       const ContainsFn& contains, std::vector<RegionVolume>* volumes) {
  const core::Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  // Solid objects: (region index, material index).
  std::vector<std::pair<int, int>> solids;
  for (std::size_t r = 0; r < scene.geometry.size(); ++r) {
    const auto& reg = scene.geometry[r];
    for (const auto& f : reg.fill) {
      int m = -1;
      for (std::size_t k = 0; k < scene.materials.size(); ++k)
        if (scene.materials[k].name == f.material) m = static_cast<int>(k);
      if (m < 0 || scene.materials[m].kind != core::MaterialKind::Solid) continue;
      const auto& mat = scene.materials[m];
      if (!(mat.density > 0)) {
        std::ostringstream os;
        os << "materials." << mat.name << ".density: a solid needs a density > 0, got "
           << mat.density << "; give the reference density in kg/m^3";
        throw std::invalid_argument(os.str());
      }
      // Only symmetry faces may cut a solid (beyond them it continues as its mirror image).
      if (const auto bounds = core::scene_detail::shapeBounds(reg.shape, dim)) {
        const auto& [lo, hi] = *bounds;
        for (int d = 0; d < dim; ++d) {
          const double tol = kGeneratorFaceTolerance * (mesh.upper(d) - mesh.origin()[d]);
          const bool symLo = scene.boundary[2 * d].type == core::BoundaryType::Symmetry;
          const bool symHi = scene.boundary[2 * d + 1].type == core::BoundaryType::Symmetry;
          if ((!symLo && lo[d] < mesh.origin()[d] - tol) || (!symHi && hi[d] > mesh.upper(d) + tol)) {
            std::ostringstream os;
            os << "geometry." << reg.name << ": solid '" << mat.name
               << "' reaches outside the mesh in direction " << "xyz"[d] << " ([" << lo[d] << ", "
               << hi[d] << "] vs mesh [" << mesh.origin()[d] << ", " << mesh.upper(d)
               << "]); particles outside the mesh are an error: enlarge the mesh or move the object "
                  "(only symmetry faces may cut a solid)";
            throw std::invalid_argument(os.str());
          }
        }
      }
      for (int d = 0; d < dim; ++d)
        if (reg.particles_per_cell[d] < 1)
          throw std::invalid_argument("geometry." + reg.name + ".particles_per_cell must be >= 1");
      solids.emplace_back(static_cast<int>(r), m);
    }
  }
  if (volumes) volumes->assign(scene.geometry.size(), RegionVolume{});
  if (solids.empty()) return;
  const std::int64_t ncells = mesh.numCells();
  const core::Box all = mesh.cellBox();
  // Whether solid object s (index into solids) holds point x: its shape contains x and no later
  // solid object claims it.
  auto holds = [&](std::size_t s, const core::RealVect& x) {
    if (!contains(scene.geometry[solids[s].first].shape, x, dim)) return false;
    for (std::size_t t = s + 1; t < solids.size(); ++t)
      if (solids[t].first != solids[s].first && contains(scene.geometry[solids[t].first].shape, x, dim)) return false;
    return true;
  };
  std::vector<std::optional<std::pair<core::RealVect, core::RealVect>>> bounds;
  for (const auto& sm : solids) bounds.push_back(core::scene_detail::shapeBounds(scene.geometry[sm.first].shape, dim));
  core::forEach(cells, [&](int i, int j, int k) {
    const int ijk[3] = {i, j, k};
    const std::int64_t cellId = all.index(i, j, k);
    for (std::size_t s = 0; s < solids.size(); ++s) {
      const auto& reg = scene.geometry[solids[s].first];
      const int m = solids[s].second;
      int ppc[3] = {1, 1, 1};
      for (int d = 0; d < dim; ++d) ppc[d] = reg.particles_per_cell[d];
      const double vol = mesh.cellVolume() / (ppc[0] * ppc[1] * ppc[2]);
      core::RealVect half{0, 0, 0};
      for (int d = 0; d < dim; ++d) half[d] = 0.5 * mesh.dx(d) / ppc[d];
      const std::size_t before = out.size();
      mesh.forSubcellCentres(ijk, ppc, [&](const core::RealVect& x, const int* sub) {
        if (!holds(s, x)) return;  // outside the shape, or a later solid object claims it
        const std::int64_t subId = sub[0] + 64 * (sub[1] + 64 * sub[2]);
        const std::int64_t gid = ((static_cast<std::int64_t>(s) * ncells + cellId) << 18) + subId;
        out.addParticle(x, reg.velocityAt(x), scene.materials[m].density * vol, vol, half, m, reg.temperature, gid);
      });
      if (!volumes) continue;
      // The shape's volume in this cell: whole where every particle point and every corner is held,
      // else sampled (cells outside the shape's bounds hold none of it).
      RegionVolume& rv = (*volumes)[static_cast<std::size_t>(solids[s].first)];
      const std::size_t made = out.size() - before;
      rv.particles += double(made) * vol;
      const int nppc = ppc[0] * ppc[1] * ppc[2];
      if (made == static_cast<std::size_t>(nppc)) {  // whole if its corners are held too
        bool whole = true;
        for (int corner = 0; corner < (1 << dim) && whole; ++corner) {
          core::RealVect x{0, 0, 0};
          for (int d = 0; d < dim; ++d) x[d] = mesh.node(d, ijk[d] + ((corner >> d) & 1));
          whole = holds(s, x);
        }
        if (whole) {
          rv.shape += mesh.cellVolume();
          continue;
        }
      }
      if (bounds[s]) {
        const auto& [lo, hi] = *bounds[s];
        bool touches = true;
        for (int d = 0; d < dim; ++d)
          touches = touches && hi[d] > mesh.node(d, ijk[d]) && lo[d] < mesh.node(d, ijk[d] + 1);
        if (!touches) continue;
      }
      int n[3] = {1, 1, 1};
      for (int d = 0; d < dim; ++d) n[d] = ppc[d] * (dim == 3 ? kShapeVolumeSamples3D : kShapeVolumeSamples2D);
      long in = 0;
      mesh.forSubcellCentres(ijk, n, [&](const core::RealVect& x, const int*) { in += holds(s, x) ? 1 : 0; });
      rv.shape += mesh.cellVolume() * double(in) / double(n[0] * n[1] * n[2]);
    }
  });
}

std::vector<std::string> geometryVolumeWarnings(const core::Scene& scene, const std::vector<RegionVolume>& volumes,
                                                double tolerance) {
  std::vector<std::string> out;
  const int dim = scene.mesh.dim();
  for (std::size_t r = 0; r < volumes.size() && r < scene.geometry.size(); ++r) {
    const RegionVolume& v = volumes[r];
    if (!(v.shape > 0) || std::abs(v.particles - v.shape) <= tolerance * v.shape) continue;
    const auto& reg = scene.geometry[r];
    std::ostringstream os;
    os.precision(4);
    os << "geometry." << reg.name << ": its particles fill " << v.particles << " m^" << dim << ", the shape "
       << v.shape << " m^" << dim << " inside the mesh (" << std::showpos << 100.0 * (v.particles / v.shape - 1.0)
       << std::noshowpos << " %): a face between two particle centres rounds to the nearer one (particle spacing";
    for (int d = 0; d < dim; ++d)
      os << (d ? " x " : " ") << scene.mesh.dx(d) / reg.particles_per_cell[d];
    os << " m); put the shape's faces on the particle lattice (cell faces and their 1/particles_per_cell "
          "divisions) or refine mesh.spacing / particles_per_cell";
    out.push_back(os.str());
  }
  return out;
}

}  // namespace mpmice::mpm
