// The C interface of adapters/openfoam/bridge/mpmice_bridge.h over the coupler's surface protocol.
#include "mpmice_bridge.h"

#include <mpi.h>

#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "coupler/launch/participant.h"
#include "core/parallel/comm.h"
#include "core/scene/scene.h"
#include "couplings/surface/surface_protocol.h"

using namespace mpmice;

struct mpmice_bridge {
  std::string error;
  bool ownsMpi = false;
  std::optional<core::Scene> scene;
  std::optional<coupler::Participant> participant;
  int faces = 0, points = 0;
  bool writeDue = false;  // the last accepted window's reply asked for the fluid's restart state
};

namespace {

template <class F>
int guarded(mpmice_bridge* b, F&& f) {
  if (!b) return 1;
  if (!b->error.empty()) return 1;
  try {
    f();
    return 0;
  } catch (const std::exception& e) {
    b->error = e.what();
  } catch (...) {
    b->error = "unknown error in the coupler bridge";
  }
  return 1;
}

}  // namespace

extern "C" {

mpmice_bridge* mpmice_bridge_start(const char* scene_file) {
  auto* b = new (std::nothrow) mpmice_bridge;
  if (!b) return nullptr;
  guarded(b, [&] {
    b->scene = core::loadScene(scene_file ? scene_file : "");
    if (b->scene->coupling.fluid != mpmice::core::FluidSolver::OpenFoam)
      throw std::invalid_argument(std::string(scene_file) + ": coupling.fluid is '" + std::string(mpmice::core::name(b->scene->coupling.fluid)) +
                                  "'; the OpenFOAM adapter needs coupling.fluid: openfoam");
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SINGLE, &provided);
      b->ownsMpi = true;
    }
    // The bridge is this program's launch layer: the one place that names the world.
    b->participant.emplace(coupler::Participant::join(core::Comm(MPI_COMM_WORLD), "openfoam", b->scene->coupling.timeout));
    if (b->participant->coupled()) coupler::handshake(*b->participant, coupler::surfaceHandshakeSections(*b->scene));
  });
  return b;
}

const char* mpmice_bridge_error(const mpmice_bridge* b) {
  if (!b) return "out of memory";
  return b->error.empty() ? nullptr : b->error.c_str();
}

int mpmice_bridge_info_get(const mpmice_bridge* b, mpmice_bridge_info* info) {
  if (!b || !info || !b->scene || !b->participant) return 1;
  const auto& i = b->scene->coupling.interface;
  info->coupled = b->participant->coupled() ? 1 : 0;
  info->two_way = i.mode == mpmice::core::CouplingMode::TwoWay ? 1 : 0;
  info->implicit = b->scene->coupling.schedule == mpmice::core::Schedule::ImplicitSerial ? 1 : 0;
  info->fluid_density = i.fluid_density;
  std::strncpy(info->patch, i.patch.c_str(), sizeof(info->patch) - 1);
  info->patch[sizeof(info->patch) - 1] = '\0';
  return 0;
}

int mpmice_bridge_set_patch(mpmice_bridge* b, int n_faces, const double* face_centres, int n_points,
                            const double* points, double depth, double dt, double start, double end) {
  return guarded(b, [&] {
    if (!b->participant->coupled()) return;
    coupler::SurfaceSetup s;
    s.faces = n_faces;
    s.points = n_points;
    s.depth = depth;
    s.dt = dt;
    s.start = start;
    s.end = end;
    s.faceCentres.assign(face_centres, face_centres + 3 * n_faces);
    s.pointCoords.assign(points, points + 3 * n_points);
    coupler::sendSetup(*b->participant, s);
    b->faces = n_faces;
    b->points = n_points;
  });
}

int mpmice_bridge_exchange(mpmice_bridge* b, double t_end, double dt, int last, const double* face_forces,
                           double* point_displacements, int* action, int* iterations) {
  return guarded(b, [&] {
    *action = 0;
    *iterations = 1;
    b->writeDue = false;
    if (!b->participant->coupled()) return;
    const auto& p = *b->participant;
    coupler::sendVector(p, {t_end, dt, last ? 1.0 : 0.0}, "window header");
    coupler::sendVector(p, std::vector<double>(face_forces, face_forces + 3 * b->faces), "patch face forces");
    const std::vector<double> r = coupler::receiveVector(p, "window reply");
    const std::vector<double> d = coupler::receiveVector(p, "patch displacements");
    if (r.size() != 3 || d.size() != 3u * static_cast<std::size_t>(b->points))
      throw std::runtime_error("coupler: malformed reply from '" + p.peerName() + "'");
    *action = static_cast<int>(r[0]);
    *iterations = static_cast<int>(r[1]);
    b->writeDue = r[2] != 0.0;
    std::memcpy(point_displacements, d.data(), d.size() * sizeof(double));
  });
}

int mpmice_bridge_write_due(const mpmice_bridge* b) { return b && b->writeDue ? 1 : 0; }

void mpmice_bridge_finish(mpmice_bridge* b) {
  if (!b) return;
  const bool owns = b->ownsMpi;
  b->participant.reset();
  delete b;
  if (owns) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
}

}  // extern "C"
