#include "mpm/solver/mpm_solver.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <sstream>
#include <stdexcept>

#include "core/health/health.h"
#include "mpm/material/tensor.h"
#include "mpm/solver/kernels.h"
#include "mpm/solver/startup_check.h"

// kernels.h's vector types are passed by value between this file's inline functions; without
// AVX (MPMICE_SIMD baseline) GCC notes the ABI of such calls across objects built with different
// flags (-Wpsabi), which none are. The note comes at the end of the file, where the instantiated
// kernels are emitted, so it is silenced for the file.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace mpmice::mpm {

using core::Field;
using kernels::dispatch;

namespace {

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

MpmSolver::MpmSolver(const core::Scene& scene, const core::Comm& comm, ContainsFn contains)
    : scene_(scene), comm_(comm), collapse_(scene.time.dt_collapse_fraction) {
  const core::Mesh& mesh = scene_.mesh;
  // 1. Options, each checked with the scene key it came from (startup_check.h).
  checkOptions(scene_);
  shape_ = parseShapeFunction(scene_.mpm.shape_function);
  scheme_ = &parseUpdateScheme(scene_.mpm.update);
  flip_ = scene_.mpm.flip;
  damping_ = scene_.mpm.damping;
  gridStressWork_ = scene_.mpm.stress_work == "grid";
  // 2. Decomposition, grid, boundary conditions.
  decomp_ = core::Decomposition(mesh, comm_.size());
  // B-splines (and GIMP within lp of a face) deposit on the node layer outside the mesh: on
  // several ranks it is summed too (beyond mirror planes it is folded inside first).
  const bool wide = shape_ != ShapeKind::Linear;
  grid_ = std::make_unique<Grid>(decomp_, comm_, wide);
  bcs_ = BoundaryConditions(scene_.boundary, mesh, grid_->box());
  // 3. Constitutive models of the solids.
  models_ = createSolidModels(scene_);
  // The particle columns this scene uses (ParticleLayout): the dimension's, loads', surface
  // forces' (file loads here; a surface coupling adds them, enableSurfaceForces) and plastic ones.
  {
    ParticleLayout layout;
    layout.dim = mesh.dim();
    layout.loads = !scene_.loads.empty();
    layout.surface = std::any_of(scene_.loads.begin(), scene_.loads.end(),
                                 [](const core::LoadSpec& l) { return l.type == core::LoadType::File; });
    layout.plastic = std::any_of(models_.begin(), models_.end(), [](const auto& m) { return m && m->plasticHistory(); });
    p_.setLayout(layout);
  }
  // 4. Particles of the cells this rank owns, their loads, then sorted by (material, cell).
  if (!contains)
    contains = [](const core::ShapeSpec& s, const core::RealVect& x, int dim) {
      return s.contains(x, dim);
    };
  {
    std::vector<RegionVolume> volumes;
    generateParticles(scene_, decomp_.cellBox(comm_.rank()), p_, contains, &volumes);
    std::vector<double> v(2 * volumes.size());
    for (std::size_t r = 0; r < volumes.size(); ++r) v[2 * r] = volumes[r].particles, v[2 * r + 1] = volumes[r].shape;
    comm_.sumInPlace(v);
    for (std::size_t r = 0; r < volumes.size(); ++r) volumes[r] = {v[2 * r], v[2 * r + 1]};
    geometryWarnings_ = geometryVolumeWarnings(scene_, volumes, kGeometryVolumeWarning);
  }
  // A solid the scene places but no particle represents is an input error, named here rather
  // than found later by the output or the physics.
  {
    std::vector<double> count(scene_.materials.size(), 0.0);
    for (std::size_t i = 0; i < p_.size(); ++i) count[static_cast<std::size_t>(p_.material[i])] += 1.0;
    comm_.sumInPlace(count);
    checkEverySolidHasParticles(scene_, count);
  }
  for (std::size_t l = 0; l < scene_.loads.size(); ++l) {
    const auto& ld = scene_.loads[l];
    const int mat = loadMaterial(scene_, l, models_);
    if (ld.type == core::LoadType::File) continue;  // held in fsurf (couplings/surface/solid/file_load.h)
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (p_.material[i] == mat &&
          contains(ld.shape, {p_.x[0][i], p_.x[1][i], p_.x[2][i]}, mesh.dim()))
        p_.load[i] = static_cast<std::int32_t>(l);
    if (ld.type == core::LoadType::Pressure && mesh.dim() == 2) assignArcAreas(static_cast<int>(l));
  }
  double minMass = 1e300;
  for (double m : p_.mass) minMass = std::min(minMass, m);
  massFloor_ = kMassFloorFraction * comm_.min(minMass);
  // Only the linear hat needs the cut-off: its gradient stays 1/dx where its weight vanishes. The C1
  // shapes (GIMP, B-splines) have grad w ~ sqrt(w) there, so dt f / m times grad w stays bounded.
  accelFloor_ = shape_ == ShapeKind::Linear ? kSmallMassFraction * comm_.min(minMass) : massFloor_;
  cells_ = std::make_unique<NodeCellOperators>(scene_, decomp_.cellBox(comm_.rank()), *grid_, bcs_, p_, shape_,
                                               massFloor_);
  cells_->setWorkMassFloor(accelFloor_);
  cells_->setComm(comm_);
  nodeWeight_.assign(static_cast<std::size_t>(grid_->numNodes()), 0.0);
  {
    const GridGeom geom = grid_->geom();
    core::forEach(decomp_.cellBox(comm_.rank()), [&](int i, int j, int k) {
      forCellNodes(mesh, i, j, k, [&](int ni, int nj, int nk, double share) {
        nodeWeight_[static_cast<std::size_t>(geom.index(ni, nj, nk))] += share;
      });
    });
  }
  migrateAndSort(true);
}

double MpmSolver::nodeKinetic(const Field& v) const {
  const double* m = grid_->mass.data();
  const double* nw = nodeWeight_.data();
  const auto vc = components(v);
  const std::int64_t n = grid_->numNodes();
  // The number of components a constant of the loop (2D: no z, which was + 0).
  const auto sum = [&]<int kComp>() {
    double e = 0;
    for (std::int64_t k = 0; k < n; ++k) {
      const double w = nw[k];
      if (w == 0.0) continue;
      double v2 = 0;
      for (int d = 0; d < kComp; ++d) v2 += vc[d][k] * vc[d][k];
      e += w * 0.5 * m[k] * v2;
    }
    return e;
  };
  switch (v.ncomp()) {
    case 1: return sum.template operator()<1>();
    case 2: return sum.template operator()<2>();
    default: return sum.template operator()<3>();
  }
}

double MpmSolver::particleKinetic() const {
  double e = 0;
  for (std::size_t i = 0; i < p_.size(); ++i)
    e += 0.5 * p_.mass[i] * (p_.v[0][i] * p_.v[0][i] + p_.v[1][i] * p_.v[1][i] + p_.v[2][i] * p_.v[2][i]);
  return e;
}

double MpmSolver::particleWork() const {
  double e = 0;
  for (std::size_t i = 0; i < p_.size(); ++i) e += p_.work[i];
  return e;
}

MpmSolver::~MpmSolver() = default;

long long MpmSolver::globalParticleCount() const {
  return comm_.sum(static_cast<long long>(p_.size()));
}

double MpmSolver::stableTimeStep() const { return stableTimeStep(nullptr); }

double MpmSolver::stableTimeStep(std::size_t* limiting) const {
  const core::Mesh& mesh = scene_.mesh;
  double dxMin = 1e300;
  for (int d = 0; d < mesh.dim(); ++d) dxMin = std::min(dxMin, mesh.dx(d));
  double cmax = 0;
  std::size_t arg = p_.size();
  if (!limiting && signalSpeedValid_) cmax = signalSpeed_;
  for (std::size_t m = 0; m < models_.size() && (limiting || !signalSpeedValid_); ++m) {
    if (!models_[m]) continue;
    const auto [b, e] = p_.materialRange(static_cast<int>(m));
    std::size_t at = e;
    const double s = models_[m]->maxSignalSpeed(p_, b, e, mesh.dim(), limiting ? &at : nullptr);
    if (s > cmax) {
      cmax = s;
      arg = at;
    }
  }
  const double local = cmax;
  cmax = comm_.max(cmax);
  if (limiting) *limiting = local == cmax && cmax > 0 ? arg : p_.size();
  // The CFL number the transfer scheme is stable at, at most (mpm_constants.h, kMaxStableCfl).
  const double cfl = std::min(scene_.time.cfl, kMaxStableCfl);
  double dt = cmax > 0 ? cfl * dxMin / cmax : scene_.time.dt_max;
  // Explicit damping v (1 - c dt): a step beyond 1 / c would reverse the velocity and, beyond
  // 2 / c, amplify it; the step keeps c dt <= 1.
  if (damping_ > 0) dt = std::min(dt, 1.0 / damping_);
  dt = std::min(dt, scene_.time.dt_max);
  if (step_ == 0 && scene_.time.dt_initial > 0) dt = std::min(dt, scene_.time.dt_initial);
  return dt;
}

std::string MpmSolver::stableTimeStepLimit() const {
  std::size_t i = 0;
  const double dt = stableTimeStep(&i);
  const core::Mesh& mesh = scene_.mesh;
  std::ostringstream os;
  os.precision(6);
  if (damping_ > 0 && dt == 1.0 / damping_ && dt < scene_.time.dt_max) {
    os << "the damping bound 1 / mpm.damping (mpm.damping " << damping_ << " 1/s, dt " << dt << " s)";
    return comm_.firstMessage(comm_.root() ? os.str() : "");
  }
  const bool cfl = dt < scene_.time.dt_max && !(step_ == 0 && dt == scene_.time.dt_initial);
  if (!cfl) {
    os << (step_ == 0 && dt == scene_.time.dt_initial ? "time.dt_initial" : "time.dt_max") << " (dt " << dt << " s)";
    return comm_.firstMessage(comm_.root() ? os.str() : "");
  }
  if (i >= p_.size()) return comm_.firstMessage("");  // another rank holds the particle
  const int m = p_.material[i];
  double x[3], v2 = 0;
  for (int d = 0; d < 3; ++d) x[d] = p_.x[d][i];
  for (int d = 0; d < mesh.dim(); ++d) v2 += p_.v[d][i] * p_.v[d][i];
  os << "the MPM CFL bound min(time.cfl, " << kMaxStableCfl << ") dx_min / (c + |v|) (dt " << dt << " s) at particle "
     << p_.id[i] << " of solid '"
     << scene_.materials[static_cast<std::size_t>(m)].name << "' at x = " << core::formatPoint(x, mesh.dim())
     << " m: wave speed c = " << models_[static_cast<std::size_t>(m)]->waveSpeed(p_.mass[i] / p_.vol[i])
     << " m/s, |v| = " << std::sqrt(v2) << " m/s, density " << p_.mass[i] / p_.vol[i] << " kg/m^3";
  return comm_.firstMessage(os.str());
}

double MpmSolver::advance(double until) {
  double dt = stableTimeStep();
  if (collapse_.collapsed(dt))
    throw core::HealthError(collapse_.message(dt, time_, step_ + 1, stableTimeStepLimit()), comm_.root());
  if (time_ + dt > until) dt = until - time_;
  beginStep(dt);
  if (scheme_->stressFirst) {
    particlesToGrid();
    computeInternalForces();
  } else {
    // USL / MUSL: the forces use the stress the particles carry into the step, so they are
    // scattered in the particle-to-grid pass (kernels::particlesToGridWithForces, same sums).
    scatterToGrid(true);
    finishParticlesToGrid();
    finishInternalForces();
  }
  updateGrid();
  gridToParticles();
  endStep();
  return dt;
}

void MpmSolver::projectToGrid() {
  grid_->mass.fill(0.0);
  grid_->velocity.fill(0.0);
  particlesToGrid();
}

void MpmSolver::assignArcAreas(int l) {
  // 2D pressure on a curved particle layer: each particle carries the arc R dtheta between the
  // mid-angles to its neighbours (sorted by angle about the load's centre over all ranks), R the
  // surface radius (the load shape's inner radius, else the particles' mean radius). Exact total
  // force whatever the lattice, where volume / spacing would alias by a few percent.
  const auto& ld = scene_.loads[l];
  std::vector<double> mine;
  double rsum = 0;
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (p_.load[i] == l) {
      const double dx = p_.x[0][i] - ld.center[0], dy = p_.x[1][i] - ld.center[1];
      mine.push_back(std::atan2(dy, dx));
      rsum += std::hypot(dx, dy);
    }
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(comm_.size())), displ(counts.size());
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_.raw());
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displ[r] = total;
    total += counts[r];
  }
  if (total < 2) return;
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displ.data(), MPI_DOUBLE,
                 comm_.raw());
  std::sort(all.begin(), all.end());
  double R = ld.shape.type == "annulus" ? ld.shape.inner_radius : comm_.sum(rsum) / total;
  const double gapEnd = (all.back() - all.front()) / (total - 1);  // ends reach half a mean gap out
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.load[i] != l) continue;
    const double th = std::atan2(p_.x[1][i] - ld.center[1], p_.x[0][i] - ld.center[0]);
    const auto it = std::lower_bound(all.begin(), all.end(), th);
    const std::size_t k = static_cast<std::size_t>(it - all.begin());
    const double lo = k == 0 ? th - 0.5 * gapEnd : 0.5 * (th + all[k - 1]);
    const double hi = k + 1 == all.size() ? th + 0.5 * gapEnd : 0.5 * (th + all[k + 1]);
    p_.loadArea[i] = R * (hi - lo);
  }
}

