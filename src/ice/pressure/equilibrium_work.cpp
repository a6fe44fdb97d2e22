// IceSolver::equilibrateWithWork: ice.equilibrium: with_work (docs/ice.md "Equilibrium with work").
//
// The fixed-energy equilibrium (EquilibriumPressure::solve) moves volume between the materials of
// a cell at their carried specific energies: a gas share compressed by a liquid's pressure gets no
// p dV work for it, and pays the work back when it expands again in the Lagrangian phase (the
// semi-implicit water-air stops, docs/ice.md). With work, every fluid r of a mixed cell that takes
// part (present, not a held trace, not cavitated) does the work of its volume change at the cell's
// equilibrium pressure p, measured from the volume it carried into the step:
//
//   e_r = e_r0 - p (v_r - s v_r0),   s = sum_P m v / sum_P m v0,
//
// an implicit (backward Euler) relaxation as in the pressure-relaxation step of Saurel, Petitpas &
// Berry (2009). s makes the participating fluids' volume change sum to 0, so sum_P m_r e_r is
// conserved to round-off (the cell's total energy is unchanged; what the fluids' total volume gains
// from a solid's compression, or a carried volume that did not fill the cell, is shared as a
// uniform dilation without work). A compression by p dissipates (it takes more than the isentropic
// work), an expansion at p gives back less: a material never gains negative energy from it.
//
// The consistent state is found per cell by Newton on each fluid's energy at the cell's last p,
//   g_r(e) = e_r0 - p (v_r(p, e) - s v_r0) - e,   g_r' = -(1 + p dv_r/de|_p),
// re-solving the equilibrium pressure of the still-changing cells after each update, then setting
// e_r = e_r0 - p (v_r - s v_r0) exactly (conservative) and solving once more (consistent).
#include <algorithm>
#include <cmath>
#include <limits>

#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

namespace {
constexpr int kMaxWorkIterations = 30;
constexpr double kWorkTolerance = 1e-12;  // |de| / (|e| + |p| v) per fluid
}  // namespace

