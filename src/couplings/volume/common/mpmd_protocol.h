#pragma once
/// @brief What the two MPM-ICE participants agree on at start-up and every step of an MPMD launch.
///
/// Start-up: the handshake sections (mesh, materials, scene hash, schedule, exchanged fields).
/// Every step: the time step (the smaller of both sides' stable steps) and whether to go on.
/// At output times: the fluid's totals, so the solid side writes one conservation CSV for both.
#include <vector>

#include "coupler/launch/handshake.h"
#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

inline constexpr int kTradeTag = 31;

/// The sections both participants must agree on.
HandshakeSections mpmiceHandshakeSections(const core::Scene& scene);

/// Leaders trade `mine` (same length on both sides); every local rank gets the peer's values.
std::vector<double> tradeValues(const Participant& p, const std::vector<double>& mine, const std::string& what);

/// Fault injection for the launch tests: when the environment sets MPMICE_FAULT_EXIT=<name>:<step>,
/// the participant called <name> ("mpm" or "ice") exits abruptly (status 9, no MPI_Finalize) after
/// that step, as a crashed program would.
void maybeInjectFault(const Participant& p, long step);

/// Both sides agree whether to take another step (both stop at time.max_steps).
bool agreeToGoOn(const Participant& p, const core::Scene& scene, long stepsTaken);

/// Smaller of this side's and the peer's stable step, capped by dt_max and the time left.
double agreeOnTimeStep(const Participant& p, double mine, double t, const core::Scene& scene);

}  // namespace mpmice::coupler