void MpmSolver::beginStep(double dt) {
  if (!(dt > 0)) throw std::invalid_argument("MpmSolver::beginStep: dt must be > 0, got " + num(dt));
  dt_ = dt;
  signalSpeedValid_ = false;
  recordRangeValid_ = false;
  cells_->newStep();
  grid_->mass.fill(0.0);
  grid_->velocity.fill(0.0);
  grid_->force.fill(0.0);
  grid_->externalForce.fill(0.0);
  computeLoads();
}

void MpmSolver::computeLoads() {
  if (scene_.loads.empty()) return;
  const int dim = scene_.mesh.dim();
  const double invDim = 1.0 / dim;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    for (int d = 0; d < 3; ++d) p_.fext[d][i] = 0.0;
    const int l = p_.load[i];
    if (l < 0) continue;
    const auto& ld = scene_.loads[l];
    double f = 1.0;
    if (time_ < ld.start)
      f = 0.0;
    else if (ld.ramp > 0)
      f = std::min(1.0, (time_ - ld.start) / ld.ramp);
    const double area = p_.loadArea[i] > 0 ? p_.loadArea[i]
                                           : p_.vol0[i] / std::pow(p_.vol0[i], invDim);  // one layer thick
    if (ld.type == core::LoadType::Traction) {
      for (int d = 0; d < dim; ++d) p_.fext[d][i] = f * area * ld.traction[d];
      continue;
    }
    double n[3] = {0, 0, 0}, len = 0;
    for (int d = 0; d < dim; ++d) n[d] = p_.x[d][i] - ld.center[d];
    if (dim == 3 && (ld.shape.type == "cylinder" || ld.shape.type == "annulus")) {
      const auto& a = ld.shape.axis;
      const double an = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      const double dot = (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / (an * an);
      for (int d = 0; d < 3; ++d) n[d] -= dot * a[d];
    }
    for (int d = 0; d < dim; ++d) len += n[d] * n[d];
    len = std::sqrt(len);
    if (len > 0)
      for (int d = 0; d < dim; ++d) p_.fext[d][i] = f * area * ld.pressure * n[d] / len;
  }
}

