#pragma once
/// @brief A run's checkpoints: when they are due (output.checkpoint_interval), writing them, and
/// the one a restart (`--restart PATH`) resumes from. Every program's time loop uses it.
///
/// Due after each step at which the clock has passed the next multiple of
/// output.checkpoint_interval (at most once per step, never at t = 0, and after the last step of
/// the run); 0 = never. A checkpoint is taken after the step's output and CSV rows, so a restart
/// resumes with the step after it. The file is `<output.directory>/<base>_checkpoint_<step>.h5`
/// (core/io/checkpoint.h), `base` the program's output base name (the scene, or the scene with
/// `_solid` / `_fluid` in an MPMD launch). The data carry the scene's identity and this
/// schedule's own position.
///
/// Sample use:
///   core::RunCheckpoints checkpoints(scene, comm, scene.name, "mpm_solver", restartPath);
///   if (const auto* c = checkpoints.resumed()) solver.loadCheckpoint(*c, "mpm");
///   ... after every step:
///   if (checkpoints.due(t)) { core::CheckpointData d; solver.saveCheckpoint(d, "mpm"); checkpoints.write(d, t, step); }
#include <memory>
#include <ostream>
#include <string>

#include "core/io/checkpoint.h"
#include "core/parallel/comm.h"
#include "core/scene/scene.h"
#include "core/time/time_loop.h"

namespace mpmice::core {

class RunCheckpoints {
 public:
  /// restartPath empty: a fresh start. Otherwise reads the checkpoint it means for `base`
  /// (collective; throws std::invalid_argument: none there, another scene, program or rank count)
  /// and prints "restart: <file> (step N, t = T s)" on rank 0 of comm to `log`.
  RunCheckpoints(const Scene& scene, const Comm& comm, std::string base, std::string program,
                 const std::string& restartPath, std::ostream* log = nullptr);

  /// The checkpoint this run resumes from; null on a fresh start.
  [[nodiscard]] const CheckpointData* resumed() const { return resumed_.get(); }
  /// Called once after every step with the clock after it (`last`: the run's last step).
  bool due(double t, bool last = false);
  /// Adds the scene identity and this schedule's position to `data` and writes the checkpoint of
  /// `step` (collective). Returns its path.
  std::string write(CheckpointData& data, double t, long step);

 private:
  Comm comm_;
  std::string dir_, base_, program_;
  const Scene& scene_;
  bool enabled_;
  OutputSchedule schedule_;
  std::unique_ptr<CheckpointData> resumed_;
};

}  // namespace mpmice::core
