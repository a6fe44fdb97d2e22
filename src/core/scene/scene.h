#pragma once
/// @brief A scene as understood by every program: mesh, time, materials, geometry, boundary
/// conditions, loads and sources, solver options, coupling and output.
///
/// A scene file (YAML) is the single source of truth of a run: mpm_solver, ice_solver, the
/// coupler and the monolithic driver all read the same file through loadScene(), which validates
/// it against one schema (scene_schema.cpp) and fills in defaults. Every value is SI.
/// Errors are SceneError, whose message names the file, the line, the key path, the value read
/// and what was expected.
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/scene/options.h"

namespace mpmice::core {

/// Where a value came from in the scene file (1-based line and column; 0 when generated).
/// The specs below compare equal member by member, locations included.
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
  [[nodiscard]] std::string str() const;  // "file:line:column"
  bool operator==(const SourceLoc&) const = default;
};

class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLoc& where, const std::string& key, const std::string& what);
  [[nodiscard]] const SourceLoc& where() const { return where_; }
  [[nodiscard]] const std::string& key() const { return key_; }

 private:
  SourceLoc where_;
  std::string key_;
};

/// A model chosen by name (EOS, constitutive model, ...) with its validated numeric parameters.
struct ModelSpec {
  std::string type;                                    // the scene name, e.g. "ideal_gas"
  std::map<std::string, double> params;                // defaults filled in
  std::map<std::string, std::vector<double>> tables;   // e.g. hardening: plastic strain / stress
  SourceLoc where;
  [[nodiscard]] double get(const std::string& key) const;  // throws std::out_of_range if absent
  [[nodiscard]] double get(const std::string& key, double fallback) const;
  [[nodiscard]] bool has(const std::string& key) const { return params.count(key) != 0; }
  bool operator==(const ModelSpec&) const = default;
};

enum class MaterialKind { Solid, Fluid };

struct MaterialSpec {
  std::string name;
  MaterialKind kind = MaterialKind::Fluid;
  double density = 0;               // reference (solid) density; fluids: optional, 0 = unset
  ModelSpec constitutive;           // solids: linear_elastic | neo_hookean | j2_plasticity
  ModelSpec eos;                    // fluids: ideal_gas | stiffened_gas | mie_gruneisen | jwl;
                                    // solids: solid_bulk (defaults from the constitutive model)
  double specific_heat = 716.0;     // cv [J/(kg K)]
  double viscosity = 0;             // dynamic viscosity [Pa s]; 0 = inviscid
  double thermal_conductivity = 0;  // [W/(m K)]; 0 = no conduction
  double thermal_expansivity = 0;   // beta [1/K] (solids)
  ModelSpec cavitation;             // fluids: pressure_cutoff (type empty: none; docs/ice.md "Cavitation")
  SourceLoc where;
  bool operator==(const MaterialSpec&) const = default;
};

/// A region of space: box, sphere (circle in 2D), cylinder, annulus, union, difference.
struct ShapeSpec {
  std::string type;
  RealVect lo{0, 0, 0}, hi{0, 0, 0};   // box
  RealVect center{0, 0, 0};            // sphere, cylinder, annulus (point on the axis)
  RealVect axis{0, 0, 1};              // cylinder, annulus (3D; 2D shapes ignore it)
  double radius = 0;                   // sphere/circle, cylinder
  double inner_radius = 0, outer_radius = 0;  // annulus
  double length = 0;                   // cylinder, annulus in 3D: extent along the axis (0 = infinite)
  std::vector<ShapeSpec> children;     // union: any child; difference: first minus the rest
  SourceLoc where;
  /// Point membership (dim = mesh dimension: coordinates beyond it are ignored).
  [[nodiscard]] bool contains(const RealVect& x, int dim) const;
  bool operator==(const ShapeSpec&) const = default;
};

/// One material's share of a geometry object.
struct FillSpec {
  std::string material;
  double volume_fraction = 1.0;
  bool operator==(const FillSpec&) const = default;
};