void MpmSolver::particlesToGrid() {
  scatterToGrid(false);
  finishParticlesToGrid();
}

void MpmSolver::scatterToGrid(bool forces) {
  Grid& g = *grid_;
  // The ledger's particle sums at the start of the step, taken in the scatter pass.
  kernels::ParticleSums sums;
  const auto mom = components(g.velocity);
  double* mass = g.mass.data();
  const auto f = components(g.force);
  const GridGeom geom = g.geom();
  const double grav[3] = {scene_.gravity[0], scene_.gravity[1], scene_.gravity[2]};
  const bool loads = !scene_.loads.empty() || surfaceForces_;
  dispatch(shape_, scene_.mesh.dim(), [&]<class S, int D>() {
    const auto scatter = [&](const auto& src) {
      if constexpr (D == 1) {
        if (forces)
          kernels::particlesToGridWithForces<D>(src, p_, 0, p_.size(), geom, mass, mom.data(), grav, loads, f.data(),
                                                &sums);
        else
          kernels::particlesToGrid<D>(src, p_, 0, p_.size(), geom, mass, mom.data(), &sums);
      } else {
        // 2D / 3D: through the node records (vector lanes over the node fields, the same bits).
        double* rec = nodeRecords();
        if (forces) {
          recordRange_ = kernels::scatterToRecords<D, true>(src, p_, 0, p_.size(), geom, rec, grav, loads, &sums);
          kernels::unpackScatter<D, true>(rec, recordRange_, mass, mom.data(), f.data());
        } else {
          recordRange_ = kernels::scatterToRecords<D, false>(src, p_, 0, p_.size(), geom, rec, grav, loads, &sums);
          kernels::unpackScatter<D, false>(rec, recordRange_, mass, mom.data(), f.data());
        }
        recordRangeValid_ = true;
      }
    };
    if constexpr (kernels::kCacheStencils<S>) {
      stencilOffset_.resize(p_.size());
      stencilRecord_.resize(p_.size() * kernels::StencilCache<S, D>::kRecord);
      scatter(kernels::StoredStencils<S, D>{p_, {stencilOffset_.data(), stencilRecord_.data()}});
      stencilsValid_ = true;
    } else {
      scatter(kernels::EvaluatedStencils<S, D>{p_, {}});
    }
  });
  ledger_.keParticles = sums.kinetic;
  ledger_.work = sums.work;
}

void MpmSolver::finishParticlesToGrid() {
  Grid& g = *grid_;
  const auto mom = components(g.velocity);
  double* mass = g.mass.data();
  bcs_.fold(g.mass, Parity::Scalar);
  bcs_.fold(g.velocity, Parity::Vector);
  g.sumAndFill({&g.mass, &g.velocity});
  bcs_.mirror(g.mass, Parity::Scalar);
  const std::int64_t n = g.numNodes();
  const int dim = scene_.mesh.dim();
  const double floor = massFloor_;  // a local: the member was reloaded after every store
  for (std::int64_t k = 0; k < n; ++k) {
    const double inv = mass[k] > floor ? 1.0 / mass[k] : 0.0;
    for (int d = 0; d < dim; ++d) mom[d][k] *= inv;
  }
  applyBC(g.velocity);
  ledger_.keNodes = nodeKinetic(g.velocity);
}

