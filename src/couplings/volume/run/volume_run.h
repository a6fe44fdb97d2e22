#pragma once
/// @brief The one time loop of an MPM-ICE run, in one process (mpmice) or in either program of
/// an MPMD launch (mpm_solver, ice_solver coupled).
///
/// 1. The start common to every schedule (startCoupling).
/// 2. Per step: both sides agree to go on (time.end, time.max_steps) and on the time step (the
///    smaller stable step of the two sides, capped by time.dt_max and landing on time.end; a
///    step below time.dt_min is an error); the scene's schedule takes the step.
/// 3. Output (core::OutputSchedule): fields and particles to HDF5/XDMF (one file set in one
///    process; "_solid" / "_fluid" in MPMD), the conservation CSV of both sides, the probes and
///    the coupling CSV (step, time, dt, iterations, converged, compute_s, exchange_s, residuals)
///    on the side that holds the solid.
/// Checkpoints (output.checkpoint_interval) hold both sides present (solvers and held exchange
/// fields), the schedule (the acceleration's history), the clock and counters, the output
/// schedule, the XDMF index and the CSV lengths: `<scene>[_solid|_fluid]_checkpoint_<step>.h5`.
/// `restart` (`--restart PATH`) resumes from one: the start is made as usual (so both programs
/// of an MPMD launch trade the same messages), then everything is returned to the checkpoint.
/// 4. Progress lines with an estimate of the time left, and closing lines: iterations per step,
///    steps accepted unconverged, the compute/exchange split of this process.
#include <functional>
#include <ostream>
#include <string>

#include "coupler/transport/transport.h"
#include "couplings/volume/schedule/sides.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Runs the scene to its end. label: who runs ("mpmice", "mpm_solver, coupled to 'ice'");
/// afterStep(n): called after step n (the MPMD launch tests' fault injection). Returns 0.
int runVolumeCoupling(const core::Scene& scene, const Sides& sides, Transport& transport, const core::Comm& comm,
                      std::ostream& log, const std::string& label, const std::function<void(long)>& afterStep = {},
                      const std::string& restart = "");

}  // namespace mpmice::coupler
