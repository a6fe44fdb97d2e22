#pragma once
/// @brief The solid side of an MPMD MPM-ICE launch: mpm_solver coupled to ice_solver.
///
/// After the handshake, the scene's schedule and the one time loop (run/volume_run.h) with the
/// solid side only; the fields cross rank to rank (MpiTransport). Writes its particles
/// (HDF5/XDMF, file suffix "_solid"), the conservation CSV of both sides and the coupling CSV.
#include <ostream>

#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Returns the exit status (0 on success). Throws CouplingTimeout / HandshakeMismatch.
int runSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                        const std::string& restart = "");

}  // namespace mpmice::coupler
