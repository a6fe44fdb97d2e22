#pragma once
/// @brief A solid-only run of the scene (mpm_solver without a peer).
///
/// Steps to time.end (or time.max_steps) with progress lines, landing steps on the output times
/// (core/time/time_loop.h). At t = 0, at every output.interval and at the last step (unless
/// output.enabled is false): one HDF5 file of particles and grid nodes plus the XDMF index
/// (mpm_output.h), and a row of energies in <directory>/<scene>_energies.csv. Probes
/// (output.probes): the position and displacement of their particles at t = 0 and after every
/// step in <directory>/<scene>_probes.csv. Checkpoints (output.checkpoint_interval) hold the
/// solver, the output schedule, the XDMF index and the CSV lengths; `restart` (a checkpoint file
/// or an output directory, `--restart PATH`) resumes from one and continues the same series.
#include <functional>
#include <ostream>
#include <string>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::mpm {

class MpmSolver;

/// Runs the scene to its end on `comm`, printing to `log` (rank 0); returns the exit status.
/// `prepare` (optional, collective) is called once on the solver before the first step (and
/// after a restart's checkpoint is loaded): mpm_solver sets the scene's file loads there.
int runStandalone(const core::Scene& scene, const core::Comm& comm, std::ostream& log,
                  const std::string& restart = "", const std::function<void(MpmSolver&)>& prepare = {});

}  // namespace mpmice::mpm
