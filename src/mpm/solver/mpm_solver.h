#pragma once
/// @brief MpmSolver: explicit Material Point Method on the shared background mesh, one rank's
/// share of a domain decomposition, as named phases the coupler calls one by one.
///
/// One step (the MPM side of the MPM-ICE schedule in docs/architecture.md):
///   beginStep(dt)
///   (1) particlesToGrid()          mass, momentum -> v_n (+ BCs);  cellState(m) for ICE
///   (2) computeInternalForces()    (USF: stress update first) internal + body forces + loads;
///       externalNodeForce()        hook: the coupler adds e.g. ICE's pressure force per node
///   (3) updateGrid()               v_L = v_n + dt f / m (damping, BCs); cellLagrangianMomentum(m)
///   (4) applyCellVelocityIncrement(m, dv)   hook: ICE's exchange increments back to the nodes
///   (5) gridToParticles()          FLIP/PIC velocity, positions, (USL/MUSL) stress update
///   endStep()                      migration between ranks, sorting, time advance
/// An uncoupled step (advance()) is these phases in order with no external contributions.
/// Collective calls (all ranks): constructor, stableTimeStep, every phase, energies.
#include <array>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/health/health.h"
#include "core/io/checkpoint.h"
#include "mpm/cell/node_cell_operators.h"
#include "mpm/grid/boundary_conditions.h"
#include "mpm/grid/grid.h"
#include "mpm/material/constitutive_model.h"
#include "mpm/mpm_constants.h"
#include "mpm/particles/particle_generator.h"
#include "mpm/particles/particle_set.h"
#include "core/scene/scene.h"
#include "mpm/scheme/update_scheme.h"
#include "mpm/shape/shape_function.h"
#include "mpm/solver/kernels.h"

namespace mpmice::mpm {

struct Energies {
  double kinetic = 0;  // sum 1/2 m v^2
  double strain = 0;   // stress work (stored elastic + dissipated plastic)
  double heat = 0;     // sum m cv T of the particles (thermal energy; the coupling's heat arrives here)
  // What the method itself creates (> 0) or removes (< 0), summed over the steps so far [J]: the
  // particle-grid transfers (particle kinetic energy change beyond the grid's: P2G loses, FLIP's
  // G2P may give back), the stress integration (the kinetic energy the internal forces give the
  // nodes plus the stress work of the particles: zero for an exact time integration; wall
  // constraints included) and mpm.damping's work.
  double transfer = 0, integration = 0, damping = 0;
  // The energy (kinetic + strain + heat) the particles removed through outflow faces carried out
  // of the mesh (mpm.outflow_particles: remove), summed over the steps so far [J].
  double outflow = 0;
  double total() const { return kinetic + strain; }
  /// kinetic + strain + heat, plus what left through outflow faces, less what the method created:
  /// constant in a closed system.
  double balance() const { return kinetic + strain + heat + outflow - transfer - integration - damping; }
};

/// What the particles removed through outflow faces (mpm.outflow_particles: remove) carried out of
/// the mesh: count, mass, momentum and energy (kinetic, stress work, heat m cv T), summed over the
/// steps so far.
struct ParticleOutflow {
  double count = 0, mass = 0;
  std::array<double, 3> momentum{0, 0, 0};
  double kinetic = 0, strain = 0, heat = 0;
  [[nodiscard]] double energy() const { return kinetic + strain + heat; }
  [[nodiscard]] std::vector<double> pack() const {
    return {count, mass, momentum[0], momentum[1], momentum[2], kinetic, strain, heat};
  }
  static ParticleOutflow unpack(const std::vector<double>& v) {
    ParticleOutflow o;
    if (v.size() != 8) return o;
    o.count = v[0];
    o.mass = v[1];
    o.momentum = {v[2], v[3], v[4]};
    o.kinetic = v[5];
    o.strain = v[6];
    o.heat = v[7];
    return o;
  }
};
/// The closing line of a run whose particles left through outflow faces ("" when none did).
std::string outflowSummary(const ParticleOutflow& o);

class MpmSolver {
 public:
  /// Builds the decomposition, grid, models and particles. Throws std::invalid_argument with a
  /// message naming the scene key for bad input. `contains` defaults to ShapeSpec::contains.
  MpmSolver(const core::Scene& scene, const core::Comm& comm, ContainsFn contains = {});
  ~MpmSolver();