template <class F>
void MpmSolver::withStencils(F&& f) {
  dispatch(shape_, scene_.mesh.dim(), [&]<class S, int D>() {
    if constexpr (kernels::kCacheStencils<S>) {
      using Cache = kernels::StencilCache<S, D>;
      if (!stencilsValid_ || stencilOffset_.size() != p_.size()) {
        stencilOffset_.resize(p_.size());
        stencilRecord_.resize(p_.size() * Cache::kRecord);
        const GridGeom geom = grid_->geom();
        kernels::Stencil<S, D> st;
        for (std::size_t i = 0; i < p_.size(); ++i) {
          st.compute(p_, i, geom);
          st.store(stencilOffset_[i], stencilRecord_.data() + i * Cache::kRecord, geom);
        }
        stencilsValid_ = true;
      }
      f.template operator()<S, D>(Cache{stencilOffset_.data(), stencilRecord_.data()});
    } else {
      f.template operator()<S, D>(kernels::EvaluatedStencils<S, D>{p_, {}});
    }
  });
}

template <class F>
void MpmSolver::forParticleBlocks(F&& f) const {
  constexpr std::size_t kBlock = 512;
  for (std::size_t m = 0; m < models_.size(); ++m) {
    const auto [b, e] = p_.materialRange(static_cast<int>(m));
    for (std::size_t k = b; k < e; k += kBlock) f(k, std::min(e, k + kBlock), models_[m].get());
  }
}

template <bool kVelocity, bool kMove>
void MpmSolver::gridToParticlesAndStress(const double* const vL[3], const double* const vn[3],
                                         const double* const vGrad[3]) {
  const GridGeom geom = grid_->geom();
  const int dim = scene_.mesh.dim();
  double cmax = 0;
  kernels::ParticleSums sums;  // the step's last pass (kMove): the ledger's sums, block by block in order
  withStencils([&]<class S, int D>(const kernels::StepStencils<S, D>& src) {
    // 2D / 3D: the grid's velocities packed into gather records first (the nodes the scatter
    // reached), read as vector lanes by kernels::gridToRecords (the same bits as the scalar
    // kernel), cleared after for the next scatter.
    using Slots = kernels::GatherSlots<D, kVelocity, kMove, true, false>;
    using SlotsFromFirst = kernels::GatherSlots<D, kVelocity, kMove, true, kVelocity || kMove>;
    const bool fromFirst = (kVelocity || kMove) && vGrad[0] == vL[0];
    const bool records = D > 1 && (fromFirst ? SlotsFromFirst::kFits : Slots::kFits);
    double* rec = records ? nodeRecords() : nullptr;
    const kernels::NodeRange range = recordRangeValid_ ? recordRange_ : kernels::NodeRange{0, grid_->numNodes()};
    if constexpr (D > 1) {
      if (records && fromFirst)
        kernels::packGather<D, kVelocity, kMove, true, kVelocity || kMove>(rec, range, vL, vn, vGrad);
      else if (records)
        kernels::packGather<D, kVelocity, kMove, true, false>(rec, range, vL, vn, vGrad);
    }
    const auto gather = [&](std::size_t b, std::size_t e) {
      if constexpr (D > 1 && SlotsFromFirst::kFits)
        if (records && fromFirst)
          return kernels::gridToRecords<D, kVelocity, kMove, true, kVelocity || kMove>(src, p_, b, e, geom, rec, dt_,
                                                                                       flip_);
      if constexpr (D > 1 && Slots::kFits)
        if (records && !fromFirst)
          return kernels::gridToRecords<D, kVelocity, kMove, true, false>(src, p_, b, e, geom, rec, dt_, flip_);
      kernels::gridToParticles<D, kVelocity, kMove, true>(src, p_, b, e, geom, vL, vn, vGrad, dt_, flip_);
    };
    forParticleBlocks([&](std::size_t b, std::size_t e, const ConstitutiveModel* model) {
      gather(b, e);
      updateDeformation(b, e);
      if (!model) {
        if (kMove) sums.add(p_, b, e);
        return;
      }
      if (gridStressWork_) workScratch_.assign(p_.work.begin() + b, p_.work.begin() + e);
      model->updateStress(p_, b, e, dt_);
      // mpm.stress_work grid: the work is the grid's (addStressWork), the model's is dropped.
      if (gridStressWork_) std::copy(workScratch_.begin(), workScratch_.end(), p_.work.begin() + b);
      // The step's last particle pass (velocity, mass and volume final): the next time step's
      // signal speed over the block while it is in cache (the max of stableTimeStep's loop).
      if (kMove) {
        cmax = std::max(cmax, model->maxSignalSpeed(p_, b, e, dim));
        sums.add(p_, b, e);
      }
    });
    if (records)
      kernels::clearRecords(rec, range, fromFirst ? SlotsFromFirst::kStride : Slots::kStride);
  });
  if (kMove) {
    endSums_ = sums;
    stencilsValid_ = false;
    signalSpeed_ = cmax;
    signalSpeedValid_ = true;
  }
}

