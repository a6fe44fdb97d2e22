#pragma once
/// @brief The start-up handshake: both participants check that they read the same scene.
///
/// Each side describes what must agree as named sections (the mesh, the materials, the fields
/// it exchanges, ...). The leaders trade the sections; any section that differs stops both
/// programs with an error that names it and shows both versions. Every rank of both programs
/// gets the same verdict.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "coupler/launch/participant.h"

namespace mpmice::coupler {

using HandshakeSections = std::vector<std::pair<std::string, std::string>>;

class HandshakeMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Trades sections with the peer; returns the peer's sections; throws HandshakeMismatch.
HandshakeSections handshake(const Participant& p, const HandshakeSections& mine);

/// Trades one string with the peer (leaders exchange, then broadcast to local ranks).
std::string tradeWithPeer(const Participant& p, const std::string& mine, const std::string& what);

}  // namespace mpmice::coupler
