#include "couplings/surface/solid/surface_solid_participant.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "coupler/acceleration/acceleration.h"
#include "coupler/iteration/implicit_iteration.h"
#include "core/io/csv_writer.h"
#include "core/io/run_checkpoints.h"
#include "coupler/mapping/mapping.h"
#include "mpm/solver/health_check.h"
#include "mpm/solver/mpm_output.h"
#include "mpm/solver/mpm_solver.h"
#include "mpm/solver/probes.h"
#include "couplings/surface/solid/surface_particles.h"
#include "couplings/surface/surface_protocol.h"
#include "core/time/time_loop.h"
#include "core/util/progress.h"

namespace mpmice::coupler {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

PointCloud cloudOf(const std::vector<double>& xyz) {
  PointCloud c;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) c.add(xyz[i], xyz[i + 1], xyz[i + 2]);
  return c;
}

/// The surface particles' data by slot of the global SurfaceCloud order.
class SurfaceSlots {
 public:
  explicit SurfaceSlots(const SurfaceCloud& c) {
    for (std::size_t k = 0; k < c.size(); ++k) slot_[c.ids[k]] = k;
    n_ = c.size();
  }
  /// Sets fsurf of the local surface particles from per-slot forces (3 per slot).
  void setForces(mpm::ParticleSet& p, const std::vector<double>& f) const {
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.surface[i] == 0.0) continue;
      const std::size_t k = slot_.at(p.id[i]);
      for (int d = 0; d < 3; ++d) p.fsurf[d][i] = f[3 * k + static_cast<std::size_t>(d)];
    }
  }
  /// Displacements x - x0 per slot (3 per slot), summed over the ranks.
  std::vector<double> displacements(const mpm::ParticleSet& p, const core::Comm& comm) const {
    std::vector<double> u(3 * n_, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.surface[i] == 0.0) continue;
      const std::size_t k = slot_.at(p.id[i]);
      for (int d = 0; d < 3; ++d) u[3 * k + static_cast<std::size_t>(d)] = p.x[d][i] - p.x0[d][i];
    }
    comm.sumInPlace(u);
    return u;
  }

 private:
  std::unordered_map<std::int64_t, std::size_t> slot_;
  std::size_t n_ = 0;
};

Eigen::VectorXd asVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

int runSurfaceSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                               const std::string& restart) {
  const core::InterfaceSpec& iface = scene.coupling.interface;
  handshake(p, surfaceHandshakeSections(scene));
  const core::Comm& comm = p.local();
  const bool root = comm.root();
  const int dim = scene.mesh.dim();
  const bool oneWay = iface.mode == core::CouplingMode::OneWay;
  const bool implicit = scene.coupling.schedule == core::Schedule::ImplicitSerial;
  if (oneWay && (scene.output.checkpoint_interval > 0 || !restart.empty()))
    throw std::invalid_argument(scene.coupling.interface.where.str() +
                                ": coupling.interface.mode: one_way writes no checkpoints and does not resume (the fluid "
                                "runs alone first, then the solid): set output.checkpoint_interval: 0, or mode: two_way");

  mpm::MpmSolver mpm(scene, comm);
  mpm.enableSurfaceForces();
  const int material = scene.materialIndex(iface.solid);
  const long long nSurface = comm.sum(static_cast<long long>(markSurfaceParticles(mpm, material)));
  if (nSurface == 0)
    throw std::invalid_argument("coupling.interface.solid: material '" + iface.solid + "' has no particles");
  const SurfaceCloud cloud = gatherSurfaceCloud(mpm);
  const SurfaceSlots slots(cloud);

  // A restart: the particles, the clock, the window counters, the displacements the fluid holds,
  // the acceleration's history and the fluid's patch at t = 0 (the maps are built from it) come
  // from the checkpoint; the fluid resumes from its time directory of the same time.
  core::RunCheckpoints checkpoints(scene, comm, scene.name, "mpm_solver (surface-coupled)", restart, &log);
  const core::CheckpointData* resumed = checkpoints.resumed();
  std::vector<double> state{0.0, 0.0, 0.0, 0.0};  // t, window, MPM sub-steps, coupling iterations
  if (resumed) {
    mpm.loadCheckpoint(*resumed, "mpm");
    state = resumed->get("run.surface");
    if (state.size() != 4) throw std::invalid_argument(resumed->source() + ": checkpoint entry 'run.surface' is malformed");
  }
  SurfaceSetup setup = receiveSetup(p);
  checkFluidTime(setup, scene, state[0]);
  if (resumed) {
    const auto& faces = resumed->get("surface.face_centres");
    const auto& points = resumed->get("surface.points");
    if (faces.size() != setup.faceCentres.size() || points.size() != setup.pointCoords.size())
      throw std::invalid_argument(resumed->source() + ": the checkpoint's patch has " + std::to_string(faces.size() / 3) +
                                  " faces and " + std::to_string(points.size() / 3) + " points, the fluid's case " +
                                  std::to_string(setup.faces) + " and " + std::to_string(setup.points));
    setup.faceCentres = faces;  // the maps of t = 0 (the fluid's mesh has moved since)
    setup.pointCoords = points;
  }
  const double forceScale = dim == 2 ? 1.0 / setup.depth : 1.0;  // 2D MPM: per unit depth
  const PointCloud particles = cloudOf(cloud.x0);
  auto forceMap = makeMapping(iface.mapping, iface.rbf_support);
  forceMap->compute(particles, cloudOf(setup.faceCentres), dim);
  auto dispMap = makeMapping(iface.mapping, iface.rbf_support);
  dispMap->compute(particles, cloudOf(setup.pointCoords), dim);

  core::Progress progress(log, comm, state[0], oneWay ? 2 * scene.time.end : scene.time.end,
                          core::ProgressOptions{2.0, 0});
  progress.start(scene.name + " (mpm_solver, surface-coupled to '" + p.peerName() + "', " + std::string(core::name(iface.mode)) + ", " +
                     std::string(core::name(scene.coupling.schedule)) + ")",
                 scene.mesh.describe(), comm.size());
  if (root) {
    for (const std::string& w : mpm.geometryWarnings()) log << "warning: " << w << "\n";
    log << "  interface: " << nSurface << " surface particles of '" << iface.solid << "'; patch '" << iface.patch
        << "' with " << setup.faces << " faces, " << setup.points << " points (depth " << setup.depth
        << " m); mapping " << forceMap->name() << "; window " << setup.dt << " s\n"
        << std::flush;
  }

  std::unique_ptr<mpm::MpmOutput> output;
  std::unique_ptr<core::CsvWriter> csv;
  if (scene.output.enabled) {
    output = std::make_unique<mpm::MpmOutput>(mpm);
    const std::string path = scene.output.directory + "/" + scene.name + "_coupling.csv";
    if (resumed) {
      core::CsvWriter::cutForResume(comm, path, static_cast<std::int64_t>(resumed->scalar("run.coupling_csv")));
      output->resumeIndex(resumed->text("run.xdmf"));
    }
    csv = std::make_unique<core::CsvWriter>(
        comm, path,
        std::vector<std::string>{"window", "time", "dt", "iterations", "converged", "substeps", "force_x", "force_y",
                                 "force_z", "residual", "compute_s", "exchange_s"},
        0, resumed ? core::CsvWriter::Mode::Append : core::CsvWriter::Mode::Truncate);
  }
  core::OutputSchedule outputs(scene.output.interval, scene.time.end);
  if (resumed) {
    outputs.resume(resumed->get("run.outputs"));
  } else if (outputs.due(0.0) && output) {
    mpm.projectToGrid();
    output->write(mpm);
  }
  // Collective; null without probes.
  const auto probes =
      mpm::ProbeRecorder::fromScene(mpm, resumed ? static_cast<std::int64_t>(resumed->scalar("run.probes_csv")) : -1);
  if (probes && !resumed) probes->record(mpm);

  // Implicit: the iterate is the displacement of the patch points; measures and acceleration
  // work on data every solid rank holds in full (a communicator of one).
  const core::Comm self(MPI_COMM_SELF);
  std::unique_ptr<ImplicitIteration> iteration;
  if (implicit) {
    auto conv = scene.coupling.convergence;
    if (conv.empty()) conv.push_back({"interface_displacement", core::MeasureType::Relative, 1e-4, true});
    for (const auto& c : conv)
      if (c.field != "interface_displacement" && c.field != "interface_force")
        throw std::invalid_argument("coupling.convergence: field '" + c.field +
                                    "' is not exchanged by a surface coupling; valid: interface_displacement, "
                                    "interface_force");
    iteration = std::make_unique<ImplicitIteration>(scene.coupling, conv, self);
    if (resumed) iteration->load(*resumed, "schedule");
  }

  // What the fluid uses (its patch holds the same: the time directory of a restart has it).
  std::vector<double> dispPoints =
      resumed ? resumed->get("surface.displacements") : std::vector<double>(3 * static_cast<std::size_t>(setup.points), 0.0);
  if (dispPoints.size() != 3 * static_cast<std::size_t>(setup.points))
    throw std::invalid_argument(resumed->source() + ": checkpoint entry 'surface.displacements' is malformed");
  std::vector<double> lastForces;
  double t = state[0];
  long window = static_cast<long>(state[1]), substepsTotal = static_cast<long>(state[2]),
       iterationsTotal = static_cast<long>(state[3]);
  // After an accepted window (and its output): the solid's checkpoint; the fluid wrote its time
  // directory of the same time when the reply asked it to.
  auto checkpoint = [&] {
    core::CheckpointData data;
    mpm.saveCheckpoint(data, "mpm");
    if (iteration) iteration->save(data, "schedule");
    data.put("run.surface", std::vector<double>{t, double(window), double(substepsTotal), double(iterationsTotal)});
    data.put("surface.displacements", dispPoints);
    data.put("surface.face_centres", setup.faceCentres);
    data.put("surface.points", setup.pointCoords);
    data.put("run.outputs", outputs.position());
    data.put("run.coupling_csv", static_cast<double>(csv ? csv->length() : 0));
    data.put("run.probes_csv", static_cast<double>(probes ? probes->csvLength() : 0));
    data.putText("run.xdmf", output ? output->indexState() : std::string());
    checkpoints.write(data, t, window);
  };
  auto mapForces = [&](const std::vector<double>& faceForces) {
    std::vector<double> f(3 * cloud.size(), 0.0);
    forceMap->mapConservative(faceForces.data(), f.data(), 3);
    for (double& v : f) v *= forceScale;
    if (dim == 2)
      for (std::size_t k = 0; k < cloud.size(); ++k) f[3 * k + 2] = 0.0;
    slots.setForces(mpm.particles(), f);
  };
  auto advanceTo = [&](double tEnd) {
    long n = 0;
    while (!core::reached(mpm.time(), tEnd) && mpm.time() < tEnd - 1e-15) {
      mpm.advance(tEnd);
      mpm::checkHealth(mpm);  // a violation ends the launch (mpm_solver's main aborts it)
      ++n;
    }
    return n;
  };
  auto solidDisplacement = [&] {
    const std::vector<double> u = slots.displacements(mpm.particles(), comm);
    std::vector<double> d(3 * static_cast<std::size_t>(setup.points), 0.0);
    dispMap->mapConsistent(u.data(), d.data(), 3);
    if (dim == 2)
      for (int k = 0; k < setup.points; ++k) d[3 * static_cast<std::size_t>(k) + 2] = 0.0;
    return d;
  };
  auto totalForce = [](const std::vector<double>& f) {
    std::array<double, 3> s{0, 0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) s[i % 3] += f[i];
    return s;
  };
  bool writeNow = false;  // this window's checkpoint is due (the fluid writes its state too)
  auto reply = [&](WindowAction a, int iterations, const std::vector<double>& d) {
    const bool write = a == WindowAction::Advance && writeNow;
    sendVector(p, {double(static_cast<int>(a)), double(iterations), write ? 1.0 : 0.0}, "window reply");
    sendVector(p, d, "patch displacements");
  };

  for (;;) {
    double compute = 0, exchange = 0, t0 = now();
    auto lap = [&](double& bucket) {
      const double t1 = now();
      bucket += t1 - t0;
      t0 = t1;
    };
    const std::vector<double> h = receiveVector(p, "window header");
    if (h.size() != 3) throw std::runtime_error("coupler: malformed window header from '" + p.peerName() + "'");
    const WindowHeader head{h[0], h[1], h[2] != 0.0};
    writeNow = !oneWay && checkpoints.due(head.tEnd, head.last);
    std::vector<double> forces = receiveVector(p, "patch face forces");
    if (forces.size() != 3u * std::size_t(setup.faces))
      throw std::runtime_error("coupler: " + std::to_string(forces.size() / 3) + " face forces from '" +
                               p.peerName() + "', expected " + std::to_string(setup.faces));
    lap(exchange);
    int iterations = 1;
    bool converged = true;
    long substeps = 0;
    double residual = 0;
    if (oneWay) {
      lastForces = forces;
      reply(WindowAction::Advance, 1, dispPoints);  // zeros: the fluid's mesh stays
      lap(exchange);
    } else if (!implicit) {
      mapForces(forces);
      substeps = advanceTo(head.tEnd);
      dispPoints = solidDisplacement();
      lap(compute);
      reply(WindowAction::Advance, 1, dispPoints);
      lap(exchange);
    } else {
      const auto cp = mpm.checkpoint();
      iteration->beginStep();
      std::vector<double> prevForces;
      std::ostringstream when;
      when << "the window ending at t = " << head.tEnd;
      StepReport report;
      for (int k = 1;; ++k) {
        if (k > 1) {
          (void)receiveVector(p, "window header (iteration " + std::to_string(k) + ")");
          forces = receiveVector(p, "patch face forces (iteration " + std::to_string(k) + ")");
          lap(exchange);
        }
        mpm.restore(cp);
        mapForces(forces);
        substeps = advanceTo(head.tEnd);
        const std::vector<double> dTilde = solidDisplacement();
        // Displacements: this iteration's input against its output; forces: the fluid's of the
        // last iteration against this one's (none to compare with in the first).
        std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> values;
        for (const auto& f : iteration->measuredFields()) {
          if (f == "interface_displacement")
            values.emplace_back(asVector(dispPoints), asVector(dTilde));
          else
            values.emplace_back(k > 1 ? asVector(prevForces) : Eigen::VectorXd(), asVector(forces));
        }
        const bool done = iteration->judge(k, values, when.str(), report);
        converged = report.converged;
        residual = report.residuals.empty() ? 0.0 : report.residuals.back();
        iterations = k;
        lap(compute);
        if (done) {
          iteration->endStep();
          dispPoints = dTilde;
          reply(WindowAction::Advance, k, dispPoints);
          lap(exchange);
          break;
        }
        const Eigen::VectorXd next = iteration->accelerate(asVector(dispPoints), asVector(dTilde));
        dispPoints.assign(next.data(), next.data() + next.size());
        prevForces = forces;
        reply(WindowAction::Repeat, k, dispPoints);
        lap(exchange);
      }
    }
    ++window;
    substepsTotal += substeps;
    iterationsTotal += iterations;
    t = head.tEnd;
    const auto F = totalForce(forces);
    if (csv)
      csv->row({double(window), t, head.dt, double(iterations), converged ? 1.0 : 0.0, double(substeps), F[0], F[1],
                F[2], residual, compute, exchange});
    if (probes && !oneWay) probes->record(mpm);
    if (!oneWay && outputs.due(mpm.time()) && output) output->write(mpm);
    // The last window's line always (the coupled progress line of `coupler run` shows it).
    progress.step(static_cast<int>(window), t, head.dt,
                  {{"iters", double(iterations)}, {"iters_total", double(iterationsTotal)}, {"mpm_substeps", double(substeps)}},
                  head.last);
    if (writeNow) checkpoint();
    if (head.last) break;
  }

  if (oneWay) {
    // The classic sequential approach: the fluid's final forces, once, on a structure that
    // relaxes (mpm.damping) to a static state over time.end.
    if (root) {
      const auto F = totalForce(lastForces);
      log << "  one-way: the fluid's forces at t = " << t << " (total " << F[0] << ", " << F[1] << ", " << F[2]
          << " N) now load the solid, relaxed over " << scene.time.end << " s (damping " << scene.mpm.damping
          << " 1/s)\n"
          << std::flush;
    }
    mapForces(lastForces);
    long n = 0;
    while (!core::reached(mpm.time(), scene.time.end)) {
      const double dt = mpm.advance(scene.time.end);
      mpm::checkHealth(mpm);
      ++n;
      if (probes) probes->record(mpm);
      if (outputs.due(mpm.time()) && output) output->write(mpm);
      progress.step(static_cast<int>(window + n), t + mpm.time(), dt);
    }
    substepsTotal += n;
  }
  if (!outputs.written(mpm.time()) && output) output->write(mpm);  // the last step, always
  // Work per window: the MPM particle-steps it took (sub-cycling included).
  const long windowsAll = oneWay ? window + (substepsTotal > 0 ? 1 : 0) : window;
  progress.finish(static_cast<int>(windowsAll), oneWay ? t + mpm.time() : t,
                  double(mpm.globalParticleCount()) * double(substepsTotal) / std::max(1.0, double(windowsAll)),
                  "particle-steps");
  return 0;
}

}  // namespace mpmice::coupler