namespace {
// One component of the grid update, v_L = v + dt ((f + f_ext) / m - c v) where m > floor, else v,
// over restrict-qualified arrays so that it vectorizes (lane by lane the same operations). The
// division is taken on every node (by 1 where m <= floor, whose result is not used): a division
// under the condition is not if-converted.
void nodeVelocityUpdate(const double* __restrict__ m, const double* __restrict__ v, const double* __restrict__ f,
                        const double* __restrict__ fe, double* __restrict__ vl, std::int64_t n, double dt, double c,
                        double floor) {
  for (std::int64_t k = 0; k < n; ++k) {
    const bool moves = m[k] > floor;
    const double mk = moves ? m[k] : 1.0;
    const double a = v[k] + dt * ((f[k] + fe[k]) / mk - c * v[k]);
    vl[k] = moves ? a : v[k];
  }
}

// F_n+1 = (I + dt L) F_n and V = V0 det F for 1D / 2D particles over distinct columns (restrict-
// qualified parameters, which GCC honours where it ignores them on locals: the loop vectorizes,
// lane by lane the same operations). In 1D L's yx, xy and yy are zero: those terms are left out.
void planarDeformationUpdate(double* __restrict__ F0c, double* __restrict__ F1c, double* __restrict__ F3c,
                             double* __restrict__ F4c, const double* __restrict__ L0c,
                             const double* __restrict__ L1c, const double* __restrict__ L3c,
                             const double* __restrict__ L4c, const double* __restrict__ vol0,
                             double* __restrict__ vol, std::size_t begin, std::size_t end, double dt, bool two) {
  if (two) {
    for (std::size_t i = begin; i < end; ++i) {
      const double F0 = F0c[i], F1 = F1c[i], F3 = F3c[i], F4 = F4c[i];
      const double L0 = L0c[i], L1 = L1c[i], L3 = L3c[i], L4 = L4c[i];
      const double n0 = F0 + dt * L0 * F0 + dt * L1 * F3, n1 = F1 + dt * L0 * F1 + dt * L1 * F4;
      const double n3 = F3 + dt * L3 * F0 + dt * L4 * F3, n4 = F4 + dt * L3 * F1 + dt * L4 * F4;
      F0c[i] = n0;
      F1c[i] = n1;
      F3c[i] = n3;
      F4c[i] = n4;
      vol[i] = vol0[i] * (n0 * n4 - n1 * n3);
    }
    return;
  }
  for (std::size_t i = begin; i < end; ++i) {
    const double F0 = F0c[i], F1 = F1c[i], F3 = F3c[i], F4 = F4c[i];
    const double L0 = L0c[i];
    const double n0 = F0 + dt * L0 * F0, n1 = F1 + dt * L0 * F1;
    F0c[i] = n0;
    F1c[i] = n1;
    vol[i] = vol0[i] * (n0 * F4 - n1 * F3);
  }
}
}  // namespace

void MpmSolver::updateDeformation(std::size_t begin, std::size_t end) {
  const double dt = dt_;
  if (scene_.mesh.dim() == 3) {
    // The column pointers in locals and no dependence assumed between particles (ivdep: the
    // columns are distinct): the loop vectorizes, lane by lane the same operations.
    double* Fc[9];
    const double* Lc[9];
    for (int k = 0; k < 9; ++k) {
      Fc[k] = p_.F[k].data();
      Lc[k] = p_.L[k].data();
    }
    const double* vol0 = p_.vol0.data();
    double* vol = p_.vol.data();
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
    for (std::size_t i = begin; i < end; ++i) {
      double Fo[9], Fn[9];
      for (int k = 0; k < 9; ++k) Fo[k] = Fc[k][i];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          double s = Fo[3 * a + b];
          for (int c = 0; c < 3; ++c) s += dt * Lc[3 * a + c][i] * Fo[3 * c + b];
          Fn[3 * a + b] = s;
        }
      for (int k = 0; k < 9; ++k) Fc[k][i] = Fn[k];
      vol[i] = vol0[i] * det(Mat3{Fn[0], Fn[1], Fn[2], Fn[3], Fn[4], Fn[5], Fn[6], Fn[7], Fn[8]});
    }
    return;
  }
  // 1D / 2D: L is zero outside the mesh's directions and F keeps the identity there, so those
  // terms add exact zeros and are left out (the 3D formula's figures, bit for bit).
  // F_zz is the exact 1 (not stored): n4 * 1 = n4, the 3D formula's figures.
  planarDeformationUpdate(p_.F[0].data(), p_.F[1].data(), p_.F[3].data(), p_.F[4].data(), p_.L[0].data(),
                          p_.L[1].data(), p_.L[3].data(), p_.L[4].data(), p_.vol0.data(), p_.vol.data(), begin,
                          end, dt, scene_.mesh.dim() == 2);
}

void MpmSolver::computeInternalForces() {
  Grid& g = *grid_;
  if (scheme_->stressFirst) {
    const auto vg = components(g.velocity);
    gridToParticlesAndStress<false, false>(vg.data(), vg.data(), vg.data());
  }
  const auto f = components(g.force);
  const GridGeom geom = g.geom();
  const double grav[3] = {scene_.gravity[0], scene_.gravity[1], scene_.gravity[2]};
  const bool loads = !scene_.loads.empty() || surfaceForces_;
  withStencils([&]<class S, int D>(const kernels::StepStencils<S, D>& src) {
    kernels::internalForces<D>(src, p_, 0, p_.size(), geom, grav, loads, f.data());
  });
  finishInternalForces();
}

void MpmSolver::finishInternalForces() {
  Grid& g = *grid_;
  bcs_.fold(g.force, Parity::Vector);
  g.sumAndFill({&g.force});
}

void MpmSolver::updateGrid() {
  Grid& g = *grid_;
  if (comm_.size() > 1) g.fill({&g.externalForce});
  const std::int64_t n = g.numNodes();
  const int dim = scene_.mesh.dim();
  const double dt = dt_, c = damping_, floor = accelFloor_;
  const double* m = g.mass.data();
  for (int d = 0; d < dim; ++d)
    nodeVelocityUpdate(m, g.velocity.data(d), g.force.data(d), g.externalForce.data(d), g.velocityL.data(d), n, dt,
                       c, floor);
  applyBC(g.velocityL);
  // The work of the coupling forces, as the update realised it (a constrained component moves
  // neither at n nor at L, so it does none), for the energy ledger below; the coupler books the
  // same work to the cells the forces came from (NodeCellOperators::cellCouplingWork, with this
  // floor) and takes it from the fluid there.
  // The ledger: the nodes' kinetic energy change less the coupling and damping work is the
  // internal forces' (with the walls' constraints), to be met by the particles' stress work.
  // (The fields' component pointers and the floor in locals: read through the Field objects in
  // the loop they were reloaded after every store to w.)
  double* w = g.externalWork.data();
  const double* nwk = nodeWeight_.data();
  const auto vn = components(g.velocity);
  const auto vl = components(g.velocityL);
  const auto fe = components(g.externalForce);
  const auto fi = components(g.force);
  double wext = 0, wdamp = 0, wforce = 0;
  for (std::int64_t k = 0; k < n; ++k) {
    double s = 0, sd = 0, sf = 0;
    if (m[k] > floor)
      for (int d = 0; d < dim; ++d) {
        const double vbar = 0.5 * (vn[d][k] + vl[d][k]);
        s += fe[d][k] * vbar;
        sd -= c * m[k] * vn[d][k] * vbar;
        sf += fi[d][k] * vbar;
      }
    w[k] = dt * s;
    const double nw = nwk[k];
    wext += nw * w[k];
    wdamp += nw * dt * sd;
    wforce += nw * dt * sf;
  }
  ledger_.damping += wdamp;
  ledger_.integration += nodeKinetic(g.velocityL) - ledger_.keNodes - wext - wdamp;
  // The forces' work so far, for gridToParticles: a coupled step's exchange increments still move
  // the nodes after this (NodeCellOperators::applyCellMomentumIncrement), and the particles deform
  // with them.
  forceWorkUpdate_ = wforce;
  cells_->bookForceWorkAtStepEnd(dt);
}

