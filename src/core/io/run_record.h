#pragma once
/// @brief What a run was: `<directory>/<scene><suffix>_run.yaml`, written by rank 0 at the start
/// and rewritten at the end (each time to a temporary name, then renamed).
///
///   program, version (the build's git describe), command line, ranks, launch_ranks, rank_layout,
///   host, started, ended, status ("running", "completed", or the failure when the program caught
///   one), scene file, scene hash, and the scene as understood (the `coupler check` dump).
/// Nothing is written when output.enabled is false. Collective (rank 0's values everywhere). While
/// it lives, its metadata is the current run's (core/io/run_metadata.h): every HDF5 file the run
/// writes carries the same facts as root attributes.
#include <memory>
#include <string>

#include "core/io/run_metadata.h"
#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::core {

class RunRecord {
 public:
  RunRecord(const Scene& scene, const Comm& comm, std::string program, const std::string& suffix = "");
  ~RunRecord();
  RunRecord(const RunRecord&) = delete;
  RunRecord& operator=(const RunRecord&) = delete;
  /// The run ended normally.
  void completed();
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const RunMetadata& metadata() const { return meta_; }

 private:
  void write(const std::string& status) const;
  const Scene& scene_;
  bool writer_;
  std::string path_;
  RunMetadata meta_;
};

}  // namespace mpmice::core
