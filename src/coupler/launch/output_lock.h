#pragma once
/// @brief The output-directory lock of an MPMD participant program (core/io/run_lock.h).
#include <memory>

#include "core/io/run_lock.h"
#include "core/scene/scene.h"
#include "coupler/launch/participant.h"

namespace mpmice::coupler {

/// Locks <scene>.<program> on the participant's rank 0. Refused alone: every rank throws
/// std::invalid_argument with the message. Refused in an MPMD launch: the local rank 0 prints
/// "<program>: error: <message>" and the whole launch is aborted (the peer would otherwise wait
/// for the handshake until coupling.timeout).
std::unique_ptr<core::RunLock> lockParticipantOutput(const Participant& participant, const core::Scene& scene,
                                                     const char* program);

}  // namespace mpmice::coupler
