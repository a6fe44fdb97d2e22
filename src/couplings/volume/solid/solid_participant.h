#pragma once
/// @brief The solid side of an MPMD MPM-ICE launch: mpm_solver coupled to ice_solver.
///
/// Runs the monolithic-style schedule with the fluid participant: per step the two sides agree on
/// the time step, then fields A..D cross rank to rank (CellExchange) at the four exchange points.
/// Writes its particles (HDF5/XDMF, file suffix "_solid"), the conservation CSV of both sides
/// and the per-step coupling log (CSV: step, time, dt, compute and exchange seconds).
#include <ostream>

#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Returns the exit status (0 on success). Throws CouplingTimeout / HandshakeMismatch.
int runSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log);

}  // namespace mpmice::coupler