/// A geometry object: fills a region with materials in a given state. Later objects override
/// earlier ones in the cells (fluids) they cover; solid objects create particles.
struct RegionSpec {
  std::string name;
  ShapeSpec shape;
  std::vector<FillSpec> fill;          // fractions sum to one
  RealVect velocity{0, 0, 0};          // the velocity at velocity_origin [m/s]
  /// A linear initial velocity field u(x) = velocity + velocity_gradient (x - velocity_origin):
  /// row i holds d u_i / d x_j [1/s] (zero: a uniform velocity). The fluid samples it at each
  /// cell centre (the cell mean of a linear field), a solid at each particle.
  std::array<RealVect, 3> velocity_gradient{};
  RealVect velocity_origin{0, 0, 0};   // [m]
  double temperature = 300.0;
  std::optional<double> pressure;      // fluids: required
  std::optional<double> density;       // fluids: optional (else from EOS(p, T))
  IntVect particles_per_cell{2, 2, 2}; // solids: per direction
  SourceLoc where;
  /// The initial velocity at x (velocity, plus the gradient's part when one is given).
  [[nodiscard]] RealVect velocityAt(const RealVect& x) const {
    RealVect u = velocity;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        u[static_cast<std::size_t>(i)] += velocity_gradient[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] *
                                          (x[static_cast<std::size_t>(j)] - velocity_origin[static_cast<std::size_t>(j)]);
    return u;
  }
  bool operator==(const RegionSpec&) const = default;
};

enum class BoundaryType { Symmetry, SlipWall, NoSlipWall, Inflow, Outflow, Periodic, Free };

/// A face matter may leave through freely (free, outflow): ICE fills its ghosts with zero gradient,
/// MPM leaves its nodes alone, and a solid reaching it continues beyond it as far as the coupling is
/// concerned.
inline bool isOpenBoundary(BoundaryType t) { return t == BoundaryType::Free || t == BoundaryType::Outflow; }

/// Boundary condition of one mesh face ("x-", "x+", "y-", ...).
struct BoundarySpec {
  BoundaryType type = BoundaryType::Symmetry;
  RealVect velocity{0, 0, 0};          // inflow
  std::optional<double> pressure;      // inflow, outflow (fixed pressure); empty = zero gradient
  std::optional<double> density;       // inflow
  double temperature = 300.0;          // inflow
  std::string material;                // inflow: which fluid enters (default: the first fluid)
  SourceLoc where;
  bool operator==(const BoundarySpec&) const = default;
};

/// A load on solid particles: "traction" (vector per unit area) or "pressure" (normal to the
/// particle set's surface, pointing away from `center`), on the particles of `material` inside
/// `shape`, ramped linearly over `ramp` seconds from `start`; or "file": point forces read from a
/// fluid code's export (core/io/force_export_file.h), mapped conservatively onto the surface
/// particles of `material` and held from t = 0 (src/couplings/surface/solid/file_load.h).
struct LoadSpec {
  LoadType type = LoadType::Pressure;
  std::string material;
  ShapeSpec shape;
  RealVect traction{0, 0, 0};
  double pressure = 0;
  RealVect center{0, 0, 0};
  double start = 0, ramp = 0;
  std::string file;                                     // file loads: path (relative to the scene file)
  InterfaceMapping mapping = InterfaceMapping::Rbf;     // file loads
  double rbf_support = 0;                               // file loads: 0 = thin-plate spline
  double depth = 0;                                     // file loads, 2D: 0 = the file's, else 1 m
  RealVect moment_center{0, 0, 0};                      // file loads: the reported moment's origin
  SourceLoc where;
  bool operator==(const LoadSpec&) const = default;
};

/// An energy source for a fluid: power per unit volume of that fluid [W/m^3] into `material` in
/// the cells inside `shape` between `start` and `end` (a shared cell gets power x theta x V).
struct SourceSpec {
  std::string material;
  ShapeSpec shape;
  double power_density = 0;
  double start = 0, end = 0;
  SourceLoc where;
  bool operator==(const SourceSpec&) const = default;
};

struct TimeSpec {
  double end = 0;
  double cfl = 0.4;
  double dt_max = 1e30;
  double dt_min = 0;        // a step below this stops the run with an error
  double dt_initial = 0;    // 0 = from the CFL condition
  double dt_collapse_fraction = 1e-3;  // a stable step below this x the first one stops the run (0 = off)
  long max_steps = 0;       // 0 = no limit
  bool operator==(const TimeSpec&) const = default;
};

struct MpmOptions {
  std::string shape_function = "linear";   // linear | gimp | bspline2 | bspline3
  std::string update = "usl";              // usf | usl | musl
  double flip = 1.0;                       // 1 = FLIP, 0 = PIC
  double damping = 0;                      // velocity-proportional damping [1/s]
  bool sort_particles = true;
  // The stress work each particle accumulates (the solid's internal energy): "material" (the
  // models' midpoint stress power), "grid" (the work its internal force did on the nodes: the
  // coupled energy budget closes to round-off) or "auto" (grid in a volume-coupled run, material
  // otherwise). docs/mpm.md "Stress work".
  std::string stress_work = "auto";
  // A particle that leaves the mesh through an `outflow` face: "remove" (it leaves the simulation,
  // counted and reported, its mass, momentum and energy booked as outflow) or "error" (the run
  // stops). Leaving through any other face is always an error.
  std::string outflow_particles = "remove";
  bool operator==(const MpmOptions&) const = default;
};

