#include "couplings/surface/solid/file_load.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "core/io/force_export_file.h"
#include "coupler/mapping/mapping.h"
#include "couplings/surface/solid/surface_particles.h"

namespace mpmice::coupler {

namespace {

/// The load's path: as given when absolute, else relative to the scene file's directory.
std::string resolve(const core::Scene& scene, const std::string& file) {
  const std::filesystem::path p(file);
  if (p.is_absolute() || scene.file.empty()) return file;
  return (std::filesystem::path(scene.file).parent_path() / p).string();
}

std::array<double, 3> cross(const double r[3], const double f[3]) {
  return {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
}

}  // namespace

std::vector<FileLoadReport> applyFileLoads(mpm::MpmSolver& mpm, std::ostream& log) {
  const core::Scene& scene = mpm.scene();
  const int dim = scene.mesh.dim();
  const core::Comm& comm = mpm.comm();
  std::vector<FileLoadReport> reports;
  bool any = false;
  for (std::size_t l = 0; l < scene.loads.size(); ++l) {
    const core::LoadSpec& ld = scene.loads[l];
    if (ld.type != core::LoadType::File) continue;
    if (!any) {
      // The file loads are the only surface forces of a run alone: start from none (a restart's
      // checkpoint holds the forces set before it).
      mpm.enableSurfaceForces();
      auto& p = mpm.particles();
      for (int d = 0; d < 3; ++d) std::fill(p.fsurf[d].begin(), p.fsurf[d].end(), 0.0);
    }
    any = true;
    const std::string what = "loads[" + std::to_string(l) + "] (file " + ld.file + ")";
    const core::ForceExport ex = core::readForceExport(resolve(scene, ld.file));
    const int material = scene.materialIndex(ld.material);
    FileLoadReport r;
    r.particles = comm.sum(static_cast<long long>(markSurfaceParticles(mpm, material)));
    if (r.particles == 0) throw std::invalid_argument(what + ": material '" + ld.material + "' has no particles");
    const SurfaceCloud cloud = gatherSurfaceCloud(mpm);
    PointCloud source, target;
    for (std::size_t k = 0; k < cloud.size(); ++k) source.add(cloud.x0[3 * k], cloud.x0[3 * k + 1], cloud.x0[3 * k + 2]);
    for (std::size_t k = 0; k < ex.size(); ++k) target.add(ex.points[3 * k], ex.points[3 * k + 1], ex.points[3 * k + 2]);
    auto map = makeMapping(ld.mapping, ld.rbf_support);
    map->compute(source, target, dim);
    std::vector<double> f(3 * cloud.size(), 0.0);
    map->mapConservative(ex.forces.data(), f.data(), 3);
    r.depth = dim == 2 ? (ld.depth > 0 ? ld.depth : (ex.depth > 0 ? ex.depth : 1.0)) : 1.0;
    if (dim == 2)
      for (std::size_t k = 0; k < cloud.size(); ++k) f[3 * k + 2] = 0.0;
    // Totals in the file's units, about the load's moment_center (the particles at t = 0).
    const std::array<double, 3> c{ld.moment_center[0], ld.moment_center[1], ld.moment_center[2]};
    std::unordered_map<std::int64_t, std::size_t> slot;
    for (std::size_t k = 0; k < cloud.size(); ++k) {
      slot[cloud.ids[k]] = k;
      const double rr[3] = {cloud.x0[3 * k] - c[0], cloud.x0[3 * k + 1] - c[1], cloud.x0[3 * k + 2] - c[2]};
      const auto m = cross(rr, &f[3 * k]);
      for (int d = 0; d < 3; ++d) {
        r.forceApplied[static_cast<std::size_t>(d)] += f[3 * k + static_cast<std::size_t>(d)];
        r.momentApplied[static_cast<std::size_t>(d)] += m[static_cast<std::size_t>(d)];
      }
    }
    r.forceRead = ex.totalForce();
    r.momentRead = ex.totalMoment(c);
    r.points = ex.size();
    r.phases = ex.phases;
    // Held on the local surface particles (2D MPM: per metre of depth).
    auto& p = mpm.particles();
    const double scale = 1.0 / r.depth;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.surface[i] == 0.0) continue;
      const std::size_t k = slot.at(p.id[i]);
      for (int d = 0; d < 3; ++d) p.fsurf[d][i] += scale * f[3 * k + static_cast<std::size_t>(d)];
    }
    if (comm.root()) {
      const char* axes = "xyz";
      log << "  " << what << ": " << r.points << " points, " << r.phases << " force vector(s) per point summed; "
          << r.particles << " surface particles of '" << ld.material << "', mapping " << map->name();
      if (dim == 2) log << ", depth " << r.depth << " m (forces per metre of depth in the solid)";
      log << "\n";
      auto line = [&](const char* label, const std::array<double, 3>& F, const std::array<double, 3>& M) {
        log << "    " << label << ": force (";
        for (int d = 0; d < dim; ++d) log << (d ? ", " : "") << F[static_cast<std::size_t>(d)];
        log << ") N, moment about (" << c[0] << ", " << c[1] << (dim == 3 ? ", " + std::to_string(c[2]) : "") << ") ";
        if (dim == 2) {
          log << "M_z " << M[2] << " N m\n";
        } else {
          log << "(";
          for (int d = 0; d < 3; ++d) log << (d ? ", " : "") << 'M' << axes[d] << ' ' << M[static_cast<std::size_t>(d)];
          log << ") N m\n";
        }
      };
      line("read   ", r.forceRead, r.momentRead);
      line("applied", r.forceApplied, r.momentApplied);
      log << std::flush;
    }
    reports.push_back(r);
  }
  return reports;
}

}  // namespace mpmice::coupler
