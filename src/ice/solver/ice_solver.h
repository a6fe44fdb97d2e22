#pragma once
/// @brief IceSolver: multi-material compressible ICE on the shared mesh, one phase per method step.
///
/// An uncoupled step() runs the phases of mpmice-method.md in order; the coupler calls them one by
/// one in the monolithic-style schedule (ARCHITECTURE.md "The exchange, step by step"):
///   setExternalMaterialState(...)  (each external material, before the pressure; step 1)
///   computeEquilibriumPressure()   (step 2)        beginStep(dt)
///   computeFaceVelocities()        (step 3, with the pointwise exchange at faces)
///   computePressureIncrement()     (step 5, explicit or semi-implicit)
///   computeFacePressure()          (step 6)  -> pressure(), pressureForce(m) for the solid
///   computeSourcesAndLagrangian()  (steps 8, 9 and 11: sources, Lagrangian values, volumes)
///   setExternalLagrangianMomentum/Energy(...)  (the solid's values after its internal forces)
///   exchange()                     (step 10) -> exchangeMomentum(m), exchangeEnergy(m)
///   advectFluids()                 (step 12; ends the step: t += dt)
/// Per-cell arrays of the coupling calls cover this rank's owned cells, x fastest; vectors are
/// component-major (3 blocks). External materials are never advected here.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <cstdint>
#include <vector>

#include "ice/boundary/ice_boundary.h"
#include "core/health/health.h"
#include "core/io/checkpoint.h"
#include "core/parallel/comm.h"
#include "core/parallel/decomposition.h"
#include "core/parallel/ghost_exchange.h"
#include "ice/pressure/equilibrium_pressure.h"
#include "core/scene/scene.h"
#include "ice/solver/energy_audit.h"
#include "ice/solver/scratch.h"
#include "ice/state/ice_state.h"
#include "ice/state/owned_cells.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

struct Totals {
  double mass = 0, energy = 0;          // energy = internal + kinetic (fluids)
  double kinetic = 0;                   // of the fluids
  std::array<double, 3> momentum{0, 0, 0};
};

class IceSolver {
 public:
  /// Builds the state from the scene's fluid regions (solids become external materials).
  /// Throws std::invalid_argument with the scene key for bad input. coupledStart: keep the
  /// scene's pressure per cell for fitFluidsToExternalVolume (a coupled run's start; ice_solver
  /// alone has none and keeps no such field).
  IceSolver(const core::Scene& scene, const core::Comm& comm, bool coupledStart = true);
  ~IceSolver();

  // ---- uncoupled driving
  /// One step of size min(stable, dt_max, t_end - t).
  void step();
  /// The stable step from the last equilibrium state: the convective-acoustic CFL bound (docs/ice.md),
  /// and with viscous fluids also the explicit viscous bound 2 / (nu lambda), lambda = 4 sum_d dx_d^-2 +
  /// (4/3) max_d dx_d^-2 (the Newtonian stress's largest rate over nu), nu = mu / rho, and with
  /// conducting fluids 1 / (2 alpha sum_d dx_d^-2), alpha = k / (rho cv).
  /// It reads the equilibrium's compressibilities, whose array the Lagrangian phase fills with the
  /// Lagrangian specific volume when no external material is present (MaterialState::lagSpvol):
  /// ask between computeEquilibriumPressure and the Lagrangian phase, as step() and the coupler do.
  [[nodiscard]] double stableTimeStep() const;
  /// What sets the stable step now: the bound (CFL, viscous, time.dt_max), the cell, its centre
  /// and the materials' state there, for the time-step collapse error. Collective.
  [[nodiscard]] std::string stableTimeStepLimit() const;
  [[nodiscard]] double time() const { return t_; }
  [[nodiscard]] long steps() const { return nsteps_; }
  [[nodiscard]] double dt() const { return dt_; }

