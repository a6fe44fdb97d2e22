#pragma once
/// @brief What a run is, as its output files carry it: the same facts as the run record
/// (`<scene><suffix>_run.yaml`, core/io/run_record.h) as string and integer attributes of the
/// root group of every HDF5 file the run writes.
///
///   program, version ("0.1.0 (<git describe>)"), command_line, ranks (this program's), launch_ranks
///   (the whole launch: both programs of an MPMD launch), rank_layout ("mpm_solver: world ranks 0-1
///   of a 3-rank launch"), host, started (UTC, ISO 8601), scene_file, scene_hash,
///   scene_as_understood (the `coupler check` dump)
///
/// The RunRecord of a run makes its metadata current (one run per process); OutputWriter writes the
/// current metadata into each file it creates. The values are rank 0's on every rank (collective
/// attribute writes need the same bytes everywhere).
#include <cstdint>
#include <string>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::core {

class H5Group;

struct RunMetadata {
  std::string program, version, command_line, rank_layout, host, started, scene_file, scene_hash, scene_as_understood;
  std::int64_t ranks = 1, launch_ranks = 1;

  /// This process's run of `scene` by `program` on comm, started now; rank 0's values on every
  /// rank (collective).
  static RunMetadata describe(const Scene& scene, const Comm& comm, const std::string& program);

  /// Writes every field as an attribute of `group` (collective on a parallel file).
  void writeTo(const H5Group& group) const;
  /// Reads them back; throws naming the file and the attribute when one is missing.
  static RunMetadata readFrom(const H5Group& group);

  /// The metadata the run of this process publishes (null when none: a writer used outside a run).
  static const RunMetadata* current();
  static void publish(const RunMetadata* m);
};

/// "2026-12-01T23:10:00Z": now, in UTC.
std::string utcNow();

}  // namespace mpmice::core
