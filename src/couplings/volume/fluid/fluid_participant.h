#pragma once
/// @brief The fluid side of an MPMD MPM-ICE launch: ice_solver coupled to mpm_solver.
///
/// The mirror of runSolidParticipant: same handshake, schedule and time loop with the fluid side
/// only. Writes its grid fields (HDF5/XDMF, file suffix "_fluid").
#include <ostream>

#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

int runFluidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                        const std::string& restart = "");

}  // namespace mpmice::coupler
