#pragma once
/// @brief What a surface-coupled fluid (the OpenFOAM adapter) and the MPM solid tell each other.
///
/// Surface coupling: the fluid owns a mesh whose boundary patch is the solid's surface. Unlike
/// MPM-ICE (cell fields on one shared mesh), only interface data cross: the fluid's forces on
/// its patch faces, the solid's displacement of the patch points. The leaders talk over the
/// launch's inter-communicator; each side broadcasts to its own ranks.
///
/// Start:   handshake (scene hash, interface, schedule)
///          fluid -> solid  SurfaceSetup: sizes, depth, time window, the patch geometry
/// Window:  fluid -> solid  WindowHeader {t_end, dt, last} + face forces (3 per face, N)
///          solid -> fluid  WindowReply {action, iterations, write} + point displacements (3 per point, m)
/// action: advance (accept the window), repeat (implicit: the fluid restores its checkpoint and
/// solves the window again with the new displacements). write: 1 when the solid writes a restart
/// checkpoint at this accepted window (output.checkpoint_interval); the fluid then writes its
/// state at the same time (OpenFOAM: its time directory, the new displacements in it).
#include <string>
#include <vector>

#include "coupler/launch/handshake.h"
#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

inline constexpr int kSurfaceTag = 41;

/// The patch as the fluid sees it at t = 0 (structure of arrays would not help: it crosses MPI).
struct SurfaceSetup {
  int faces = 0, points = 0;
  double depth = 1;               // extent of a 2D fluid mesh in its empty direction [m]
  double dt = 0, start = 0, end = 0;  // the fluid's (fixed) time step: the coupling window
  std::vector<double> faceCentres;  // 3 per face
  std::vector<double> pointCoords;  // 3 per point
};

enum class WindowAction { Advance = 0, Repeat = 1 };

struct WindowHeader {
  double tEnd = 0, dt = 0;
  bool last = false;
};

/// The sections both sides must agree on.
HandshakeSections surfaceHandshakeSections(const core::Scene& scene);

/// Leader to leader: a vector of any length (its length goes first). Every local rank of the
/// receiving side gets the vector. Waits are timed (CouplingTimeout names the peer and `what`).
void sendVector(const Participant& p, const std::vector<double>& v, const std::string& what);
std::vector<double> receiveVector(const Participant& p, const std::string& what);

void sendSetup(const Participant& p, const SurfaceSetup& s);
SurfaceSetup receiveSetup(const Participant& p);

/// Checks what the solid must know about the fluid's time: throws std::invalid_argument naming
/// the scene keys and the OpenFOAM controlDict entries that disagree. `start`: the time the solid
/// starts from (0, or a restart's checkpoint time), which the fluid must start from too.
void checkFluidTime(const SurfaceSetup& s, const core::Scene& scene, double start = 0.0);

}  // namespace mpmice::coupler
