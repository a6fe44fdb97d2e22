#pragma once
/// @brief libmpm's named constants: the reference state and the regularisation constants (small-mass
/// cut-offs, mass floors, tolerances) that were literals in src/mpm and the MPM-ICE solid side.
///
/// Each value is part of the numbers the tests reproduce; the comment names the test that would
/// fail if it changed, or says that none does. Change one only with the tests it names.
namespace mpmice::mpm {

// ---- reference state ----------------------------------------------------------------------------

/// [Pa] The pressure at which a solid is stress-free when its EOS does not give one
/// (`threshold_pressure`); p_ref of the mean-stress correction sigma + (p - p_ref) I.
/// Pinned by: no test directly. The scene catalog (core/scene/model_catalog.cpp) fills
/// threshold_pressure = 101325 for parsed scenes, so the fallback only serves scenes built in code;
/// tests/unit/scene/test_scene_parse.cpp pins the catalog's copy of the value.
inline constexpr double kReferencePressure = 101325.0;

/// [cells] Width over which the solid's node mass falls to zero at its surface, as the mean-stress
/// correction sees it: a particle is wholly a surface particle (the pressure's excess over the
/// solid side's acts along the normal only) where h |grad M| / M >= 1 / kSurfaceLayerCells, M the
/// node mass interpolated to the particle. The B-splines' mass ramps over about two cells.
/// Pinned by: tests/verification/coupled/test_cylinder_annulus.cpp (seed cylinder at dx 0.05:
/// 1.0 gives 0.0501, 2.0 0.0510, interior bias -0.5 % and +0.2 %; docs/coupling.md).
inline constexpr double kSurfaceLayerCells = 2.0;
/// A cell's cooling (NodeCellOperators::addCellEnergy) takes its solid's thermal energy down to
/// this share of the material's mean temperature at most (the cell's particle mass at that
/// temperature); the rest goes to every particle of the material in proportion to its thermal
/// energy, counted (spreadCooling()), so that no region of a solid is drained by a cooling that
/// keeps arriving (the energy correction at a solid's leading edge, docs/coupling.md).
inline constexpr double kMinCellTemperatureShare = 0.5;

/// [K] The temperature of the absent-solid state (a cell the solid does not reach still needs a
/// valid state for ICE's equilibrium pressure; its volume fraction is zero).
/// Pinned by: no test directly; the MPMD-against-in-process launch tests
/// (tests/integration/mpmice, mpmice_mpmd_equals_monolithic_*) compare two runs that share it.
inline constexpr double kReferenceTemperature = 300.0;

// ---- particle order ----------------------------------------------------------------------------

/// Steps between particle sorts by (material, cell) when mpm.sort_particles is on. The order of the
/// particles is the summation order of every particle-to-grid pass, so it moves results by round-off.
/// Pinned by: no test on its value; the integration comparisons at 1e-10 (tests/integration/mpmice)
/// run both launches with it.
inline constexpr int kSortInterval = 20;

// ---- time step ------------------------------------------------------------------------------------

/// The largest CFL number MPM's step takes: the stable step is min(time.cfl, this) dx_min / max(c + |v|).
/// The explicit step with FLIP / PIC transfers is not stable to CFL 1: the grid velocity a step
/// hands on is the particles' re-projection (lumped^-1 consistent mass, eigenvalue a < 1 for the
/// shortest modes), which moves the bound from dt c / dx <= 1 to <= 1 / sqrt(2 - a) ~ 0.71, and a
/// node a free surface's particle barely reaches (GIMP, mass and stiffness ~ overlap^2) lowers it
/// further. The linearised 1D step (free bar, FLIP, offsets 0-0.75 cell to the grid): GIMP 0.53 / 0.60 /
/// 0.63 at 3 / 2 / 1 particles per cell, bspline2 0.74 (2 per cell), linear hats down to 0.44 at a
/// free surface (unbounded as a surface particle's weight on a node -> 0: no cap holds it); the adiabatic
/// piston (GIMP, 2 per cell) grows a sawtooth from CFL 0.67 (MPM alone) and 0.69 (coupled)
/// (docs/mpm.md "The time step's limit"). 0.5 is below every GIMP and B-spline case; 2D / 3D were
/// not analysed.
/// Pinned by: tests/verification/coupled/test_piston.cpp, AdiabaticPiston.AtCfl07RunsWithinTheMpmStepsLimit
/// (the piston at time.cfl 0.7 ends within the piston's bound), and
/// tests/unit/mpm/test_solver_setup.cpp, TimeStep.CflAboveTheMpmLimitIsCapped.
inline constexpr double kMaxStableCfl = 0.5;

// ---- regularisation -----------------------------------------------------------------------------

/// Mass floor of the grid, as a fraction of the smallest particle mass: a node (or cell) with less
/// mass has no velocity (v = p / m is set to 0) and a cell below it is empty (absent-solid state).
/// Pinned by: no test fails on its exact value (it only removes round-off-sized masses); the
/// tests that would show a change are the integration comparisons at 1e-10
/// (tests/integration/mpmice) and tests/unit/mpm/test_solver_setup.cpp (Phases.*).
inline constexpr double kMassFloorFraction = 1e-12;

/// Small-mass cut-off of the grid update with linear hats, as a fraction of the smallest particle
/// mass: a node with less mass keeps v_L = v_n (see MpmSolver::kSmallMassFraction).
/// Pinned by: tests/verification/mpm/test_mpm_bar.cpp, VibratingBar.LinearUslStableAtSmallMassNodes
/// (without it linear + USL blew up at 50 cells).
inline constexpr double kSmallMassFraction = 1e-2;

/// Relative tolerance of the J2 radial return's Newton iteration (|r| <= tol * q).
/// Pinned by: tests/unit/mpm/test_constitutive.cpp, J2Plasticity.ReturnMappingHitsYieldSurface,
/// only loosely: it checks q on the yield surface to 1e-6 (linear hardening converges in one step),
/// so only a tolerance far looser than this one fails it.
inline constexpr double kJ2ReturnTolerance = 1e-13;
/// Iteration cap of that Newton iteration (exact in one step for linear hardening).
/// Pinned by: no test on its value (the J2Plasticity tests of test_constitutive.cpp converge
/// within it; a cap too small would fail them).
inline constexpr int kJ2MaxIterations = 50;

/// Crushable foam return (crushable_foam.cpp): relative tolerance on the multiplier's bracket and
/// on the consistency residual (|r| <= tol * Y), and the iteration cap of the safeguarded secant.
/// Pinned by: tests/unit/mpm/test_constitutive.cpp, CrushableFoam.* (closed forms to 1e-9 relative;
/// a tolerance looser than about 1e-8 fails them).
inline constexpr double kFoamReturnTolerance = 1e-13;
inline constexpr int kFoamReturnMaxIterations = 200;

/// Tolerance, as a fraction of the mesh extent, with which a solid region may touch a non-symmetry
/// mesh face before particle generation rejects it.
/// Pinned by: no test (the scene tests place solids well inside or on symmetry faces).
inline constexpr double kGeneratorFaceTolerance = 1e-9;

/// Probe ties: squared distances equal to within this fraction of dx_min^2 count as equal (the
/// lowest particle id wins).
/// Pinned by: tests/unit/mpm/test_probes.cpp, ProbeRecorder.PicksTheNearestParticleAndTheLowestIdOnTies.
inline constexpr double kProbeTieTolerance = 1e-10;

/// The particle generator's check of what the particles fill against the shape (RegionVolume):
/// sample points per particle spacing and direction in the cells the particle lattice does not
/// fill whole (16 in 1D and 2D: 1024 points per cut cell at 2 particles per direction; 6 in 3D:
/// 1728; a face is placed within half a sample spacing), and
/// the relative difference above which the run's log warns (geometryVolumeWarnings).
/// Pinned by: tests/unit/mpm/test_solver_setup.cpp, ParticleGeneration.ReportsAShapeRoundedByTheLattice.
inline constexpr int kShapeVolumeSamples2D = 16;
inline constexpr int kShapeVolumeSamples3D = 6;
inline constexpr double kGeometryVolumeWarning = 0.01;

}  // namespace mpmice::mpm