  // ---- state -------------------------------------------------------------------------------
  [[nodiscard]] const core::Scene& scene() const { return scene_; }
  [[nodiscard]] const core::Decomposition& decomposition() const { return decomp_; }
  [[nodiscard]] const core::Comm& comm() const { return comm_; }
  /// Writable particles: the step's cached stencils are recomputed before their next use.
  [[nodiscard]] ParticleSet& particles() {
    stencilsValid_ = false;
    signalSpeedValid_ = false;
    return p_;
  }
  [[nodiscard]] const ParticleSet& particles() const { return p_; }
  [[nodiscard]] Grid& grid() { return *grid_; }
  [[nodiscard]] const Grid& grid() const { return *grid_; }
  [[nodiscard]] long long globalParticleCount() const;
  /// The solid geometry objects whose particles fill a volume off their shape's by more than
  /// kGeometryVolumeWarning (geometryVolumeWarnings; measured at set-up, every rank's cells): the
  /// runners log them as warnings at the start.
  [[nodiscard]] const std::vector<std::string>& geometryWarnings() const { return geometryWarnings_; }
  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] long stepCount() const { return step_; }
  [[nodiscard]] ShapeKind shapeKind() const { return shape_; }
  [[nodiscard]] const SchemeTraits& scheme() const { return *scheme_; }
  [[nodiscard]] const ConstitutiveModel& model(int material) const { return *models_[material]; }
  /// The MPM-ICE node-cell transfer operators on this solver's grid and particles; beginStep()
  /// starts a new step generation of their per-step data.
  [[nodiscard]] NodeCellOperators& cells() { return *cells_; }
  [[nodiscard]] const NodeCellOperators& cells() const { return *cells_; }

  /// Small-mass cut-off of the grid update with linear hats: a node whose mass is below this
  /// fraction of the smallest particle mass keeps v_L = v_n (no acceleration). Such nodes appear
  /// when a particle just enters a cell (weight ~ 0) while the hat's gradient stays 1/dx: f/m there
  /// is unbounded and, through the velocity gradient, blew up linear + USL at free surfaces
  /// (docs/mpm.md). GIMP and B-splines need none (grad w ~ sqrt(w) as w -> 0: bounded).
  static constexpr double kSmallMassFraction = mpm::kSmallMassFraction;

  /// The CFL time step: cfl * dx_min / max(c + |v|) over all particles, capped by dt_max.
  [[nodiscard]] double stableTimeStep() const;
  /// What sets the stable step now: the particle (id, material, position, wave speed, |v|) of the
  /// CFL bound, or time.dt_max / time.dt_initial; for the time-step collapse error. Collective.
  [[nodiscard]] std::string stableTimeStepLimit() const;
  /// One uncoupled step with dt = min(stableTimeStep, time left to `until`). Returns dt.
  double advance(double until = 1e300);
  /// Node mass and velocity v_n from the particles as they are now (what particlesToGrid() gives),
  /// without stepping: e.g. for output of the initial state. Collective.
  void projectToGrid();

  // ---- phases (see the brief) ----------------------------------------------------------------
  void beginStep(double dt);
  /// The step begun by beginStep (0 before the first).
  [[nodiscard]] double stepSize() const { return dt_; }
  void particlesToGrid();
  /// Cell-centred state of solid material m: cells().cellState(m).
  const SolidCellState& cellState(int material) { return cells_->cellState(material); }
  void computeInternalForces();
  /// Node force the coupler may add to before updateGrid() (zeroed by beginStep).
  [[nodiscard]] core::Field& externalNodeForce() { return grid_->externalForce; }
  void updateGrid();
  // The MPM-ICE node-cell operators between updateGrid() and gridToParticles() (and the
  // mean-stress and cell forces between computeInternalForces() and updateGrid()) are
  // cells().X (mpm/cell/node_cell_operators.h); these forward to them.
  void cellLagrangianMomentum(int material, core::Field& out) const { cells_->cellLagrangianMomentum(material, out); }
  void applyCellVelocityIncrement(int material, const core::Field& dv) { cells_->applyCellVelocityIncrement(material, dv); }
  void addCellForce(int material, const core::Field& force) { cells_->addCellForce(material, force); }
  void addCellPressureStress(const core::Field& cellPressure, double pRef) {
    cells_->addCellPressureStress(cellPressure, pRef);
  }
  void addCellEnergy(int material, const core::Field& energy) { cells_->addCellEnergy(material, energy); }
  void gridToParticles();
  void endStep();

