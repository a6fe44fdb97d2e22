#pragma once
/// @brief A fluid-only run of the scene (ice_solver without a peer).
///
/// Prints the scene, mesh, ranks and materials; steps to time.end (or time.max_steps) with
/// progress lines (the pressure iterations of each step); at t = 0, at every output.interval and
/// at the last step (core/time/time_loop.h) writes HDF5/XDMF output and a row of total mass,
/// momentum and energy to <directory>/<scene>_totals.csv; ends with the summary (steps, wall
/// time, cell-steps/s). Checkpoints (output.checkpoint_interval) hold the solver, the output
/// schedule, the XDMF index and the CSV length; `restart` (`--restart PATH`: a checkpoint file or
/// an output directory) resumes from one and continues the same series.
#include <ostream>
#include <string>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::ice {

/// Runs the scene to its end on `comm`, printing to `log` (rank 0); returns the exit status.
int runStandalone(const core::Scene& scene, const core::Comm& comm, std::ostream& log,
                  const std::string& restart = "");

}  // namespace mpmice::ice
