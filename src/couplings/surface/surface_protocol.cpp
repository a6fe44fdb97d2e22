#include "couplings/surface/surface_protocol.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "coupler/launch/timed_wait.h"

namespace mpmice::coupler {

HandshakeSections surfaceHandshakeSections(const core::Scene& s) {
  const auto& i = s.coupling.interface;
  std::ostringstream iface;
  iface << "solid " << i.solid << ", patch " << i.patch << ", mapping " << core::name(i.mapping) << " (support " << i.rbf_support
        << "), mode " << core::name(i.mode) << ", fluid density " << i.fluid_density;
  return {{"scene hash (mesh, materials, boundary)", core::sceneHash(s)},
          {"interface", iface.str()},
          {"schedule", std::string(core::name(s.coupling.schedule))},
          {"exchanged fields", "fluid -> solid: face forces | solid -> fluid: point displacements"}};
}

void sendVector(const Participant& p, const std::vector<double>& v, const std::string& what) {
  if (!p.local().root()) return;
  double n = static_cast<double>(v.size());
  std::vector<MPI_Request> reqs(2);
  MPI_Isend(&n, 1, MPI_DOUBLE, 0, kSurfaceTag, p.inter(), &reqs[0]);
  MPI_Isend(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, 0, kSurfaceTag + 1, p.inter(), &reqs[1]);
  waitAll(reqs, p.timeout(), p.peerName(), what);
}

std::vector<double> receiveVector(const Participant& p, const std::string& what) {
  double n = 0;
  std::vector<double> v;
  if (p.local().root()) {
    std::vector<MPI_Request> reqs(1);
    MPI_Irecv(&n, 1, MPI_DOUBLE, 0, kSurfaceTag, p.inter(), &reqs[0]);
    waitAll(reqs, p.timeout(), p.peerName(), what + " (size)");
    v.resize(static_cast<std::size_t>(n));
    MPI_Irecv(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, 0, kSurfaceTag + 1, p.inter(), &reqs[0]);
    waitAll(reqs, p.timeout(), p.peerName(), what);
  }
  MPI_Bcast(&n, 1, MPI_DOUBLE, 0, p.local().raw());
  v.resize(static_cast<std::size_t>(n));
  MPI_Bcast(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, 0, p.local().raw());
  return v;
}

void sendSetup(const Participant& p, const SurfaceSetup& s) {
  sendVector(p, {double(s.faces), double(s.points), s.depth, s.dt, s.start, s.end}, "interface set-up");
  sendVector(p, s.faceCentres, "patch face centres");
  sendVector(p, s.pointCoords, "patch points");
}

SurfaceSetup receiveSetup(const Participant& p) {
  const std::vector<double> h = receiveVector(p, "interface set-up");
  if (h.size() != 6) throw std::runtime_error("coupler: malformed interface set-up from '" + p.peerName() + "'");
  SurfaceSetup s;
  s.faces = static_cast<int>(h[0]);
  s.points = static_cast<int>(h[1]);
  s.depth = h[2];
  s.dt = h[3];
  s.start = h[4];
  s.end = h[5];
  s.faceCentres = receiveVector(p, "patch face centres");
  s.pointCoords = receiveVector(p, "patch points");
  if (s.faceCentres.size() != 3u * std::size_t(s.faces) || s.pointCoords.size() != 3u * std::size_t(s.points))
    throw std::runtime_error("coupler: patch geometry from '" + p.peerName() + "' does not match its sizes");
  return s;
}

void checkFluidTime(const SurfaceSetup& s, const core::Scene& scene, double start) {
  if (!(s.dt > 0))
    throw std::invalid_argument("the fluid's deltaT (system/controlDict) must be > 0; it is the coupling window");
  if (std::abs(s.start - start) > 1e-12 * std::max(1.0, std::abs(start))) {
    std::ostringstream os;
    os.precision(17);
    os << "the fluid case starts at t = " << s.start << " (controlDict startTime); ";
    if (start == 0.0)
      os << "coupled runs start at 0";
    else
      os << "the solid resumes its checkpoint at t = " << start << " (`coupler run --restart` starts both there)";
    throw std::invalid_argument(os.str());
  }
  if (std::abs(s.end - scene.time.end) > 0.5 * s.dt) {
    std::ostringstream os;
    os << "time.end is " << scene.time.end << " s in the scene but the fluid case's controlDict endTime is " << s.end
       << " s; make them equal (`coupler run` sets it from the scene)";
    throw std::invalid_argument(os.str());
  }
}

}  // namespace mpmice::coupler
