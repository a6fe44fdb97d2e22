#pragma once
/// @brief ProbeRecorder: follows the solid particles nearest to the scene's `output.probes` points
/// and writes their position and displacement x - x0 every time it is asked, one CSV row each.
///
/// At construction (collective) each probe picks, over all ranks, the particle whose initial
/// position x0 is nearest to its point (ties, within round-off of the distance, go to the lowest
/// global id) and keeps that particle's global id: particles move between ranks, so every
/// record() finds them again by id (the last local index is tried first). The file,
/// <output.directory>/<scene>_probes.csv, holds
///   step, time, <name>_x, <name>_y[, <name>_z], <name>_ux, <name>_uy[, <name>_uz] per probe
/// (components up to the mesh dimension), written by rank 0 of the solver's communicator through
/// core::CsvWriter. A probe whose particle no longer exists (it left the mesh) reads NaN.
///
/// Sample use (every program that steps an MpmSolver):
///   auto probes = ProbeRecorder::fromScene(solver);   // null: no probes, or output disabled
///   if (probes) probes->record(solver);               // t = 0, then after every step
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/io/csv_writer.h"
#include "mpm/solver/mpm_solver.h"

namespace mpmice::mpm {

class ProbeRecorder {
 public:
  /// One probe's particle as last recorded: position and displacement (3 components, zero
  /// beyond the mesh dimension); NaN when the particle was not found on any rank.
  struct Sample {
    std::array<double, 3> x{}, u{};
  };

  /// Picks the particles of `probes` (collective) and opens `path` on rank 0 (its directory is
  /// created). An empty `path` records without writing (the samples are still gathered).
  /// resumeLength >= 0: a restart continues the file from its first resumeLength bytes
  /// (core::CsvWriter::cutForResume).
  ProbeRecorder(const MpmSolver& solver, const std::vector<core::ProbeSpec>& probes, const std::string& path,
                std::int64_t resumeLength = -1);
  /// The scene's probes into <output.directory>/<scene>_probes.csv; null when the scene has no
  /// probes or output is disabled. Collective.
  static std::unique_ptr<ProbeRecorder> fromScene(const MpmSolver& solver, std::int64_t resumeLength = -1);
  /// The CSV path a scene's probes go to.
  static std::string pathFor(const core::Scene& scene);

  /// Finds each probe's particle (collective), stores the samples and writes one row:
  /// solver.stepCount(), solver.time(), then the probes' positions and displacements.
  void record(const MpmSolver& solver);

  [[nodiscard]] const std::vector<std::int64_t>& particleIds() const { return ids_; }
  [[nodiscard]] const std::vector<Sample>& samples() const { return samples_; }
  [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }
  /// Bytes of the CSV written so far on this rank (0 where it does not write), for a checkpoint.
  [[nodiscard]] std::int64_t csvLength() const { return csv_ ? csv_->length() : 0; }

 private:
  std::vector<std::string> names_;
  std::vector<std::int64_t> ids_;    // global particle id per probe
  std::vector<std::size_t> hint_;    // last local index per probe (checked against the id)
  std::vector<Sample> samples_;
  std::vector<std::string> columns_;
  int dim_ = 2;
  std::unique_ptr<core::CsvWriter> csv_;
};

}  // namespace mpmice::mpm
