#pragma once
/// @brief The energy audit of ICE: what the non-conservative fallbacks of each step add.
///
/// Mass, momentum and total energy move between cells in flux form, so they are conserved to
/// round-off, except where a step falls back to a non-conservative update to keep the thermal
/// energy e - e_cold (cv T) positive: advection taking the directly advected internal energy instead of
/// E / m - |u|^2 / 2, and the Lagrangian energy correction not giving a material its share when
/// that would drain it (docs/ice.md "Health check"). Each fallback's energy change m |e_taken -
/// e_conservative| is added up here; the health check stops the run when the sum over the run
/// exceeds kMaxCreatedEnergyShare of the fluids' total energy (a run that created a sizeable part
/// of its energy out of nothing is not a solution, whatever its temperatures).
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::ice {

/// The largest share of the fluids' total energy the fallbacks may create over a run.
/// Sod and Toro 1-5 in every setting of the shock sweep stay below 4e-6, water against air below
/// 1e-3 where it completes; the first-order run that hid +14573 % created 9 % (docs/ice.md "Health check").
inline constexpr double kMaxCreatedEnergyShare = 1e-2;

struct EnergyAudit {
  // ---- this rank, this step
  double stepCreated = 0;  // sum of |energy change| of this step's fallbacks [J]
  double localEnergy = 0;  // the fluids' total energy after advection [J]
  // ---- this rank, over the run: the single largest fallback (cell: stored-box index)
  double worst = 0;
  std::int64_t worstCell = -1;
  int worstMaterial = -1;
  // ---- every rank, over the run (after endStep)
  double created = 0;  // sum of |energy change| of every fallback so far [J]
  double energy = 0;   // the fluids' total energy after the last step [J]

  /// A fallback in `cell` of `material` changed the energy by `de` [J].
  void add(double de, std::int64_t cell, int material) {
    const double a = std::abs(de);
    stepCreated += a;
    if (a > worst) worst = a, worstCell = cell, worstMaterial = material;
  }
  /// Sums this step over every rank (collective: one reduction of two values).
  void endStep(const core::Comm& comm) {
    std::vector<double> v = {stepCreated, localEnergy};
    comm.sumInPlace(v);
    created += v[0];
    energy = v[1];
    stepCreated = localEnergy = 0;
  }
  /// More energy created than kMaxCreatedEnergyShare of the total.
  [[nodiscard]] bool exceeded() const { return created > kMaxCreatedEnergyShare * std::abs(energy); }
};

}  // namespace mpmice::ice
