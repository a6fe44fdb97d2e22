#include "coupler/launch/output_lock.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "core/parallel/mpi_session.h"

namespace mpmice::coupler {

std::unique_ptr<core::RunLock> lockParticipantOutput(const Participant& participant, const core::Scene& scene,
                                                     const char* program) {
  try {
    return core::lockOutputDirectory(participant.local(), scene, program, &std::cerr);
  } catch (const std::exception& ex) {
    if (!participant.coupled()) throw std::invalid_argument(ex.what());
    if (participant.local().root()) std::fprintf(stderr, "%s: error: %s\n", program, ex.what());
    std::fflush(stderr);
    core::MpiSession::abortAll(1);
  }
}

}  // namespace mpmice::coupler