  // ---- surface coupling (an interface-BC fluid such as OpenFOAM) ------------------------------
  /// From now on the particle column fsurf (force per particle, held from step to step until the
  /// coupler changes it) enters the internal force pass like a load.
  void enableSurfaceForces() {
    surfaceForces_ = true;
    if (!p_.layout().surface) {  // fsurf and surface are stored from now on (zeros)
      ParticleLayout layout = p_.layout();
      layout.surface = true;
      p_.setLayout(layout);
    }
  }
  /// Makes mpm.stress_work "auto" mean "grid" (the volume coupling's solid side calls it before
  /// the first step) where the particles deform with the nodes' velocity the grid count takes,
  /// v_L (USL, USF's forces). MUSL deforms them with the velocity remapped from the particles, so
  /// the grid count there would also charge the stored work with what the remap filters out of
  /// the nodes (the particle-grid transfer's loss): "auto" stays "material" (docs/mpm.md "Stress
  /// work").
  void useGridStressWorkByDefault() {
    if (scene_.mpm.stress_work == "auto" && scheme_->kind != UpdateScheme::MUSL) gridStressWork_ = true;
  }
  /// Whether the particles' stress work is the grid's count (mpm.stress_work grid, or auto in a
  /// volume-coupled run with USL / USF) rather than the models' stress power.
  [[nodiscard]] bool gridStressWork() const { return gridStressWork_; }

  // ---- checkpoints (implicit coupling repeats a step from the state before it) ----------------
  /// This rank's sums of Energies::transfer, integration, damping, and the step's partial sums.
  struct Ledger {
    double transfer = 0, integration = 0, damping = 0;
    double keParticles = 0, work = 0, keNodes = 0;  // at the start of the step, after P2G
    ParticleOutflow outflow;                        // this rank's removed particles (migrateAndSort)
  };
  struct Checkpoint {
    ParticleSet particles;
    double time = 0;
    long step = 0;
    Ledger ledger;
  };
  /// The state a step starts from (particles, clock, energy ledger); restore() returns to it. Local.
  [[nodiscard]] Checkpoint checkpoint() const { return {p_, time_, step_, ledger_}; }
  void restore(const Checkpoint& c) {
    stencilsValid_ = false;
    signalSpeedValid_ = false;
    p_ = c.particles;
    time_ = c.time;
    step_ = c.step;
    ledger_ = c.ledger;
  }

  // ---- restart (mpm_solver_checkpoint.cpp) ------------------------------------------------------
  /// Puts this rank's complete state under `prefix` (every particle column, history variables
  /// included; the clock; the time-step collapse reference); loadCheckpoint() returns a solver
  /// built from the same scene on the same ranks to it. Local.
  void saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const;
  void loadCheckpoint(const core::CheckpointData& data, const std::string& prefix);

  // ---- diagnostics ---------------------------------------------------------------------------
  [[nodiscard]] Energies energies() const;
  /// What the particles removed through outflow faces carried out, summed over ranks (collective).
  [[nodiscard]] ParticleOutflow outflow() const;
  /// Particles removed through outflow faces at the end of the last step (global, every rank),
  /// and, on rank 0, a line saying which (face, material, count, mass, time); empty otherwise.
  [[nodiscard]] long long removedLastStep() const { return removedLastStep_; }
  [[nodiscard]] const std::string& removalReport() const { return removalReport_; }
  /// Centre-of-mass velocity (global).
  [[nodiscard]] core::RealVect centerOfMassVelocity() const;

