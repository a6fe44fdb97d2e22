#pragma once
/// @brief `<output.directory>/log.<program>`: what a program prints to the terminal, kept with its
/// output (log.mpm_solver, log.ice_solver, log.mpmice; `coupler run` writes the OpenFOAM solver's
/// output to log.<solver>, e.g. log.pimpleFoam).
///
/// A log is only ever appended to (opened O_APPEND, never truncated or removed): each run adds a
/// section headed
///   ==== mpm_solver 0.1.0 (<git describe>): scene 'flap' (configs/flap.yaml), started <UTC>, pid <n> on <host> ====
/// so an earlier run's log, or the log of another scene sharing the directory, stays as it was.
/// The two programs of an MPMD launch write different files (their names), and the run lock keeps
/// a second run of the same scene out while one runs.
///
/// While a tee lives, everything rank 0 writes to std::cout and std::cerr, and every error line
/// (core/util/error_line.h), also goes to the log. Nothing is written when output.enabled is false.
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::core {

class LogFile {
 public:
  /// Opens (creating the directory and the file when missing) `path` for appending and writes the
  /// section header; throws std::runtime_error naming the file when it cannot. launchedBy: the
  /// program of this project that keeps the log of another one (`coupler` for OpenFOAM's solver).
  LogFile(const std::string& path, const std::string& program, const Scene& scene, const std::string& launchedBy = "");
  ~LogFile();
  LogFile(const LogFile&) = delete;
  LogFile& operator=(const LogFile&) = delete;

  /// Rank 0 of comm with output enabled: the log of `program`, with std::cout, std::cerr and the
  /// error lines teed into it until it is destroyed. Null elsewhere.
  static std::unique_ptr<LogFile> teeProgramOutput(const Comm& comm, const Scene& scene, const std::string& program);

  /// Appends text as it is (one write).
  void write(std::string_view text) const;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  void tee();
  std::string path_;
  int fd_ = -1;
  std::unique_ptr<std::streambuf> outTee_, errTee_;
  std::streambuf* outOld_ = nullptr;
  std::streambuf* errOld_ = nullptr;
};

/// `<output.directory>/log.<program>`.
std::string logFilePath(const Scene& scene, const std::string& program);

}  // namespace mpmice::core