double MpmSolver::forceWork() const {
  // sum_i dt f_i . (v_i + v_L,i) / 2 over the nodes above the acceleration floor (the work the
  // grid's internal, body and load forces do at the mean node velocity), the ranks' shared nodes
  // once.
  const Grid& g = *grid_;
  const double* m = g.mass.data();
  const double* nwk = nodeWeight_.data();
  const auto vn = components(g.velocity);
  const auto vl = components(g.velocityL);
  const auto f = components(g.force);
  double w = 0;
  for (std::int64_t k = 0; k < g.numNodes(); ++k) {
    if (!(m[k] > accelFloor_)) continue;
    double s = 0;
    for (int d = 0; d < scene_.mesh.dim(); ++d) {
      const double vbar = 0.5 * (vn[d][k] + vl[d][k]);
      s += f[d][k] * vbar;
    }
    w += nwk[k] * dt_ * s;
  }
  return w;
}

void MpmSolver::addStressWork() {
  // The work of each particle's stress in this step as the grid update realised it: the force the
  // particle put on node i, -V_p sigma_p grad w_ip (the stress and volume computeInternalForces
  // used, unchanged until gridToParticles in every scheme), times the node's mean velocity
  // (v_n + v_L) / 2: dW_p = dt V_p sigma_p : grad(v_mean)_p, v_L as the step ends (a coupled
  // step's exchange increments included: the particles deform with them, and NodeCellOperators
  // books the forces' share of the increments' kinetic energy here rather than to the heat,
  // bookForceWorkAtStepEnd). Summed over the particles it is the
  // kinetic energy the internal forces gave the nodes (the energy update of the grid is exact:
  // m (v_L^2 - v_n^2) / 2 = dt f . v_mean), so the stored (elastic + plastic) energy and the
  // kinetic energy exchange it without a truncation error; the models' own midpoint stress power
  // (sigma_n + sigma_n+1) / 2 : D(v_L) differs from it by O(dt^2) a step (docs/coupling.md
  // "Energy budget"). Nodes below the acceleration floor do not move and take no work. What is left
  // in mpm_stress_integration is the body forces' work.
  Grid& g = *grid_;
  const auto vn = components(g.velocity);
  const auto vl = components(g.velocityL);
  const double* mass = g.mass.data();
  const GridGeom geom = g.geom();
  const double dt = dt_, floor = accelFloor_;
  withStencils([&]<class S, int D>(const kernels::StepStencils<S, D>& src) {
    for (std::size_t i = 0; i < p_.size(); ++i) {
      double L[3][3] = {};
      src.forNodes(i, geom, [&](std::int64_t n, double, double gx, double gy, double gz) {
        if (!(mass[n] > floor)) return;  // a node below the floor does not move: no work done on it
        const double gr[3] = {gx, gy, gz};
        for (int a = 0; a < D; ++a) {
          const double vm = 0.5 * (vn[a][n] + vl[a][n]);
          for (int b = 0; b < D; ++b) L[a][b] += vm * gr[b];
        }
      });
      double power = p_.stress[kXX][i] * L[0][0] + p_.stress[kYY][i] * L[1][1] +
                     p_.stress[kZZ][i] * L[2][2] + p_.stress[kXY][i] * (L[0][1] + L[1][0]);
      // In 1D / 2D the yz and xz terms are exact zeros (and their stresses are not stored).
      if constexpr (D == 3)
        power = power + p_.stress[kYZ][i] * (L[1][2] + L[2][1]) + p_.stress[kXZ][i] * (L[0][2] + L[2][0]);
      p_.work[i] += dt * p_.vol[i] * power;
    }
  });
}

void MpmSolver::gridToParticles() {
  Grid& g = *grid_;
  // The grid count of the stress work at the node velocity the step ends with (after a coupled
  // step's exchange increments, whose kinetic deficit left the forces' share of them to the
  // stress work, NodeCellOperators::bookForceWorkAtStepEnd); the ledger follows the forces' work
  // to the same velocity in either count.
  if (gridStressWork_) addStressWork();
  if (cells_->forceWorkShifted()) ledger_.integration += forceWork() - forceWorkUpdate_;
  // The grid's kinetic energy now (after any coupling increments) against the particles' after.
  const double keFinal = nodeKinetic(g.velocityL);
  const auto vL = components(g.velocityL);
  const auto vn = components(g.velocity);
  const GridGeom geom = g.geom();
  const int dim = scene_.mesh.dim();
  const std::size_t np = p_.size();
  switch (scheme_->kind) {
    case UpdateScheme::USF:
      withStencils([&]<class S, int D>(const kernels::StepStencils<S, D>& src) {
        kernels::gridToParticles<D, true, true, false>(src, p_, 0, np, geom, vL.data(), vn.data(), vL.data(), dt_, flip_);
      });
      stencilsValid_ = false;
      break;
    case UpdateScheme::USL:
      gridToParticlesAndStress<true, true>(vL.data(), vn.data(), vL.data());
      break;
    case UpdateScheme::MUSL: {
      g.ensureRemap();
      g.remap.fill(0.0);
      const auto mom = components(g.remap);
      withStencils([&]<class S, int D>(const kernels::StepStencils<S, D>& src) {
        kernels::gridToParticles<D, true, false, false>(src, p_, 0, np, geom, vL.data(), vn.data(), vL.data(), dt_, flip_);
        kernels::momentumToGrid<D>(src, p_, 0, np, geom, mom.data());
      });
      bcs_.fold(g.remap, Parity::Vector);
      g.sumAndFill({&g.remap});
      const double* m = g.mass.data();
      for (int d = 0; d < dim; ++d)
        for (std::int64_t k = 0; k < g.numNodes(); ++k) mom[d][k] = m[k] > massFloor_ ? mom[d][k] / m[k] : 0.0;
      applyBC(g.remap);
      const double* vr[3] = {mom[0], mom[1], mom[2]};
      gridToParticlesAndStress<false, true>(vL.data(), vn.data(), vr);
      break;
    }
  }
  // USL / MUSL end with the block pass, which took the sums (forParticleBlocks visits the
  // particles in order); USF sums here.
  const bool summed = scheme_->kind != UpdateScheme::USF;
  const double keParticles = summed ? endSums_.kinetic : particleKinetic();
  ledger_.transfer += (ledger_.keNodes - ledger_.keParticles) + (keParticles - keFinal);
  ledger_.integration += (summed ? endSums_.work : particleWork()) - ledger_.work;
}