 private:
  /// stableTimeStep; `limiting`: this rank's particle that sets the CFL bound (size(): none here).
  double stableTimeStep(std::size_t* limiting) const;
  void computeLoads();
  void assignArcAreas(int load);
  /// The particle pass of particlesToGrid() (filling the stencil cache), with the internal forces
  /// of computeInternalForces() in the same pass when `forces`; then the grid work of each.
  void scatterToGrid(bool forces);
  void finishParticlesToGrid();
  void finishInternalForces();
  /// F = (I + dt L) F and V = V0 det F of particles [begin, end).
  void updateDeformation(std::size_t begin, std::size_t end);
  /// Calls f(begin, end, model) over this rank's particles in blocks of kBlock within each
  /// material's range (model null for a material without one), so that a pass reading the grid
  /// and the particle updates after it run on a block still in cache.
  template <class F>
  void forParticleBlocks(F&& f) const;
  /// The grid-to-particle pass that gives L (kVelocity, kMove as in kernels::gridToParticles from
  /// velocity field vGrad), then F, V and the stress, block by block.
  template <bool kVelocity, bool kMove>
  void gridToParticlesAndStress(const double* const vL[3], const double* const vn[3], const double* const vGrad[3]);
  /// Calls f.template operator()<Shape, Dim>(cache) with this step's stencil cache, filled first
  /// if particlesToGrid() did not fill it since the particles last moved.
  template <class F>
  void withStencils(F&& f);
  void migrateAndSort(bool forceSort);
  void applyBC(core::Field& v) const { bcs_.apply(v); }
  /// Adds each particle's stress work of this step, as the grid update and the coupling's
  /// increments realised it, to its work (start of gridToParticles).
  void addStressWork();
  /// sum_i dt f_i . (v_i + v_L,i) / 2 over the nodes that move, at the velocity v_L now (the grid's
  /// forces' work; updateGrid sums the same at its own v_L in its node loop).
  [[nodiscard]] double forceWork() const;
  /// This rank's share of sum_nodes 1/2 m |v|^2 (each mesh node counted once over all ranks).
  [[nodiscard]] double nodeKinetic(const core::Field& v) const;
  /// This rank's particles: kinetic energy and stress work.
  [[nodiscard]] double particleKinetic() const;
  [[nodiscard]] double particleWork() const;

  core::Scene scene_;
  core::Comm comm_;
  core::Decomposition decomp_;
  std::unique_ptr<Grid> grid_;
  BoundaryConditions bcs_;
  ParticleSet p_;
  std::vector<std::unique_ptr<ConstitutiveModel>> models_;  // per scene material (null: fluid)
  ShapeKind shape_;
  const SchemeTraits* scheme_;
  double flip_, damping_;
  double dt_ = 0, time_ = 0;
  long step_ = 0;
  core::StepCollapse collapse_;  // time.dt_collapse_fraction (advance())
  double massFloor_ = 0;
  bool surfaceForces_ = false;
  double accelFloor_ = 0;  // linear: kSmallMassFraction x smallest particle mass; else massFloor_
  int sortInterval_ = kSortInterval;
  std::unique_ptr<NodeCellOperators> cells_;  // the MPM-ICE node-cell operators
  // The step's stencils (kernels::StencilCache), filled by particlesToGrid(), used by the force
  // and grid-to-particle passes; stale once the particles move or are written from outside.
  std::vector<std::int64_t> stencilOffset_;
  std::vector<double> stencilRecord_;
  bool stencilsValid_ = false;
  // The largest CFL signal speed of this rank's particles, taken in the step's last particle pass
  // (USL / MUSL) and used by the next stableTimeStep(); stale once the particles are written from
  // outside or a step begins.
  double signalSpeed_ = 0;
  bool signalSpeedValid_ = false;
  // The ledger's particle sums after the step's last particle pass (USL / MUSL), taken in it.
  kernels::ParticleSums endSums_;
  // Node records of the 2D / 3D scatter and gather (kernels.h, "Node records"): 8 doubles per
  // node, 64-byte aligned, all zero between passes. Allocated zeroed on first use (calloc: the
  // pages stay untouched until a particle's stencil reaches them). recordRange_: the nodes the
  // step's scatter reached (valid until the particles move), which the gather packs.
  struct FreeDeleter {
    void operator()(void* q) const { std::free(q); }
  };
  std::unique_ptr<void, FreeDeleter> recordMemory_;
  double* records_ = nullptr;
  kernels::NodeRange recordRange_;
  bool recordRangeValid_ = false;
  double* nodeRecords();
  Ledger ledger_;
  long long removedLastStep_ = 0;
  std::string removalReport_;
  bool gridStressWork_ = false;     // mpm.stress_work: grid (addStressWork) or material (the models)
  std::vector<double> workScratch_;  // the models' work, discarded with gridStressWork_
  double forceWorkUpdate_ = 0;       // the forces' work at the grid update (before the coupling's increments)
  std::vector<double> nodeWeight_;  // this rank's share of each node (its owned cells' node shares)
  std::vector<std::string> geometryWarnings_;  // geometryWarnings()
  // Reused scratch (no allocations in the step).
  std::vector<std::uint64_t> sortKey_;
  std::vector<std::uint32_t> perm_;
  std::vector<double> scratch_;
};

}  // namespace mpmice::mpm