std::vector<EquilibriumFailure> IceSolver::equilibrateWithWork(
    const std::vector<const double*>& rho, const std::vector<double*>& rhoMicro,
    const std::vector<std::vector<double>>& carried, std::vector<std::pair<int, std::int64_t>>& held,
    std::vector<std::pair<int, std::int64_t>>& cavitated) {
  const std::size_t nm = st_.mat.size();
  held = equil_->heldTraces();
  cavitated = equil_->cavitated();
  if (nm < 2) return {};
  // Per (material, stored cell): held or cavitated in the first solve (no work).
  const std::int64_t ns = st_.press.npts();
  std::vector<char> skip(nm * static_cast<std::size_t>(ns), 0), cavCell(static_cast<std::size_t>(ns), 0);
  for (const auto& [r, c] : held) skip[static_cast<std::size_t>(r) * ns + c] = 1;
  for (const auto& [r, c] : cavitated) cavCell[static_cast<std::size_t>(c)] = 1;
  // Candidate cells: two or more fluids take part, each with a carried volume, no cavity.
  struct Cell {
    std::int64_t c;
    std::size_t slot;  // index in ownedCells_ (carried)
  };
  std::vector<Cell> cells;
  ownedCells_.forEach([&](std::size_t a, std::int64_t c) {
    if (cavCell[static_cast<std::size_t>(c)]) return;
    int n = 0;
    bool ok = true;
    for (std::size_t r = 0; r < nm && ok; ++r) {
      if (st_.mat[r].external || !(rho[r][c] > 0) || skip[r * ns + c]) continue;
      const double v0 = carried[r][a];
      if (!(v0 > 0) || !std::isfinite(v0)) ok = false;
      ++n;
    }
    if (ok && n >= 2) cells.push_back({c, a});
  });
  if (cells.empty()) return {};
  std::vector<std::vector<double>> e0(nm, std::vector<double>(cells.size()));
  for (std::size_t r = 0; r < nm; ++r)
    for (std::size_t k = 0; k < cells.size(); ++k) e0[r][k] = st_.mat[r].eint.data()[cells[k].c];
  auto takesPart = [&](std::size_t r, std::int64_t c) {
    return !st_.mat[r].external && rho[r][c] > 0 && !skip[r * ns + c];
  };
  // The target energy of every participating fluid of cell k at the current (p, v): conservative.
  std::vector<double> target(nm);
  auto targets = [&](std::size_t k) {
    const std::int64_t c = cells[k].c;
    double vf = 0, vf0 = 0;
    for (std::size_t r = 0; r < nm; ++r) {
      if (!takesPart(r, c)) continue;
      vf += rho[r][c] / rhoMicro[r][c];
      vf0 += rho[r][c] * carried[r][cells[k].slot];
    }
    const double s = vf / vf0, p = st_.press.data()[c];
    for (std::size_t r = 0; r < nm; ++r)
      if (takesPart(r, c)) target[r] = e0[r][k] - p * (1.0 / rhoMicro[r][c] - s * carried[r][cells[k].slot]);
  };
  std::vector<std::int64_t> active;
  for (const Cell& cl : cells) active.push_back(cl.c);
  std::vector<std::size_t> activeSlot(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) activeSlot[k] = k;
  std::vector<EquilibriumFailure> failures;
  // The carried volumes by stored cell, for the trace rule of the solves below (candidate cells only).
  std::vector<std::vector<double>> vc(nm, std::vector<double>(static_cast<std::size_t>(ns), 0.0));
  std::vector<const double*> carriedNow, eNow;
  for (std::size_t r = 0; r < nm; ++r) {
    for (const Cell& cl : cells) vc[r][static_cast<std::size_t>(cl.c)] = carried[r][cl.slot];
    carriedNow.push_back(vc[r].data());
    eNow.push_back(st_.mat[r].eint.data());
  }
  auto resolve = [&](const std::vector<std::int64_t>& which) {
    auto found = equil_->solve(which, rho, eNow, st_.press.data(), rhoMicro, pressureIterationsOut(), &carriedNow);
    mostPressureIterations_ = std::max(mostPressureIterations_, equil_->lastMostIterations());
    return found;
  };
  for (int it = 0; it < kMaxWorkIterations && !active.empty(); ++it) {
    std::vector<std::int64_t> next;
    std::vector<std::size_t> nextSlot;
    for (std::size_t q = 0; q < active.size(); ++q) {
      const std::size_t k = activeSlot[q];
      const std::int64_t c = active[q];
      targets(k);
      const double p = st_.press.data()[c];
      bool moved = false;
      for (std::size_t r = 0; r < nm; ++r) {
        if (!takesPart(r, c)) continue;
        double& e = st_.mat[r].eint.data()[c];
        const double v = 1.0 / rhoMicro[r][c];
        const double g = target[r] - e;
        if (std::abs(g) <= kWorkTolerance * (std::abs(e) + std::abs(p) * v)) continue;
        // dv/de at fixed p, by a difference of the EOS's density.
        const double de = 1e-7 * std::max(std::abs(e), std::abs(p) * v);
        const double e1 = e + de;
        double r1 = 0, d1 = 0;
        st_.mat[r].eos->density(1, &p, &e1, &r1, &d1);
        const double gamma = r1 > 0 && std::isfinite(r1) ? p * (1.0 / r1 - v) / de : 0.0;
        double step = g / std::max(1.0 + gamma, 0.1);
        // Halve a step that would leave the material without an admissible state.
        for (int h = 0; h < 40; ++h) {
          const double en = e + step;
          double pf = 0;
          st_.mat[r].eos->pressureFloor(1, &en, &pf);
          if (pf < std::numeric_limits<double>::infinity() && pf < p) break;
          step *= 0.5;
        }
        e += step;
        moved = true;
      }
      if (moved) next.push_back(c), nextSlot.push_back(k);
    }
    active.swap(next);
    activeSlot.swap(nextSlot);
    if (active.empty()) break;
    failures = resolve(active);
    if (!failures.empty()) return failures;
  }
  // Conservative: the exact targets at the converged (p, v), then one consistent solve.
  std::vector<std::int64_t> all;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    targets(k);
    const std::int64_t c = cells[k].c;
    for (std::size_t r = 0; r < nm; ++r)
      if (takesPart(r, c)) st_.mat[r].eint.data()[c] = target[r];
    all.push_back(c);
  }
  failures = resolve(all);
  if (!failures.empty()) return failures;
  // The held traces and cavities: the first solve's outside the candidate cells, the last's inside.
  std::vector<char> isCand(static_cast<std::size_t>(ns), 0);
  for (const Cell& cl : cells) isCand[static_cast<std::size_t>(cl.c)] = 1;
  auto merge = [&](std::vector<std::pair<int, std::int64_t>>& first,
                   const std::vector<std::pair<int, std::int64_t>>& last) {
    std::erase_if(first, [&](const auto& rc) { return isCand[static_cast<std::size_t>(rc.second)] != 0; });
    first.insert(first.end(), last.begin(), last.end());
  };
  merge(held, equil_->heldTraces());
  merge(cavitated, equil_->cavitated());
  return {};
}

}  // namespace mpmice::ice