struct ExchangePair {
  std::string a, b;
  double momentum = 0, heat = 0;
  bool operator==(const ExchangePair&) const = default;
};

struct IceOptions {
  std::string advection = "second_order";  // first_order | second_order
  std::string limiter = "van_leer";        // minmod | van_leer | superbee (second order)
  std::string pressure_solver = "explicit";  // explicit | semi_implicit
  std::string linear_solver = "pfmg_pcg";  // pfmg_pcg | smg_pcg | cg | bicgstab (semi_implicit)
  double solver_tolerance = 1e-10;
  int solver_max_iterations = 1000;
  // pfmg_pcg / smg_pcg: the most solves one multigrid set-up serves (its coarse levels lag the
  // matrix; 1: a fresh hierarchy every step). ice/linear/hypre_struct_pcg.h.
  int preconditioner_reuse = 20;
  double exchange_momentum = 1e15;         // default K for every pair
  double exchange_heat = 0;                // default H for every pair
  std::vector<ExchangePair> exchange_pairs;  // overrides per pair
  int max_pressure_iterations = 100;
  double pressure_tolerance = 1e-11;
  // Shock viscosity at faces in compression (du < 0): q = rho (linear c |du| + quadratic du^2),
  // added to the face pressure (0, 0: off).
  double shock_viscosity_linear = 0;
  // Face pressure: "riemann" (the two-shock approximate Riemann solution at faces in compression,
  // docs/ice.md) or "average" (the density-weighted average of the cell pressures).
  std::string face_pressure = "auto";  // auto: riemann for fluids alone, average with solids
  double shock_viscosity_quadratic = 0;
  // Traces: a fluid below this fraction of a cell's fluid mass is held at its carried volume when
  // the cell's pressure is below its own (docs/ice.md "Traces"); 0 turns the rule off.
  double trace_mass_fraction = 1e-6;
  // The semi-implicit step's speed floor in its CFL bound, as a fraction of the cell's sound speed:
  // the step is at most cfl dx / (fraction c) even where the flow is slower (docs/ice.md
  // "Semi-implicit step"). A low-Mach flow whose acoustics do not matter may lower it.
  double semi_implicit_sound_fraction = 0.1;
  // The semi-implicit pressure's time weight theta: the face velocities and the Lagrangian phase
  // take p_eq + theta dp, the pressure equation kbar dp - theta dt^2 div(beta grad dp) = -dt div U*.
  // 1: backward Euler (dissipative, the default); 0.5: Crank-Nicolson (second order in time, no
  // damping of the acoustics). docs/ice.md "The semi-implicit pressure's time weight".
  double semi_implicit_theta = 1.0;
  // The equilibrium pressure's energies: "fixed_energy" (each material keeps its carried e while
  // the solve moves volume between materials) or "with_work" (each fluid does the work p dv of its
  // volume change, the fluids' energy conserved; docs/ice.md "Equilibrium with work").
  std::string equilibrium = "fixed_energy";
  bool operator==(const IceOptions&) const = default;
};

struct ConvergenceSpec {
  std::string field;
  MeasureType type = MeasureType::Relative;
  double limit = 1e-6;
  bool strict = false;            // strict: must hold; suffices: enough on its own
  bool operator==(const ConvergenceSpec&) const = default;
};

struct AccelerationSpec {
  AccelerationType type = AccelerationType::None;
  double relaxation = 0.5;        // constant; the initial one for aitken and iqn_ils
  int reuse = 8;                  // iqn_ils: past steps kept
  double filter = 1e-2;           // iqn_ils: QR filter threshold (docs/coupling.md: why 1e-2)
  bool preconditioner = false;    // iqn_ils: residual_sum (true) or none (default; docs/coupling.md)
  bool operator==(const AccelerationSpec&) const = default;
};

