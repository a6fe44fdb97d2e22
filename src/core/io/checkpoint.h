#pragma once
/// @brief Checkpoints: the complete state of a run at the end of a step, to resume it from.
///
/// A checkpoint is a set of named entries, each one array of doubles per rank (a rank's particle
/// columns, its stored cell fields, its part of an acceleration history, a clock of one value).
/// Every rank puts the same names (the lengths differ); names are identifiers with dots
/// (`mpm.particles`, `ice.air.mass`). Integers (ids, counts, steps) are stored as doubles (exact
/// below 2^53); text (the scene hash, the XDMF index) as one character per double.
///
/// The file `<dir>/<base>_checkpoint_<step:06d>.h5` is written collectively (parallel HDF5) under
/// `<name>.part` and renamed by rank 0 when complete, so a checkpoint is complete or absent:
///   /                 attributes: time, step, nranks, format (1)
///   /data/<name>      (sum of the ranks' lengths)   the ranks' arrays, concatenated in rank order
///   /counts/<name>    (nranks)                      each rank's length
/// A checkpoint resumes only on the rank count that wrote it (the arrays are each rank's own
/// storage, ghosts included), and only the scene whose sceneHash() it holds.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::core {

struct Scene;

class CheckpointData {
 public:
  void put(const std::string& name, std::vector<double> values);
  void put(const std::string& name, std::span<const double> values) {
    put(name, std::vector<double>(values.begin(), values.end()));
  }
  void put(const std::string& name, double value) { put(name, std::vector<double>{value}); }
  void putText(const std::string& name, const std::string& text);

  [[nodiscard]] bool has(const std::string& name) const { return entries_.count(name) > 0; }
  /// This rank's array; throws std::invalid_argument naming the file and the entry when absent.
  [[nodiscard]] const std::vector<double>& get(const std::string& name) const;
  /// A one-value entry (throws unless the entry holds exactly one value).
  [[nodiscard]] double scalar(const std::string& name) const;
  [[nodiscard]] std::string text(const std::string& name) const;
  /// Copies entry `name` into `out`, which must have its length (throws naming both otherwise).
  void copyTo(const std::string& name, std::span<double> out) const;

  [[nodiscard]] const std::map<std::string, std::vector<double>>& entries() const { return entries_; }
  /// The file it was read from ("" for one being built), for messages.
  [[nodiscard]] const std::string& source() const { return source_; }
  void setSource(std::string s) { source_ = std::move(s); }

 private:
  std::map<std::string, std::vector<double>> entries_;
  std::string source_;
};

/// `<dir>/<base>_checkpoint_<step:06d>.h5`
[[nodiscard]] std::string checkpointPath(const std::string& dir, const std::string& base, long step);

/// Writes `data` (collective; every rank the same names) to `path`: `<path>.part`, renamed by
/// rank 0 when closed. Throws std::runtime_error on every rank when any rank fails.
void writeCheckpoint(const Comm& comm, const std::string& path, const CheckpointData& data, double time,
                     long step);

/// Reads this rank's arrays of the checkpoint `path` (collective). Throws std::invalid_argument
/// (the same on every rank) when the file is missing or unreadable, or was written by another
/// number of ranks (naming both counts).
[[nodiscard]] CheckpointData readCheckpoint(const Comm& comm, const std::string& path);

/// The checkpoint `--restart PATH` means for the output base name `base`: PATH a directory, its
/// latest `<base>_checkpoint_<step>.h5` (the highest step); PATH a checkpoint file, the file of
/// `base` with the same step in the same directory (so one file names the checkpoint of both
/// programs of an MPMD launch). Throws std::invalid_argument naming PATH when there is none.
[[nodiscard]] std::string resolveCheckpoint(const std::string& path, const std::string& base);

/// Puts the scene's identity (its hash, its name) and `program`, the program that wrote it.
void putSceneIdentity(CheckpointData& data, const Scene& scene, const std::string& program);
/// Throws std::invalid_argument naming the file when the checkpoint holds another scene hash (the
/// mesh, materials or boundary conditions differ) or was written by another program.
void checkSceneIdentity(const CheckpointData& data, const Scene& scene, const std::string& program);

}  // namespace mpmice::core