  // ---- phases (see the brief above)
  void setExternalMaterialState(int material, std::span<const double> mass, std::span<const double> velocity,
                                std::span<const double> temperature, std::span<const double> specificVolume);
  /// The face transport of external material m (coupling.solid_transport mpm; solid_faces.h): its
  /// face density [kg/m^3] and face mass flux [kg/(m^2 s)] at the low face of each owned cell per
  /// direction, 3 x owned cells each, component-major. Before computeEquilibriumPressure; from
  /// the first call on, ICE's volume balance moves the solids' volume with it. Collective.
  void setExternalFaceTransport(int material, std::span<const double> density, std::span<const double> flux);
  /// Once, at the start of a coupled run, after every external material's first state: scales
  /// each fluid's mass in every cell so that the fluids, at their initial micro state, fill
  /// exactly the volume the solids leave free (V - sum m_e v_e; a trace where the solids fill
  /// the cell). The solids' node-to-cell mass smears their surface over neighbouring cells; this
  /// starts the fluids in pressure equilibrium with that smeared surface. Needs coupledStart
  /// (std::logic_error without).
  void fitFluidsToExternalVolume();
  void computeEquilibriumPressure();
  void beginStep(double dt);
  void computeFaceVelocities();
  void computePressureIncrement();
  void computeFacePressure();
  /// Pressure force -V theta_m grad(p_f) on material m per owned cell [N], 3 components.
  [[nodiscard]] core::Field pressureForce(int material) const;
  void computeSourcesAndLagrangian();
  /// Solid's Lagrangian momentum [kg m/s] (3 x owned cells) and internal energy [J] per cell.
  void setExternalLagrangianMomentum(int material, std::span<const double> momentum);
  void setExternalLagrangianEnergy(int material, std::span<const double> energy);
  /// The work [J] per owned cell that the pressure forces of this step do on external material m,
  /// as its own solver realises it (MPM: the kinetic energy its nodes gain from them). Before
  /// computeSourcesAndLagrangian: the fluids' energy change there is the flux form of the cell's
  /// p dV work less this work (energy conservation with external materials). Zero unless set.
  void setExternalCouplingWork(int material, std::span<const double> work);
  /// External material m's own volume change over the step [m^3] per owned cell, as its solver
  /// realises it (MPM: its particles' volumes times the trace of the velocity gradient the
  /// coupling work uses). Before computeSourcesAndLagrangian. Once set, the Lagrangian phase books
  /// the p dV work of the difference between it and the material's share of the cell's volume
  /// change to the cell's fluids (docs/coupling.md, "The solid's own volume change"); unset, that
  /// difference stays in the energy correction shared by heat capacity.
  void setExternalVolumeChange(int material, std::span<const double> volumeChange);
  void exchange();
  /// The end of exchange() with solids: each fluid's temperature moves the fraction of the cell's
  /// compliance the solids carry towards theirs (src/ice/exchange/trace_temperature.cpp).
  void relaxEmbeddedFluidTemperatures();
  /// Exchange increments of momentum [kg m/s] (3 comps) and internal energy [J] per owned cell
  /// (the energy: exchange heat, and the external material's share of the Lagrangian phase's
  /// energy correction).
  [[nodiscard]] const core::Field& exchangeMomentum(int material) const { return st_.mat[material].dMom; }
  [[nodiscard]] const core::Field& exchangeEnergy(int material) const { return st_.mat[material].dEnergy; }
  void advectFluids();

  // ---- checkpoints (implicit coupling repeats a step from the state before it)
  struct Checkpoint {
    std::vector<core::Field> fields;
    double t = 0;
    long steps = 0;
  };
  /// Copies of every field a step starts from (each material's mass, velocity, internal energy,
  /// specific volume, volume fraction, compressibility; the pressures) and the clock. Local.
  [[nodiscard]] Checkpoint checkpoint() const;
  void restore(const Checkpoint& c);

  // ---- restart (ice_solver_checkpoint.cpp)
  /// Puts this rank's complete state under `prefix`: every field of every material (mass,
  /// velocity, energies, specific volumes, fractions, compressibility, the Lagrangian values, the
  /// face velocities, the exchange increments), the pressures, the face fluxes, and the clock
  /// and counters. loadCheckpoint() returns a solver built from the same scene on the same ranks
  /// to it. Local.
  void saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const;
  void loadCheckpoint(const core::CheckpointData& data, const std::string& prefix);

