// IceSolver phase 10, last part (coupled runs): the temperature of a fluid dispersed in a solid
// follows the solid's. In a cell the solid fills, the fluid is a trace (volume fraction ~1e-10, or
// the little gas advection leaves behind a moving surface): its heat capacity is negligible and its
// Lagrangian phase is not physical. It takes the share kappa_f / kbar of the cell's volume change
// (up to 1 / theta_f), capped at +-50 % a step, doing p dV work at the cell pressure, and the next
// equilibrium pressure gives it its volume back without work: a ratchet that pumps it to 1e9 K in a
// few hundred steps wherever the solid moves or rings (the piston's copper, the cylinder's wall at
// K = 0; docs/verification-coupled.md "The piston"). A fluid that is a real phase of the cell (a
// mixed cell at the surface) must keep its own adiabat. What separates the two is the share of the
// cell's compliance each carries: the solids carry w = sum_s theta_s kappa_s / kbar (the fraction
// of a volume change of the cell the solids take). Where w ~ 1 the cell's mechanics are the solid's
// and the fluid is embedded in it; where w ~ 0 the fluid is the cell's compliance. The crossover is
// at theta_f ~ kappa_s / kappa_f (p / K_s, 1e-6 for air against copper), so a gas fraction of 1e-3
// keeps its own temperature to 1e-3 and a trace of 1e-10 follows the solid's to 1e-4. A fluid
// stiffer than the solids beside it (water against soft rubber, kappa_f ~ 1e-3 kappa_s) is not
// pumped: it takes less than its volume's share of a volume change; yet there w ~ 1 wherever the
// rubber is (it is the cell's compliance): the water followed the rubber's temperature changes with
// w alone and the added-mass period went from -0.10 % to +0.74 %. So w is weighted by how far the
// fluid is pumped: the fraction g = 1 - 1 / A of its volume change that exceeds the mean (0 where
// A <= 1), A its amplification, the larger of kappa_f / kbar (its relative volume change over the
// cell's, by the theta-kappa split of the Lagrangian phase) and kappa_f / kappa_fluids (the
// fluids' volume-mean compressibility: the split of the fluids' fill of a solid's own volume change,
// Dv in lagrangian_phase.cpp, which goes by theta kappa among the fluids alone). A gas trace in a
// metal: A ~ 1e6, g ~ 1. Water beside the added-mass rubber: A = 1 (the only fluid; 1e-3 against
// the rubber), g = 0. Detonation products as a trace (theta 1.3e-5, kappa 5e-9 .. 1.7e-8 1/Pa) in a
// crushable foam's cell (kappa 6e-9 .. 1.7e-8) with water (3e-10; the strengthless foam's cell
// (34,0), 294-348 us): A 18-49 by the fluids' fill, g 0.94-0.98. Before 7 Dec 2026 the weight was
// kappa_f / (kappa_f + kappa_s), against the solids only: 0.45-0.50 there, and the fill's work (Dv)
// cooled that trace below 0 K in every foam model but the water-filled one (docs/slides.md "Runs to
// 1 ms"; each now runs to 1 ms). So each fluid's temperature change
// in this step becomes the fraction w g of the solids' change (their heat-capacity-weighted one,
// from the start of the step to now) plus (1 - w g) of its own: a trace follows the solids'
// adiabat, a real phase keeps its own.
// The fluid's own change is measured over its whole cycle, from the temperature the step found
// (after the last step's advection, before this step's equilibrium pressure: tempCycle, kept by
// computeEquilibriumPressure), not from the equilibrium's volume: for a fluid with a cold energy
// (a stiffened gas's p_inf / rho, water's and the products' cold curves) the equilibrium's volume
// change at fixed energy moves its temperature by the cold energy's change, which the Lagrangian
// volume change then takes back with work, so half the cycle showed a large temperature change the
// whole cycle does not have. In the layered column (ten polymer layers in silicone,
// tests/verification/coupled/layered_column.yaml with ICE's face transport) the silicone of the
// mixed cells cooled in every Lagrangian phase and warmed in every equilibrium; measured over the
// half, the rule paid it 55,700 J of the polymer's heat in 20 us against 273 J of kinetic energy
// (the filled lattices' drain, docs/slides.md), over the whole cycle -290 J. An ideal gas's
// temperature does not depend on its volume: its measure is unchanged.
// The change, not the temperature: without heat exchange (ice.exchange.heat 0) a trace keeps its
// offset from the solid's temperature, and drag heat shared at one temperature rise stays one
// temperature rise (IceExchange.DragHeatIsSharedAtOneTemperatureRiseNotGivenToATrace). The heat
// comes from the solids in proportion to their heat capacities (for a trace, ~1e-13 of theirs), so
// energy is conserved, and the solids' part goes to their solver with the exchange increments
// (dEnergy).
#include <algorithm>
#include <cmath>

