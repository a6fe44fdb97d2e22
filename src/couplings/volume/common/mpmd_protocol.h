#pragma once
/// @brief What the two MPM-ICE participants agree on at start-up and every step of an MPMD launch.
///
/// Start-up: the handshake sections (mesh, materials, scene hash, schedule, exchanged fields).
/// (Every step both sides then agree on going on and on the time step through the transport;
/// run/volume_run.h.)
#include <vector>

#include "coupler/launch/handshake.h"
#include "coupler/launch/participant.h"
#include "core/scene/scene.h"
#include "couplings/volume/common/exchange_declaration.h"

namespace mpmice::coupler {

/// The sections both participants must agree on.
HandshakeSections mpmiceHandshakeSections(const core::Scene& scene);

/// Trades this program's exchange declaration (`mine`: the solid's when `solid`, else the
/// fluid's) with the peer's and agrees on what travels (agree(): the same verdict on both sides,
/// a mismatch throws HandshakeMismatch naming both lists).
FieldUses agreeExchange(const Participant& p, const core::Scene& scene, bool solid, const ExchangeDeclaration& mine);

/// Fault injection for the launch tests: when the environment sets MPMICE_FAULT_EXIT=<name>:<step>,
/// the participant called <name> ("mpm" or "ice") exits abruptly (status 9, no MPI_Finalize) after
/// that step, as a crashed program would; MPMICE_FAULT_STALL=<name>:<step> makes it sleep for ever
/// after that step, as a stopped or hung program would.
void maybeInjectFault(const Participant& p, long step);

}  // namespace mpmice::coupler