  // ---- access
  [[nodiscard]] const core::Field& pressure() const { return st_.press; }
  [[nodiscard]] const IceState& state() const { return st_; }
  [[nodiscard]] IceState& state() {
    semi_.mobilityFresh = false;
    return st_;
  }
  /// The most equilibrium iterations a cell of this rank took in the last step's equilibrium
  /// solves (the progress line's p_iters; the per-cell counts, state().iters, are kept only when
  /// the output writes them: the field pressure_iterations).
  [[nodiscard]] int mostPressureIterations() const { return mostPressureIterations_; }
  [[nodiscard]] int numMaterials() const { return static_cast<int>(st_.mat.size()); }
  /// The momentum exchange coefficient K of materials a and b [kg/(m^3 s)] (ice.exchange.momentum,
  /// ice.exchange.pairs; 0 for a == b).
  [[nodiscard]] double momentumExchange(int a, int b) const {
    return K_[static_cast<std::size_t>(a * numMaterials() + b)];
  }
  [[nodiscard]] const core::Mesh& mesh() const { return mesh_; }
  [[nodiscard]] const core::Decomposition& decomposition() const { return decomp_; }
  [[nodiscard]] const core::Box& ownedBox() const { return owned_; }
  [[nodiscard]] const core::Comm& comm() const { return comm_; }
  /// Totals over every rank (collective).
  [[nodiscard]] Totals totals() const;
  /// Output fields over the owned cells: pressure, iterations, and per material density,
  /// velocity, temperature, volume fraction (collective-free; built on demand, only those whose
  /// name `wanted` accepts: all without it).
  [[nodiscard]] std::vector<core::Field> outputFields(const std::function<bool(const std::string&)>& wanted = {}) const;
  /// Their names, in outputFields' order (none built: output.fields is checked against them).
  [[nodiscard]] std::vector<std::string> outputFieldNames() const;
  /// Material density m/V (per unit total volume) of material m in owned cell (i,j,k).
  [[nodiscard]] double density(int m, int i, int j, int k) const;
  /// Iterations of the last step's semi-implicit pressure solve (0 for the explicit pressure)
  /// and their sum over every step so far; the same on every rank.
  [[nodiscard]] int linearIterations() const { return linIters_; }
  [[nodiscard]] long linearIterationsTotal() const { return linItersTotal_; }
  /// Multigrid set-ups of hypre's pressure solver so far (pfmg_pcg, smg_pcg; 0 otherwise).
  [[nodiscard]] long preconditionerSetups() const;
  /// The run's closing line on the semi-implicit pressure solve: the solver, the linear iterations
  /// over `steps` steps and per step, the multigrid set-ups (with hypre).
  [[nodiscard]] std::string pressureSolveSummary(long steps) const;
  [[nodiscard]] bool semiImplicit() const { return semiImplicit_; }
  /// Counters: cells where advection fell back to the internal-energy update (diagnostic).
  [[nodiscard]] long energyFallbacks() const { return fallbacks_; }
  /// Donor cells (per material and step, this rank's) whose outgoing face values advection
  /// blended toward their own to keep e and v positive (advection_phase.cpp, positivityBlend).
  [[nodiscard]] long positivityBlends() const { return positivityBlends_; }
  /// The heat the viscous updates gave the fluids since this solver was built, this rank's owned
  /// cells [J] (the kinetic energy they took; lagrangian_phase.cpp): the flow's viscous dissipation.
  [[nodiscard]] double viscousHeat() const { return viscousHeat_; }
  /// A fluid of the scene has a viscosity.
  [[nodiscard]] bool viscous() const { return anyViscous_; }
  /// The energy those fallbacks added (energy_audit.h; the health check reads it).
  [[nodiscard]] const EnergyAudit& energyAudit() const { return audit_; }
  /// A fluid present in an owned cell whose sound speed at the last equilibrium, c^2 = v / kappa,
  /// is out of range (health_check.h, soundSpeedSquared); the health check names it. Recorded
  /// where kappa is made: its array holds the Lagrangian specific volume from the Lagrangian
  /// phase on (MaterialState::lagSpvol).
  struct SoundSpeedViolation {
    int material;
    std::int64_t cell;  // stored-box index
    double c2;
  };
  [[nodiscard]] const std::vector<SoundSpeedViolation>& soundSpeedViolations() const { return soundBad_; }

