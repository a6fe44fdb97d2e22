#include "core/io/run_checkpoints.h"

#include <cstdio>

namespace mpmice::core {

RunCheckpoints::RunCheckpoints(const Scene& scene, const Comm& comm, std::string base, std::string program,
                               const std::string& restartPath, std::ostream* log)
    : comm_(comm),
      dir_(scene.output.directory),
      base_(std::move(base)),
      program_(std::move(program)),
      scene_(scene),
      enabled_(scene.output.checkpoint_interval > 0),
      schedule_(scene.output.checkpoint_interval, scene.time.end) {
  schedule_.due(0.0);  // never at t = 0: moves the next time to the first interval
  if (restartPath.empty()) return;
  const std::string path = resolveCheckpoint(restartPath, base_);
  resumed_ = std::make_unique<CheckpointData>(readCheckpoint(comm_, path));
  checkSceneIdentity(*resumed_, scene_, program_);
  schedule_.resume(resumed_->get("run.checkpoints"));
  if (log && comm_.root()) {
    const auto& clock = resumed_->get("run.clock");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6e", clock.at(0));
    *log << "restart: " << path << " (step " << static_cast<long>(clock.at(1)) << ", t = " << buf << " s)\n"
         << std::flush;
  }
}

bool RunCheckpoints::due(double t, bool last) { return enabled_ && schedule_.due(t, last); }

std::string RunCheckpoints::write(CheckpointData& data, double t, long step) {
  putSceneIdentity(data, scene_, program_);
  data.put("run.checkpoints", schedule_.position());
  data.put("run.clock", std::vector<double>{t, static_cast<double>(step)});
  const std::string path = checkpointPath(dir_, base_, step);
  writeCheckpoint(comm_, path, data, t, step);
  return path;
}

}  // namespace mpmice::core
