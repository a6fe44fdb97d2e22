#include "mpm/solver/probes.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "mpm/mpm_constants.h"

namespace mpmice::mpm {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* const kAxis[3] = {"x", "y", "z"};
}  // namespace

std::string ProbeRecorder::pathFor(const core::Scene& scene) {
  return scene.output.directory + "/" + scene.name + "_probes.csv";
}

std::unique_ptr<ProbeRecorder> ProbeRecorder::fromScene(const MpmSolver& solver, std::int64_t resumeLength) {
  const core::Scene& s = solver.scene();
  if (s.output.probes.empty() || !s.output.enabled) return nullptr;
  return std::make_unique<ProbeRecorder>(solver, s.output.probes, pathFor(s), resumeLength);
}

ProbeRecorder::ProbeRecorder(const MpmSolver& solver, const std::vector<core::ProbeSpec>& probes,
                             const std::string& path, std::int64_t resumeLength)
    : dim_(solver.scene().mesh.dim()) {
  const core::Comm& comm = solver.comm();
  const ParticleSet& p = solver.particles();
  const core::Mesh& mesh = solver.scene().mesh;
  double h = 1e300;
  for (int d = 0; d < dim_; ++d) h = std::min(h, mesh.dx(d));
  // Distances equal to within round-off of the particle positions count as ties.
  const double tieTol = kProbeTieTolerance * h * h;
  for (const core::ProbeSpec& probe : probes) {
    std::vector<double> d2(p.size());
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
      double s = 0;
      for (int d = 0; d < dim_; ++d) {
        const double e = p.x0[d][i] - probe.point[d];
        s += e * e;
      }
      d2[i] = s;
      best = std::min(best, s);
    }
    best = comm.min(best);
    if (!(best < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument("output.probes: probe '" + probe.name +
                                  "' has no solid particle to follow (the scene has no solid particles)");
    // Lowest global id among the nearest (ids are below 2^53, exact as doubles).
    double id = std::numeric_limits<double>::infinity();
    std::size_t local = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (d2[i] <= best + tieTol && static_cast<double>(p.id[i]) < id) {
        id = static_cast<double>(p.id[i]);
        local = i;
      }
    id = comm.min(id);
    names_.push_back(probe.name);
    ids_.push_back(static_cast<std::int64_t>(id));
    hint_.push_back(local);
  }
  samples_.resize(probes.size());
  columns_ = {"step", "time"};
  for (const std::string& n : names_) {
    for (int d = 0; d < dim_; ++d) columns_.push_back(n + "_" + kAxis[d]);
    for (int d = 0; d < dim_; ++d) columns_.push_back(n + "_u" + kAxis[d]);
  }
  if (!path.empty()) {
    if (comm.root()) {
      const std::filesystem::path dir = std::filesystem::path(path).parent_path();
      std::error_code ec;
      if (!dir.empty()) std::filesystem::create_directories(dir, ec);
    }
    if (resumeLength >= 0) core::CsvWriter::cutForResume(comm, path, resumeLength);
    csv_ = std::make_unique<core::CsvWriter>(comm, path, columns_, 0,
                                             resumeLength >= 0 ? core::CsvWriter::Mode::Append
                                                               : core::CsvWriter::Mode::Truncate);
  }
}

void ProbeRecorder::record(const MpmSolver& solver) {
  const ParticleSet& p = solver.particles();
  const std::size_t np = ids_.size();
  // Per probe: found, x (3), u (3); summed over ranks (one rank holds each particle).
  std::vector<double> buf(7 * np, 0.0);
  for (std::size_t k = 0; k < np; ++k) {
    std::size_t i = hint_[k];
    if (i >= p.size() || p.id[i] != ids_[k]) {
      const auto it = std::find(p.id.begin(), p.id.end(), ids_[k]);
      i = it == p.id.end() ? p.size() : static_cast<std::size_t>(it - p.id.begin());
    }
    if (i == p.size()) continue;
    hint_[k] = i;
    buf[7 * k] = 1;
    for (int d = 0; d < 3; ++d) {
      buf[7 * k + 1 + d] = p.x[d][i];
      buf[7 * k + 4 + d] = p.x[d][i] - p.x0[d][i];
    }
  }
  solver.comm().sumInPlace(buf);
  std::vector<double> row{static_cast<double>(solver.stepCount()), solver.time()};
  for (std::size_t k = 0; k < np; ++k) {
    const bool found = buf[7 * k] > 0.5;
    for (int d = 0; d < 3; ++d) {
      samples_[k].x[d] = found ? buf[7 * k + 1 + d] : kNaN;
      samples_[k].u[d] = found ? buf[7 * k + 4 + d] : kNaN;
    }
    for (int d = 0; d < dim_; ++d) row.push_back(samples_[k].x[d]);
    for (int d = 0; d < dim_; ++d) row.push_back(samples_[k].u[d]);
  }
  if (csv_) csv_->row(row);
}

}  // namespace mpmice::mpm
