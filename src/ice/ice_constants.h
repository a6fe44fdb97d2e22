#pragma once
/// @brief The reference state and the regularisation constants of ICE, in one place.
///
/// Each value says which test fails if it changes (found by reading tests/; "no test pins it"
/// where none asserts on it: the value is then kept for the results it gives, not for a test).
/// The scene's own defaults (src/core/scene: a region's or an inflow's temperature, 300 K) are
/// separate, and not taken from here.
namespace mpmice::ice {

// ---- reference state (absent fluids, external materials without a covering region, the
// pressure of cells no fluid region covers)
/// Reference pressure [Pa] (1 atm). No test pins it (the tests place every fluid and give
/// external materials their state through setExternalMaterialState).
inline constexpr double kReferencePressure = 101325.0;
/// Reference temperature [K]. No test pins it (as kReferencePressure; ExternalSolidEos's
/// internalEnergy, cv * T_ref, is never asked for by a test).
inline constexpr double kReferenceTemperature = 300.0;

// ---- face pressure (ice.face_pressure: riemann)
/// Slope Gamma of the shock impedance W = rho (c + Gamma |du|) in the two-shock face pressure:
/// (gamma + 1) / 2 of an ideal gas with gamma = 1.4 (the strong-shock limit of its Hugoniot).
/// Pinned by IceShockDefaults.* (the overshoot bounds) and IceSod.* (the L1 bounds).
inline constexpr double kShockImpedanceSlope = 1.2;
/// ice.face_pressure: riemann_low_mach: the face's acoustic strain |p_R - p_L| / (rho c^2) (the
/// relative density jump of an acoustic wave) at which the Riemann terms act in full (lowMachScale
/// in face_phase.cpp). Measured between the coupled tests' needs (4 Dec 2026): the shock slab's
/// reflected plateau rings at up to 0.05 (damped in full from it), the flap's Mach 0.03 flow makes
/// 4e-4; 0.01 and 0.003 gave the same results on the added-mass, flap and slab tests.
inline constexpr double kRiemannFullStrain = 0.01;

// ---- time step (explicit pressure)
/// The largest acoustic Courant number c dt sum_d 1 / dx_d the explicit step takes (its bound
/// next to time.cfl's convective-acoustic one, IceSolver::stableTimeStep). The explicit step
/// (face velocities from the cell pressures, the pressure increment from their divergence, the
/// cell momentum from the faces' mean pressures) is, linearised about a state at rest without the
/// Riemann terms (the faces of an expansion), unstable above nu = c dt / dx = 1 / sqrt(2) in 1D and
/// above sum_d nu_d^2 = 1 / 2 in 2D and 3D: the amplification |g| is 1.07 at 0.72, 1.25 at 0.75,
/// 2.24 at 0.9 (`python3 benchmarks/ice/acoustic_stability.py`). sum_d nu_d <= 0.7 keeps
/// sum_d nu_d^2 below 1 / 2 in every dimension. Measured (docs/ice.md "The explicit step's
/// acoustic limit"): water's rarefaction at time.cfl 0.9 grew an odd-even pressure oscillation.
/// Pinned by IceTimeStep.ExplicitAcousticCourantBoundsASlowFlowAboveCfl07 and
/// IceShockDefaults.WaterRarefactionAtCflOneStaysMonotone.
inline constexpr double kMaxAcousticCourant = 0.7;
/// The semi-implicit step's start and growth with two or more fluids (IceSolver::stableTimeStep):
/// the run's first step is the explicit pressure's stable step (sum_d (|u_d| + c) / dx_d, the
/// acoustic Courant number at most kMaxAcousticCourant; time.dt_initial instead when given) and each
/// later step at most this factor times the bound of the step before. The semi-implicit convective
/// bound counts the speed a pressure jump creates only to the linear Riemann estimate
/// |dp| / (Z_c + Z_n); where a liquid meets a gas the contact's cells outrun it (water at 1 GPa
/// against air: 377 m/s estimated, 526-534 m/s in steps 4-6 against u* = 492 m/s) and the pulse
/// stays in the shocked gas: 1D, first order, 400 cells, +5.00 % pressure behind the air shock and
/// 3.7e-4 of the energy made by the fallbacks; van Leer and superbee stopped (air below 0 K at the
/// contact). With the start: +0.70 %, no energy made, both limiters complete at 100-1600 cells
/// (docs/ice.md "The semi-implicit step's start"; 1.2 gave +2.08 %). One fluid keeps the
/// semi-implicit bound from the first step (Sod needs no start: +0.12 % without it). Pinned by
/// IceTimeStep.SemiImplicitWithTwoFluidsStartsFromTheExplicitStepAndGrows and
/// IceShockDefaults.SemiImplicitWaterAirStartsFromTheExplicitStep.
inline constexpr double kSemiImplicitStepGrowth = 1.1;

// ---- regularisation: traces, caps and cut-offs
/// Volume fraction of each fluid left in the cells a solid object of the scene covers at the
/// start. No test pins it (only the mpmice integration tests have solid regions, and they
/// compare runs that share the value).
inline constexpr double kTraceFraction = 1e-10;
/// Sub-cells per direction with which a cell the edge of an energy source's shape cuts measures
/// the fraction of its volume inside (midpoint rule; 8 in 2D resolves the fraction to 1/64).
inline constexpr int kSourceSamples = 8;
/// The largest share of a cell the solids' supplied volume may take in the equilibrium pressure
/// (fill cap; fitFluidsToExternalVolume leaves the fluids 1 - kMaxSolidFraction of the cell).
/// Pinned by IceExternal.OverfullSolidCellsKeepTheSolidPressureAndFluidsFitTheFreeVolume (the
/// solid's theta within 1e-6 of 1) and IceExchange.DragHeatIsSharedAtOneTemperatureRiseNotGivenToATrace
/// ("air is a trace": m_air < 1e-8 m_steel).
inline constexpr double kMaxSolidFraction = 1.0 - 1e-9;
/// Material mass [kg] below which advection drops a material from a cell (small-mass cut-off).
/// No test pins it.
inline constexpr double kTraceMass = 1e-200;
/// Fluid mass, as a share of the cell's fluid mass, below which advection drops a fluid from the
/// cell: there its specific values (ratios of round-off in the upwind tails) grow without bound
/// (water against air at 1.2 kg/m^3, 1600 cells: air at 1e-59 of the cell's mass with e < 0, at
/// 1e-82 with |u| 1e40 m/s). At 1e-20 even a gas trace in water at 1 bar takes 1e-17 of the cell's
/// volume, 3e-13 of the pressure (IceWaterAir.InterfaceAdvectionKeepsPressureUniform, 1e-10).
inline constexpr double kNegligibleMassFraction = 1e-20;
/// The largest share of its mass a donor cell may lose through all its faces in one advection
/// step (positivity cap on the outflow). No test pins it.
inline constexpr double kMaxOutflowFraction = 0.9;
/// Advected velocities below this [m/s] are set to zero: upwind tails ahead of waves decay
/// geometrically and would otherwise reach denormal numbers (two orders of magnitude slower).
/// No test pins it.
inline constexpr double kTinyVelocity = 1e-150;
/// Volume fraction above which a material counts as present: for the time step bounds (its speed
/// in the CFL bound, its viscosity in the viscous bound) and for the entropy-bounded face state
/// of second-order advection, which acts only between cells where the other materials together
/// are below it (single-fluid cells). The IceTimeStep tests use cells one fluid fills; with the
/// entropy bound acting in mixed cells as well, IceWaterAir.RealDensityRatioCompletesAndConverges
/// fails (400 cells: L1 5.759 > 5.75; docs/ice.md "Shocks", fix 3).
inline constexpr double kPresentFraction = 1e-6;
/// The largest relative volume change |dt (kappa_r / kbar) div U| of a material in one
/// Lagrangian step (cap; capped cells are counted as fallbacks). No test pins it.
inline constexpr double kMaxVolumeChange = 0.5;
/// An energy update that would leave less than this share of a cell's thermal energy e - e_cold
/// (cv T, eos.h) is not taken (advection falls back to the directly advected internal energy, the
/// Lagrangian energy fix keeps e_L). Measured from e_cold, not from e = 0: a Mie-Gruneisen liquid
/// with a reference temperature has e = 0 at T0 (slides_underwater_foam_water). No test pins the value.
inline constexpr double kMinEnergyShare = 0.1;
/// The share of its specific thermal energy (e - e_cold at the donor's density) and specific
/// volume that the part of a donor cell's fluid staying in the cell keeps at least after the
/// outflow through all its faces (advection_phase.cpp, the positivity blend: the outgoing face
/// values are blended toward the donor's own where the limited ones would take more). No test
/// pins the value (any share in (0, 1) keeps e and v positive by construction).
inline constexpr double kMinRemainderShare = 0.1;

/// Fluid regions' sub-cell fill (initial_regions.h cellShares): sample points per direction in a
/// cell whose corners and centre are not all filled from one region (8: 64 in 2D, 512 in 3D); a
/// region's face between two cell centres then holds its volume to 1/16 of a cell.
/// Pinned by: tests/unit/ice/test_initial_fill.cpp.
inline constexpr int kFillSamples = 8;

}  // namespace mpmice::ice