 private:
  void initialize(const core::Scene& scene, bool coupledStart);
  /// The bound that sets the stable step (stableTimeStepLimit): on this rank, the cell (stored-box
  /// index) and the value of the bound there when `here`.
  struct StepBound {
    const char* limit = "";
    bool here = false;
    std::int64_t cell = -1;
    int material = -1;
    bool riemann = false;  // the value is the Riemann dissipation rate (riemannDissipationRate)
    bool acoustic = false;  // the value is the explicit acoustic rate c sum_d 1 / dx_d
    bool conduction = false;  // the value is the thermal diffusivity alpha (else a material's nu)
    double value = 0;
  };
  double stableTimeStep(StepBound* where) const;
  void fillGhosts(const std::vector<std::pair<core::Field*, FieldKind>>& fields, const std::vector<int>& mats);
  void fillMaterialGhosts(bool lagrangian);
  /// Phase 5, semi-implicit: assemble (face mobilities, the stencil, the right-hand side), solve
  /// for st_.dp (ice/linear), correct the face velocities.
  void solveSemiImplicit();
  /// Phase 2's pieces (pressure_phase.cpp): a failed equilibrium pressure is an error naming the
  /// cell, the materials and why (collective); theta, specific volume and kappa from the solved
  /// state, the held traces and cavities given.
  void reportEquilibriumFailures(const std::vector<EquilibriumFailure>& failures);
  void finishEquilibrium(const std::vector<std::pair<int, std::int64_t>>& held,
                         const std::vector<std::pair<int, std::int64_t>>& cavitated);
  /// ice.equilibrium: with_work (equilibrium_work.cpp): each fluid of a mixed cell does the work
  /// of its volume change at the cell's pressure, measured from its carried volume (per material,
  /// per owned cell); the fluids' energy conserved. Updates held/cavitated to the final solve's.
  std::vector<EquilibriumFailure> equilibrateWithWork(const std::vector<const double*>& rho,
                                                      const std::vector<double*>& rhoMicro,
                                                      const std::vector<std::vector<double>>& carried,
                                                      std::vector<std::pair<int, std::int64_t>>& held,
                                                      std::vector<std::pair<int, std::int64_t>>& cavitated);
  void allocateSemiImplicitScratch();
  void assembleSemiImplicit();
  void solvePressureSystem();