double* MpmSolver::nodeRecords() {
  if (!records_) {
    const std::size_t bytes = sizeof(double) * kernels::kRecordDoubles * static_cast<std::size_t>(grid_->numNodes());
    recordMemory_.reset(std::calloc(bytes + 64, 1));
    if (!recordMemory_) throw std::bad_alloc();
    const auto at = reinterpret_cast<std::uintptr_t>(recordMemory_.get());
    records_ = reinterpret_cast<double*>((at + 63) & ~static_cast<std::uintptr_t>(63));
  }
  return records_;
}

void MpmSolver::endStep() {
  stencilsValid_ = false;
  recordRangeValid_ = false;
  time_ += dt_;
  ++step_;
  migrateAndSort(scene_.mpm.sort_particles && step_ % sortInterval_ == 0);
}

void MpmSolver::migrateAndSort(bool forceSort) {
  const core::Mesh& mesh = scene_.mesh;
  const int dim = mesh.dim();
  const std::size_t n = p_.size();
  // 1. Particles outside the mesh. One that left through an `outflow` face leaves the simulation
  //    (mpm.outflow_particles: remove): counted, its mass, momentum and energy booked as outflow
  //    and reported; one outside any other face (or through an outflow face with "error", or not
  //    finite) stops the run on every rank.
  const int nmat = static_cast<int>(scene_.materials.size());
  const bool removeAtOutflow = scene_.mpm.outflow_particles == "remove";
  long long outside = -1;
  int outsideFace = -1;
  double where[3] = {0, 0, 0};
  std::vector<char> keep;                  // only filled when a particle leaves
  std::vector<double> removed;             // per (face, material): count, mass; only when one leaves
  // The grid coordinate as the stencils compute it (GridGeom: times 1 / dx), not a division per
  // particle and direction (the division was 4 % of a 2D linear step).
  const GridGeom geom = grid_->geom();
  // First whether any particle is outside at all, in a loop without early exits that vectorizes
  // (q >= 0 and q < cells holds exactly for the finite coordinates inside: NaN fails both); the
  // search for the face below runs only when one is.
  std::size_t outsideCount = 0;
  for (int d = 0; d < dim; ++d) {
    const double* xd = p_.x[d].data();
    const double o = geom.origin[d], inv = geom.invDx[d], cells = mesh.cells()[d];
    for (std::size_t i = 0; i < n; ++i) {
      const double q = (xd[i] - o) * inv;
      outsideCount += !(q >= 0.0 && q < cells);
    }
  }
  for (std::size_t i = 0; i < n && outsideCount > 0; ++i) {
    int face = -1;  // -1 inside; 0..5 the face crossed; 6 not finite
    for (int d = 0; d < dim && face < 0; ++d) {
      const double q = (p_.x[d][i] - geom.origin[d]) * geom.invDx[d];
      if (!std::isfinite(q)) face = 6;
      else if (q < 0.0) face = 2 * d;
      else if (!(q < mesh.cells()[d])) face = 2 * d + 1;
    }
    if (face < 0) continue;
    if (face < 6 && removeAtOutflow && scene_.boundary[face].type == core::BoundaryType::Outflow) {
      if (keep.empty()) {
        keep.assign(n, 1);
        removed.assign(2 * 6 * nmat, 0.0);
      }
      keep[i] = 0;
      const int m = p_.material[i];
      const double mass = p_.mass[i];
      ParticleOutflow& o = ledger_.outflow;
      o.count += 1;
      o.mass += mass;
      double v2 = 0;
      for (int d = 0; d < 3; ++d) {
        o.momentum[d] += mass * p_.v[d][i];
        v2 += p_.v[d][i] * p_.v[d][i];
      }
      o.kinetic += 0.5 * mass * v2;
      o.strain += p_.work[i];
      if (models_[m]) o.heat += mass * scene_.materials[m].specific_heat * p_.temperature[i];
      removed[2 * (face * nmat + m)] += 1;
      removed[2 * (face * nmat + m) + 1] += mass;
      continue;
    }
    if (outside < 0) {
      outside = p_.id[i];
      outsideFace = face;
      for (int e = 0; e < 3; ++e) where[e] = p_.x[e][i];
    }
  }
  std::vector<double> flags{outside >= 0 ? 1.0 : 0.0, keep.empty() ? 0.0 : 1.0};
  comm_.sumInPlace(flags);
  if (flags[0] > 0) {
    std::ostringstream os;
    if (outside >= 0) {
      os << "particle " << outside << " at (" << where[0] << ", " << where[1] << ", " << where[2] << ") ";
      if (outsideFace < 6)
        os << "left the mesh (" << mesh.describe() << ") through the " << core::boundaryFaceName(outsideFace) << " face ("
           << core::toString(scene_.boundary[outsideFace].type) << ")";
      else
        os << "has a position that is not finite";
    } else {
      os << "a particle on another rank left the mesh (" << mesh.describe() << ")";
    }
    os << " at t = " << time_ << ", step " << step_
       << ": it is outside the mesh. Enlarge the mesh, or make that face a wall (noslip_wall / symmetry)";
    if (!removeAtOutflow) os << ", or let particles leave through outflow faces (mpm.outflow_particles: remove)";
    else os << ", or make it an outflow face (particles leaving through it are removed, mpm.outflow_particles)";
    throw std::runtime_error(os.str());
  }
  removedLastStep_ = 0;
  removalReport_.clear();
  if (flags[1] > 0) {
    if (removed.empty()) removed.assign(2 * 6 * nmat, 0.0);
    comm_.sumInPlace(removed);
    std::ostringstream os;
    os << "mpm: at t = " << time_ << " s (step " << step_ << ")";
    const char* sep = " ";
    for (int f = 0; f < 6; ++f)
      for (int m = 0; m < nmat; ++m) {
        const double cnt = removed[2 * (f * nmat + m)];
        if (cnt == 0) continue;
        removedLastStep_ += static_cast<long long>(cnt);
        os << sep << static_cast<long long>(cnt) << " particle(s) of '" << scene_.materials[m].name << "' (mass "
           << removed[2 * (f * nmat + m) + 1] << " kg) left through the outflow face "
           << core::boundaryFaceName(f);
        sep = "; ";
      }
    os << " and are removed (mpm.outflow_particles: remove)";
    if (comm_.root()) removalReport_ = os.str();
    if (!keep.empty()) {
      p_.compact(keep);
      p_.updateMaterialRanges(nmat);
    }
  }
  const std::size_t nk = p_.size();
  sortKey_.resize(nk);
  std::vector<int> dest;  // only filled on several ranks
  const core::Box all = mesh.cellBox();
  const int me = comm_.rank();
  bool moving = false;
  if (comm_.size() > 1) dest.assign(nk, me);
  const bool needKeys = comm_.size() > 1 || forceSort || !p_.groupedByMaterial();
  for (std::size_t i = 0; needKeys && i < nk; ++i) {
    int c[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d) c[d] = std::clamp(cellCoordinate(mesh, d, p_.x[d][i]), 0, mesh.cells()[d] - 1);
    sortKey_[i] = static_cast<std::uint64_t>(all.index(c[0], c[1], c[2]));
    if (comm_.size() > 1) {
      dest[i] = decomp_.ownerOfCell(c[0], c[1], c[2]);
      if (dest[i] != me) moving = true;
    }
  }
  // 2. Migration to the owning ranks.
  bool received = false;
  if (comm_.size() > 1 && comm_.max(moving ? 1 : 0) > 0) {
    const int np = comm_.size();
    const std::size_t ps = ParticleSet::packedSize();
    std::vector<std::vector<double>> out(np);
    std::vector<char> keepHere(nk, 1);
    for (std::size_t i = 0; i < nk; ++i)
      if (dest[i] != me) {
        p_.pack(i, out[dest[i]]);
        keepHere[i] = 0;
      }
    std::vector<int> scount(np), rcount(np), sdisp(np), rdisp(np);
    std::vector<double> sbuf;
    for (int r = 0; r < np; ++r) {
      sdisp[r] = static_cast<int>(sbuf.size());
      scount[r] = static_cast<int>(out[r].size());
      sbuf.insert(sbuf.end(), out[r].begin(), out[r].end());
    }
    MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm_.raw());
    int total = 0;
    for (int r = 0; r < np; ++r) {
      rdisp[r] = total;
      total += rcount[r];
    }
    std::vector<double> rbuf(static_cast<std::size_t>(total));
    MPI_Alltoallv(sbuf.data(), scount.data(), sdisp.data(), MPI_DOUBLE, rbuf.data(), rcount.data(),
                  rdisp.data(), MPI_DOUBLE, comm_.raw());
    std::vector<std::uint64_t> keys;
    for (std::size_t i = 0; i < nk; ++i)
      if (keepHere[i]) keys.push_back(sortKey_[i]);
    p_.compact(keepHere);
    for (std::size_t k = 0; k + ps <= rbuf.size(); k += ps) {
      const std::size_t i = p_.size();
      p_.unpack(rbuf.data() + k);
      const auto c = cellOfParticle(mesh, p_, i, all);
      keys.push_back(static_cast<std::uint64_t>(all.index(c[0], c[1], c[2])));
      received = true;
    }
    sortKey_ = std::move(keys);
  }
  if (needKeys && (forceSort || received || !p_.groupedByMaterial())) p_.sortBy(sortKey_, perm_, scratch_);
  p_.updateMaterialRanges(static_cast<int>(scene_.materials.size()));
}