#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

using core::forEach;

void IceSolver::relaxEmbeddedFluidTemperatures() {
  if (!anyExternal_) return;
  const core::Box& sb = st_.press.box();
  forEach(owned_, [&](int i, int j, int k) {
    const std::int64_t c = sb.index(i, j, k);
    double kbar = 0, ks = 0, Cs = 0, CsdTs = 0, kf = 0, thetaF = 0;
    for (const MaterialState& m : st_.mat) {
      const double tk = m.theta.data()[c] * m.kappa.data()[c];
      kbar += tk;
      if (!m.external && m.mass.data()[c] > 0) kf += tk, thetaF += m.theta.data()[c];
      if (!m.external || !(m.mass.data()[c] > 0)) continue;
      ks += tk;
      const double C = m.mass.data()[c] * m.eos->cv();
      Cs += C;
      CsdTs += C * (m.eos->temperature(1.0 / m.lagSpvol().data()[c], m.eintL.data()[c]) -
                    m.eos->temperature(1.0 / m.spvol.data()[c], m.eint.data()[c]));
    }
    // A cavitated liquid (kbar = inf) takes the cell's whole volume change: the solids carry none.
    if (!(Cs > 0) || !(kbar > 0) || std::isinf(kbar)) return;
    const double w = ks / kbar, dTs = CsdTs / Cs, kappaF = thetaF > 0 ? kf / thetaF : 0.0;
    double Q = 0;  // heat [J] the fluids take from the solids
    for (MaterialState& m : st_.mat) {
      const double mass = m.mass.data()[c];
      if (m.external || !(mass > 0)) continue;
      double& e = m.eint.data()[c];  // a fluid's Lagrangian energy (its start-of-step one: eintStart)
      const double T0 = m.tempCycle.npts() > 0 && std::isfinite(m.tempCycle.data()[c])
                            ? m.tempCycle.data()[c]
                            : m.eos->temperature(1.0 / m.spvol.data()[c], m.eintStart.data()[c]);
      const double dTown = m.eos->temperature(1.0 / m.lagSpvol().data()[c], e) - T0;
      // How far it is pumped (above): a fluid no more compressible than its cell and its fluids keeps its own.
      const double kr = m.kappa.data()[c];
      const double A = std::max(kr / kbar, kappaF > 0 ? kr / kappaF : 0.0);
      const double wf = A > 1 ? w * (1.0 - 1.0 / A) : 0.0;
      // Towards the heat-capacity-weighted mean change of the fluid and the solids, which the
      // solids pay: for a trace (Cf ~ 1e-13 Cs) the solids' change, as above; for a fluid with a
      // heat capacity like the solids' both meet between their own changes, so neither goes past
      // the other's (a soft solid's cell holds real water at wf ~ 0.5: moved to the solid's change,
      // expanding water took its heat from a PVC tube's corner particles to below 0 K).
      const double Cf = mass * m.eos->cv();
      const double de = wf * m.eos->cv() * Cs / (Cs + Cf) * (dTs - dTown);
      // A change that would leave the fluid less than kMinEnergyShare of its thermal energy
      // e - e_cold is not taken (the Lagrangian energy fix's guard): the rule moves temperature
      // changes, and a trace the ratchet above has already cooled towards 0 K would be taken below
      // it by a solid's small cooling (a buffer gas in a filled lattice's polymer, docs/slides.md).
      const double ec = m.eos->hasColdEnergy() ? m.eos->coldEnergy(1.0 / m.lagSpvol().data()[c]) : 0.0;
      if (e - ec > 0 && e + de - ec < kMinEnergyShare * (e - ec)) continue;
      e += de;
      Q += mass * de;
    }
    if (Q == 0.0) return;
    for (MaterialState& m : st_.mat) {
      const double mass = m.mass.data()[c];
      if (!m.external || !(mass > 0)) continue;
      const double share = -Q * mass * m.eos->cv() / Cs;  // [J]
      m.eintL.data()[c] += share / mass;
      m.dEnergy(i, j, k) += share;
    }
  });
}

}  // namespace mpmice::ice