/// The interface of a surface-coupled fluid (coupling.fluid: openfoam): which solid's surface
/// particles meet which boundary patch of the fluid mesh, how data are mapped between them and
/// which OpenFOAM case and solver run the fluid. See docs/openfoam.md.
struct InterfaceSpec {
  std::string solid;                        // material whose surface particles are coupled
  std::string patch;                        // the fluid's coupled boundary patch
  std::string openfoam_case;                // case directory (relative to the scene file)
  std::string openfoam_solver = "pimpleFoam";
  InterfaceMapping mapping = InterfaceMapping::Rbf;
  double rbf_support = 0;                   // rbf: 0 = thin-plate spline, > 0 = Wendland C2 radius [m]
  CouplingMode mode = CouplingMode::TwoWay;  // one_way: fluid to steady state, forces once
  double fluid_density = 1.0;               // rho for kinematic-pressure solvers (pimpleFoam) [kg/m^3]
  SourceLoc where;
  bool operator==(const InterfaceSpec&) const = default;
};

struct CouplingSpec {
  Schedule schedule = Schedule::Monolithic;
  int min_iterations = 1, max_iterations = 50;
  bool accept_unconverged = false;
  std::vector<ConvergenceSpec> convergence;
  AccelerationSpec acceleration;
  double timeout = 60.0;                // seconds any wait may take
  int mpm_ranks = 1, ice_ranks = 1;     // for `coupler run`
  FluidSolver fluid = FluidSolver::Ice;
  InterfaceSpec interface;              // fluid: openfoam (required there)
  // How ICE's volume balance moves a solid's volume across cell faces: "ice" (ICE's face fluxes
  // of the solid's cell fraction) or "mpm" (MPM's face transport of its node-to-cell average, the
  // fluids locked to the solid only at faces inside it; docs/flap.md "Mixed cells").
  std::string solid_transport = "ice";
  // The pressure MPM's mean-stress correction gives a solid's surface particles (those whose
  // stencil sees the surface): "interpolated" (from the nodes, the fluid's pressure among the
  // cells around them: the static load of the fluid reaches into the surface, the seed cylinder's
  // Eq. 13) or "cell" (each particle its own cell's, as inside the solid: no net work on the
  // solid's own modes; a soft solid in a liquid, docs/verification-coupled.md "Added mass over
  // many periods").
  std::string surface_pressure = "interpolated";
  bool operator==(const CouplingSpec&) const = default;
};

/// A point followed through the run: the solid particle nearest to `point` at t = 0, its
/// position and displacement written every step to <directory>/<scene>_probes.csv.
struct ProbeSpec {
  std::string name;
  RealVect point{0, 0, 0};
  SourceLoc where;
  bool operator==(const ProbeSpec&) const = default;
};

struct OutputSpec {
  std::string directory = "output";
  double interval = 0;                  // 0 = only the last step
  double checkpoint_interval = 0;       // [s] simulated; 0 = no checkpoints
  std::vector<std::string> fields;      // empty = every field the solver offers
  bool particles = true;
  bool enabled = true;
  std::vector<ProbeSpec> probes;        // solid points followed every step
  bool operator==(const OutputSpec&) const = default;
};

struct Scene {
  std::string file;          // path it was read from
  std::string name;          // scene: key (default: the file name)
  std::string description;
  Mesh mesh;
  std::array<BoundarySpec, 6> boundary;  // x-, x+, y-, y+, z-, z+
  TimeSpec time;
  RealVect gravity{0, 0, 0};
  std::vector<MaterialSpec> materials;
  std::vector<RegionSpec> geometry;
  std::vector<LoadSpec> loads;
  std::vector<SourceSpec> sources;
  MpmOptions mpm;
  IceOptions ice;
  CouplingSpec coupling;
  OutputSpec output;

  [[nodiscard]] const MaterialSpec* material(const std::string& name) const;
  [[nodiscard]] int materialIndex(const std::string& name) const;  // -1 if absent
  [[nodiscard]] std::vector<int> solids() const;   // indices into materials
  [[nodiscard]] std::vector<int> fluids() const;
  [[nodiscard]] std::array<bool, 3> periodic() const;
  bool operator==(const Scene&) const = default;
};

/// Reads, validates and completes a scene. Throws SceneError.
Scene loadScene(const std::string& path);
/// Same from text (tests); `file` names it in errors.
Scene parseScene(const std::string& yamlText, const std::string& file);
/// The scene as understood, defaults filled in, as YAML (what `coupler check` prints).
std::string dumpScene(const Scene& s);
/// A hash of mesh, materials and boundary conditions (the handshake compares it).
std::string sceneHash(const Scene& s);

const char* boundaryFaceName(int face);  // 0..5 -> "x-", "x+", ...
const char* toString(BoundaryType t);

}  // namespace mpmice::core