Energies MpmSolver::energies() const {
  Energies e;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    e.kinetic += 0.5 * p_.mass[i] *
                 (p_.v[0][i] * p_.v[0][i] + p_.v[1][i] * p_.v[1][i] + p_.v[2][i] * p_.v[2][i]);
    e.strain += p_.work[i];
  }
  for (std::size_t m = 0; m < models_.size(); ++m) {
    if (!models_[m]) continue;
    const double cv = scene_.materials[m].specific_heat;
    const auto [b, en] = p_.materialRange(static_cast<int>(m));
    for (std::size_t i = b; i < en; ++i) e.heat += p_.mass[i] * cv * p_.temperature[i];
  }
  std::vector<double> s{e.kinetic, e.strain, e.heat, ledger_.transfer, ledger_.integration, ledger_.damping,
                        ledger_.outflow.energy()};
  comm_.sumInPlace(s);
  e.outflow = s[6];
  e.kinetic = s[0];
  e.strain = s[1];
  e.heat = s[2];
  e.transfer = s[3];
  e.integration = s[4];
  e.damping = s[5];
  return e;
}

std::string outflowSummary(const ParticleOutflow& o) {
  if (!(o.count > 0)) return "";
  std::ostringstream os;
  os << "  outflow: " << static_cast<long long>(o.count) << " particles left through outflow faces and were removed "
     << "(mpm.outflow_particles: remove): mass " << o.mass << " kg, momentum (" << o.momentum[0] << ", "
     << o.momentum[1] << ", " << o.momentum[2] << ") kg m/s, energy " << o.energy() << " J (kinetic " << o.kinetic
     << ", stress work " << o.strain << ", heat " << o.heat << ")\n";
  return os.str();
}

ParticleOutflow MpmSolver::outflow() const {
  std::vector<double> v = ledger_.outflow.pack();
  comm_.sumInPlace(v);
  return ParticleOutflow::unpack(v);
}

core::RealVect MpmSolver::centerOfMassVelocity() const {
  std::vector<double> s(4, 0.0);
  for (std::size_t i = 0; i < p_.size(); ++i) {
    s[0] += p_.mass[i];
    for (int d = 0; d < 3; ++d) s[d + 1] += p_.mass[i] * p_.v[d][i];
  }
  comm_.sumInPlace(s);
  return {s[1] / s[0], s[2] / s[0], s[3] / s[0]};
}

}  // namespace mpmice::mpm
