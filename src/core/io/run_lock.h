#pragma once
/// @brief The output-directory lock: one run of a scene into one output directory at a time.
///
/// A lock is the file <directory>/<name>.lock, created exclusively before anything else is
/// written there, holding "pid host program" of its holder. A second run finds it and is refused
/// with a message naming the holder; a lock left by a dead process (same host, pid not alive) is
/// taken over with a note. The lock is released (the file removed) when its holder ends normally.
///
/// Names: `coupler run` and `mpmice` lock `<scene>`; each program of an MPMD launch locks
/// `<scene>.<program>` (its rank 0), so the two participants of one launch never refuse each
/// other while a second launch is refused. A lock may also name `conflicts`: other lock names of
/// the same directory that must not be held by a live process other than this one or one of its
/// ancestors (the participants of a `coupler run` accept the coupler's lock; `mpmice` refuses a
/// running MPMD launch of the scene and the other way round).
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::core {

/// A run refused because another live process holds the lock.
class RunLockHeld : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RunLock {
 public:
  /// Takes <directory>/<name>.lock (creating the directory); throws RunLockHeld naming the holder,
  /// std::runtime_error when the file cannot be written. Notes a stale lock taken over on `log`.
  RunLock(const std::string& directory, const std::string& name, const std::string& program,
          const std::vector<std::string>& conflicts = {}, std::ostream* log = nullptr);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  [[nodiscard]] const std::string& path() const { return path_; }

  /// Rank 0 of comm takes the lock, the others learn the outcome: every rank throws the same
  /// RunLockHeld / std::runtime_error message on failure. Null on ranks other than 0.
  static std::unique_ptr<RunLock> acquire(const Comm& comm, const std::string& directory, const std::string& name,
                                          const std::string& program, const std::vector<std::string>& conflicts = {},
                                          std::ostream* log = nullptr);

  /// "pid 123 on host vm (mpmice)" for a lock file's text; empty when malformed.
  static std::string describeHolder(const std::string& lockText);

 private:
  std::string path_;
  std::string text_;
};

/// The lock of `program`'s run of `scene` (RunLock::acquire on comm; null when output is disabled
/// and off rank 0): "coupler" and "mpmice" lock <scene>, refusing a live MPMD launch of it; the
/// MPMD programs lock <scene>.<program>, refusing a live <scene> lock other than their coupler's.
std::unique_ptr<RunLock> lockOutputDirectory(const Comm& comm, const Scene& scene, const std::string& program,
                                             std::ostream* log);

}  // namespace mpmice::core
