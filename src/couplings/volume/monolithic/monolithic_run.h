#pragma once
/// @brief The in-process MPM-ICE run (mpmice): libmpm and libice in one process on one
/// decomposition, the exchange points turned into copies (InMemoryTransport).
///
/// The reference that MPMD launches are measured against: the same SolidSide, FluidSide,
/// schedule and time loop (run/volume_run.h) as mpm_solver + ice_solver, so both give the same
/// numbers for every schedule.
#include <ostream>

#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Runs the scene to its end on `comm`; returns the exit status. A scene with only solids or
/// only fluids runs that one solver alone (with a line saying so).
int runMonolithic(const core::Scene& scene, const core::Comm& comm, std::ostream& log,
                  const std::string& restart = "");

}  // namespace mpmice::coupler