  core::Comm comm_;
  core::Mesh mesh_;
  core::Decomposition decomp_;
  core::Box owned_;
  std::unique_ptr<core::GhostExchange> ghosts_;
  IceBoundary bc_;
  IceState st_;
  OwnedCells ownedCells_;  // linear indices (stored box) of the owned cells, computed where read
  std::unique_ptr<EquilibriumPressure> equil_;
  std::vector<double> K_, H_;             // exchange coefficients (n x n)
  bool anyK_ = false, anyH_ = false, anyExternal_ = false, anyViscous_ = false, anyConduction_ = false;
  bool secondOrder_ = true, semiImplicit_ = false;
  // The semi-implicit step's bound (stableTimeStep's last value, mutable: the coupler asks for it)
  // and the bound of the step taken last (beginStep; 0 before the first): the next step is at most
  // kSemiImplicitStepGrowth times it. Checkpointed with the clock.
  mutable double bound_ = 0;
  double lastBound_ = 0;
  bool stepRamp_ = false;  // semi-implicit with two or more fluids (kSemiImplicitStepGrowth)
  double dtInitial_ = 0;   // time.dt_initial: the first step's bound (0: none)
  double soundFraction_ = 0.1;  // ice.semi_implicit_sound_fraction: the semi-implicit step's speed floor / c
  int mostPressureIterations_ = 0;  // mostPressureIterations()
  // The per-cell equilibrium iteration counts to fill (nullptr where they are not kept).
  int* pressureIterationsOut() { return st_.iters.empty() ? nullptr : st_.iters.data(); }
  double semiTheta_ = 1.0;      // ice.semi_implicit_theta: the semi-implicit pressure's time weight
  bool equilibriumWork_ = false;  // ice.equilibrium: with_work
  enum class LinearSolver { Cg, Bicgstab, PfmgPcg, SmgPcg } linearSolver_ = LinearSolver::PfmgPcg;
  std::string linearSolverName_ = "pfmg_pcg";
  int linIters_ = 0;
  long linItersTotal_ = 0;
  int limiter_ = 1;
  double q1_ = 0, q2_ = 0;  // shock viscosity (linear, quadratic)
  bool riemannFacePressure_ = true;  // ice.face_pressure: riemann, or auto without external materials
  bool riemannLowMach_ = false;      // ice.face_pressure: riemann_low_mach (lowMachScale, face_phase.cpp)
  /// The Riemann face pressure is in use. With external materials (coupled runs, asked for by
  /// `riemann`) it acts only at faces whose two cells hold none of them: computeCellMixes gives a
  /// cell with a solid no impedance, which turns off the face pressure's dissipation, the face
  /// velocity's Riemann response and their time-step rate at its faces (docs/ice.md, method step 6).
  [[nodiscard]] bool riemannFacePressureOn() const { return riemannFacePressure_; }
  double cfl_ = 0.4, tEnd_ = 0, dtMax_ = 1e30, dtMin_ = 0, solverTol_ = 1e-10;
  int solverMaxIt_ = 1000, preconditionerReuse_ = 20;
  /// hypre's structured PCG (pfmg_pcg, smg_pcg), made on first use.
  linear::HypreStructPcg& structSolver();
  core::RealVect gravity_{0, 0, 0};
  bool anyGravity_ = false;
  struct Source {
    int material;
    double power, start, end;
    std::vector<std::int64_t> cells;
    std::vector<double> share;  // per cell: the fraction of its volume inside the source's shape
  };
  std::vector<Source> sources_;
  core::StepCollapse collapse_{0.0};  // time.dt_collapse_fraction (step())
  double t_ = 0, dt_ = 0;
  long nsteps_ = 0, fallbacks_ = 0, positivityBlends_ = 0;
  double viscousHeat_ = 0;  // viscousHeat()
  EnergyAudit audit_;
  /// The Lagrangian phase's correction of the cells with a solid, given after the momentum
  /// exchange with the drag heat (applyDeferredCorrection): stored and owned index, D [J], and the
  /// cell's heat capacity C = sum m cv [J/K] (the masses do not change between the two phases).
  struct DeferredCorrection {
    std::int64_t c, oc;
    double D, C;
  };
  std::vector<DeferredCorrection> deferred_;
  std::vector<double> dragHeat_;  // exchange(): per owned cell, the drag heat [J]
  std::vector<double> viscousSecond_;  // computeSourcesAndLagrangian: per owned cell, the viscous updates' -m du.du/2 [J]
  std::vector<double> viscousGrad_;  // computeSourcesAndLagrangian: a viscous fluid's d_q u_comp per stored cell
  void applyDeferredCorrection();
  std::vector<SoundSpeedViolation> soundBad_;  // soundSpeedViolations(): finishEquilibrium's
  std::array<InflowState, 6> inflow_{};
  core::Field initialPressure_;           // the scene's pressure per owned cell (coupled start only)
  /// Coupled start only, per owned cell whose centre lies in a solid object inside a fluid region:
  /// the fluids that region holds (bit r), which fitFluidsToExternalVolume lets fill the volume
  /// the solid leaves free (0 elsewhere: every fluid scaled alike).
  std::vector<std::uint32_t> solidCellFluids_;
  SemiImplicitScratch semi_;
  HeldShares held_;
  // The equilibrium phase's scratch (kept from step to step: no allocation per step): the EOS
  // batches of finishEquilibrium, kEquilibriumChunk owned cells at a time.
  static constexpr std::size_t kEquilibriumChunk = 512;
  std::vector<double> eqRho_, eqE_, eqC2_;
  std::vector<std::int64_t> eqCells_;  // the chunk's stored indices
  AdvectionScratch adv_;
  // The cells' mixture values of the Riemann face pressure over a block of slabs, made by each of
  // its readers (the stable step, the face velocities, the face pressure) as it sweeps the slabs
  // (forMixBlocks in phase_units.h): a few operations per cell and reader against four arrays of
  // the whole box.
  mutable CellMixes mixes_;
  // ice.face_pressure: riemann_low_mach: the cell pressure before the pressure increment (stored
  // box), which the face pressure's mixtures read (lowMachScale), as the stable step's and the
  // face velocities' do; empty otherwise.
  std::vector<double> lowMachPressure_;
  // The semi-implicit stable step's mixture impedance per cell (owned box grown by one).
  mutable std::vector<double> impedanceScratch_;
};

}  // namespace mpmice::ice
