#include "ice/pressure/equilibrium_pressure.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ice/state/lanes.h"

namespace mpmice::ice {

namespace {
// Scratch of at least n entries (only the first n are written and read): never shrunk, so the
// next block's first sweep does not zero it again.
template <class T>
void atLeast(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}
}  // namespace

EquilibriumPressure::EquilibriumPressure(std::vector<const Eos*> eos, double tolerance, int maxIterations,
                                         std::vector<bool> fluid, double traceMassFraction)
    : eos_(std::move(eos)), tol_(tolerance), maxIt_(maxIterations), fluid_(std::move(fluid)),
      traceY_(traceMassFraction) {
  fluid_.resize(eos_.size(), false);
  for (const Eos* law : eos_) pCav_.push_back(law->cavitationPressure());
}

template <class Fill>
std::vector<EquilibriumFailure> EquilibriumPressure::solveInBlocks(std::size_t n, Fill&& fill,
                                                                   const std::vector<const double*>& rho,
                                                                   const std::vector<const double*>& e, double* p,
                                                                   const std::vector<double*>& rhoMicro, int* iters,
                                                                   const std::vector<const double*>* carriedVolume) {
  held_.clear();
  cavitated_.clear();
  mostIt_ = 0;
  std::vector<EquilibriumFailure> failures;
  for (std::size_t b = 0; b < n; b += kBlock) {
    block_.resize(std::min(kBlock, n - b));
    fill(b, block_.size(), block_.data());
    solveBlock(block_, rho, e, p, rhoMicro, iters, carriedVolume, failures);
  }
  return failures;
}

std::vector<EquilibriumFailure> EquilibriumPressure::solve(const std::vector<std::int64_t>& cells,
                                                           const std::vector<const double*>& rho,
                                                           const std::vector<const double*>& e, double* p,
                                                           const std::vector<double*>& rhoMicro, int* iters,
                                                           const std::vector<const double*>* carriedVolume) {
  auto fill = [&](std::size_t first, std::size_t count, std::int64_t* out) {
    std::copy_n(cells.begin() + static_cast<std::ptrdiff_t>(first), count, out);
  };
  return solveInBlocks(cells.size(), fill, rho, e, p, rhoMicro, iters, carriedVolume);
}

std::vector<EquilibriumFailure> EquilibriumPressure::solve(const OwnedCells& cells,
                                                           const std::vector<const double*>& rho,
                                                           const std::vector<const double*>& e, double* p,
                                                           const std::vector<double*>& rhoMicro, int* iters,
                                                           const std::vector<const double*>* carriedVolume) {
  auto fill = [&](std::size_t first, std::size_t count, std::int64_t* out) { cells.fill(first, count, out); };
  return solveInBlocks(cells.size(), fill, rho, e, p, rhoMicro, iters, carriedVolume);
}

void EquilibriumPressure::solveBlock(const std::vector<std::int64_t>& cells, const std::vector<const double*>& rho,
                                     const std::vector<const double*>& e, double* p,
                                     const std::vector<double*>& rhoMicro, int* iters,
                                     const std::vector<const double*>* carriedVolume,
                                     std::vector<EquilibriumFailure>& failures) {
  const std::size_t nm = eos_.size();
  const double inf = std::numeric_limits<double>::infinity();
  // Cell c took `n` iterations (kept per cell where asked; the most of the solve always).
  auto count = [&](std::int64_t c, int n) {
    if (iters) iters[c] = n;
    mostIt_ = std::max(mostIt_, n);
  };
  // Records cell c (active slot a) as failed after `iterations`.
  auto fail = [&](EquilibriumFailure::Kind kind, std::size_t a, std::int64_t c, double pc, double lo, double hi,
                  double residual, int iterations) {
    EquilibriumFailure fl{c, pc, lo, hi, residual, iterations, kind, floorMat_[a], floor_[a]};
    failures.push_back(fl);
    count(c, iterations);
  };
  // An absent material's density at the cell's pressure p (its state if it arrives). Where its law
  // gives none with a finite positive density there (an ideal gas at p <= 0, as in water under
  // tension, a cavitated liquid's cut-off), it keeps the density it carries (1 otherwise): its
  // specific volume stays finite and positive. (An ideal gas's rho = p / ((gamma - 1) e) at p < 0
  // was taken as it came: a helium trace advected into such a water cell in a 2D blast kept the
  // negative specific volume as its Lagrangian value and stopped the run.)
  auto absentDensity = [&](std::size_t r, std::int64_t c, double pc) {
    const double vc = carriedVolume ? (*carriedVolume)[r][c] : 0.0;  // read before rhoMicro (aliased)
    double rr, dd;
    eos_[r]->density(1, &pc, &e[r][c], &rr, &dd);
    if (!(rr > 0.0) || !std::isfinite(rr)) rr = vc > 0 && std::isfinite(vc) ? 1.0 / vc : 1.0;
    rhoMicro[r][c] = rr;
  };
  if (nm == 1) {  // one material fills the cell: theta = 1, p from the EOS directly
    for (const std::int64_t c : cells) {
      const double r = rho[0][c];
      double pc;
      eos_[0]->pressure(1, &r, &e[0][c], &pc);
      if (pc < pCav_[0]) pc = pCav_[0], cavitated_.emplace_back(0, c);  // below the cut-off: a cavity
      p[c] = pc;
      rhoMicro[0][c] = r;
      count(c, 0);
    }
    return;
  }
  active_.clear();
  for (const std::int64_t c : cells) {
    int present = 0, only = -1;
    for (std::size_t r = 0; r < nm; ++r)
      if (rho[r][c] > 0) ++present, only = static_cast<int>(r);
    if (present > 1) {
      active_.push_back(c);
    } else if (present == 1) {  // one material fills the cell: p from its EOS, no iteration
      const auto o = static_cast<std::size_t>(only);
      eos_[o]->pressure(1, &rho[o][c], &e[o][c], &p[c]);
      if (p[c] < pCav_[o]) p[c] = pCav_[o], cavitated_.emplace_back(only, c);  // below the cut-off: a cavity
      count(c, 0);
      for (std::size_t r = 0; r < nm; ++r) {
        if (r == o) rhoMicro[r][c] = rho[r][c];
        else absentDensity(r, c, p[c]);
      }
    } else {  // empty cells (no material yet) keep their pressure
      count(c, 0);
      for (std::size_t r = 0; r < nm; ++r) absentDensity(r, c, p[c]);
    }
  }
  // The admissible interval's lower end per active cell: the largest floor of the present materials.
  std::size_t na = active_.size();
  floor_.assign(na, -inf);
  floorMat_.assign(na, -1);
  // The trace rule: a material below traceY_ of the cell's fluid mass (a fluid, or an external
  // one: a solid's smear at the edge of its particles' stencil), with an admissible carried state,
  // is held at its carried volume below its own pressure p_own (pHold_), and its floor (below
  // p_own) does not bound the cell's interval.
  const bool traces = traceY_ > 0 && carriedVolume != nullptr && na > 0;
  // Whether some material of the block is held (pHold_ set for it): the reads of pHold_ below are
  // made only then (without it every p_own is -inf and no test on it passes).
  bool hold = false;
  if (traces) {
    // Each active cell's fluid mass, once (the same sum for every material below).
    fluidMass_.resize(na);
    for (std::size_t a = 0; a < na; ++a) {
      const std::int64_t c = active_[a];
      double mf = 0;
      for (std::size_t s = 0; s < nm; ++s)
        if (fluid_[s]) mf += rho[s][c];
      fluidMass_[a] = mf;
    }
    holdCand_.clear();
    for (std::size_t r = 0; r < nm; ++r) {
      const double* vc = (*carriedVolume)[r];
      for (std::size_t a = 0; a < na; ++a) {
        const std::int64_t c = active_[a];
        const double m = rho[r][c];
        if (!(m > 0)) continue;
        const double mf = fluidMass_[a];
        if (!(m < traceY_ * mf) || !(vc[c] > 0) || !std::isfinite(vc[c])) continue;
        const double rc = 1.0 / vc[c];
        double po, pf;
        eos_[r]->pressure(1, &rc, &e[r][c], &po);
        eos_[r]->pressureFloor(1, &e[r][c], &pf);
        if (std::isfinite(po) && po > pf) holdCand_.push_back({r, c, po, rc});  // an admissible carried state
      }
    }
    hold = !holdCand_.empty();
  }
  if (hold) {
    // Indexed by cell - c0_ (the block's cells span c0_ .. c0_ + n - 1).
    std::int64_t n = 0;
    c0_ = active_.front();
    for (const std::int64_t c : active_) c0_ = std::min(c0_, c);
    for (const std::int64_t c : active_) n = std::max(n, c - c0_ + 1);
    pHold_.resize(nm);
    rhoHold_.resize(nm);
    for (std::size_t r = 0; r < nm; ++r) {
      if (static_cast<std::int64_t>(pHold_[r].size()) < n) {
        pHold_[r].resize(static_cast<std::size_t>(n));
        rhoHold_[r].resize(static_cast<std::size_t>(n));
      }
      double* ph = pHold_[r].data();
      for (const std::int64_t c : active_) ph[c - c0_] = -inf;
    }
    for (const HoldCandidate& h : holdCand_) {
      pHold_[h.r][static_cast<std::size_t>(h.c - c0_)] = h.p;
      rhoHold_[h.r][static_cast<std::size_t>(h.c - c0_)] = h.rho;
    }
    all_ = active_;
  }
  for (std::size_t r = 0; r < nm; ++r) {
    atLeast(ea_, na);
    atLeast(pf_, na);
    for (std::size_t a = 0; a < na; ++a) ea_[a] = e[r][active_[a]];
    eos_[r]->pressureFloor(na, ea_.data(), pf_.data());
    const double* ph = hold ? pHold_[r].data() : nullptr;
    for (std::size_t a = 0; a < na; ++a) {
      if (ph && ph[active_[a] - c0_] > -inf) continue;  // a held trace is admissible at every pressure
      if (rho[r][active_[a]] > 0 && !(pf_[a] <= floor_[a])) floor_[a] = pf_[a], floorMat_[a] = static_cast<int>(r);
    }
  }
  // Cavitating liquids (not traces that may be held): their cut-off is their floor. Where one sets
  // the cell's floor F (at or above the others'), f(F) with the liquids at the cut-off decides:
  // f(F) >= 0 is a cavity at F (solved here), f(F) < 0 puts the root above F (iterated below).
  cavFloor_.assign(na, 0);
  bool anyCav = false;
  for (std::size_t r = 0; r < nm; ++r) anyCav = anyCav || pCav_[r] > -inf;
  if (anyCav) {
    const double* none = nullptr;
    for (std::size_t a = 0; a < na; ++a) {
      const std::int64_t c = active_[a];
      if (!(floor_[a] < inf)) continue;  // fails below
      double F = floor_[a];
      int cm = -1;
      for (std::size_t r = 0; r < nm; ++r) {
        const double* ph = hold ? pHold_[r].data() : none;
        // A cut-off equal to another material's floor (a solid_bulk solid's 0) is the cell's too.
        if (!(rho[r][c] > 0) || (ph && ph[c - c0_] > -inf) || !(pCav_[r] > -inf) || !(pCav_[r] >= F) ||
            (cm >= 0 && pCav_[r] == F))
          continue;
        F = pCav_[r];
        cm = static_cast<int>(r);
      }
      if (cm < 0) continue;
      // f(F): the cavitating liquids (cut-off == F) at their density there, the others at theirs.
      double vOther = 0, vCav = 0;
      bool ok = true;
      for (std::size_t r = 0; r < nm && ok; ++r) {
        const double m = rho[r][c];
        if (!(m > 0)) {  // absent: its density at F (the iteration below recomputes it if needed)
          absentDensity(r, c, F);
          continue;
        }
        double rr, dd;
        const double* ph = hold ? pHold_[r].data() : none;
        if (ph && F < ph[c - c0_]) {
          rr = rhoHold_[r][static_cast<std::size_t>(c - c0_)];
        } else {
          // Where F is the end of this material's range too (a solid_bulk solid has no state at
          // p <= 0, its density tends to ~rho0 (p / p_ref)^(p_ref / K) as p -> 0+; an ideal gas at
          // 0): its limit from above, never its law at its floor.
          double pf;
          eos_[r]->pressureFloor(1, &e[r][c], &pf);
          const double pe = pCav_[r] != F && !(F > pf) ? F + 1e-9 * std::max(std::abs(F), 1.0) : F;
          eos_[r]->density(1, &pe, &e[r][c], &rr, &dd);
        }
        rhoMicro[r][c] = rr;
        if (!(rr > 0) || !std::isfinite(rr)) ok = false;
        else if (pCav_[r] == F && !(ph && ph[c - c0_] > -inf)) vCav += m / rr;
        else vOther += m / rr;
      }
      floor_[a] = F;
      floorMat_[a] = cm;
      if (!ok) continue;  // a material without a state at F: the iteration names it
      if (1.0 - vOther - vCav >= 0) {  // a cavity at F: the liquids share the volume left
        const double free = 1.0 - vOther;
        for (std::size_t r = 0; r < nm; ++r) {
          const double m = rho[r][c];
          const double* ph = hold ? pHold_[r].data() : none;
          if (!(m > 0) || pCav_[r] != F || (ph && ph[c - c0_] > -inf)) continue;
          const double share = free * (m / rhoMicro[r][c]) / vCav;  // its volume fraction
          rhoMicro[r][c] = m / share;
          cavitated_.emplace_back(static_cast<int>(r), c);
        }
        p[c] = F;
        count(c, 0);
        floor_[a] = inf;  // done: taken out of the iteration below
        floorMat_[a] = -2;
      } else {
        cavFloor_[a] = 1;
      }
    }
  }
  {
    std::size_t keep = 0;
    for (std::size_t a = 0; a < na; ++a) {
      const std::int64_t c = active_[a];
      const double F = floor_[a];
      if (floorMat_[a] == -2) continue;  // cavitated above
      if (!(F < inf)) {  // some material has no admissible state at its energy
        fail(EquilibriumFailure::Kind::NoAdmissibleState, a, c, p[c], F, inf, inf, 0);
        continue;
      }
      if (!(p[c] > F) || !std::isfinite(p[c]))  // start inside the interval
        p[c] = std::isfinite(F) ? F + std::max(std::abs(F), 1.0) : (std::isfinite(p[c]) ? p[c] : 1.0);
      active_[keep] = c;
      floor_[keep] = F;
      floorMat_[keep] = floorMat_[a];
      cavFloor_[keep] = cavFloor_[a];
      ++keep;
    }
    na = keep;
    active_.resize(na);
    cavFloor_.resize(na);
  }
  lo_.assign(floor_.begin(), floor_.begin() + static_cast<std::ptrdiff_t>(na));
  hi_.assign(na, inf);
  down_.assign(na, 0);
  up_.assign(na, 0);
  // Per active slot the bracket is kept in lo_/hi_ (and the floor in floor_), indexed by slot
  // (compacted along with active_). Every iterate lies strictly inside (lo, hi).
  for (int it = 0; na > 0; ++it) {
    atLeast(pa_, na);
    atLeast(f_, na);
    atLeast(df_, na);
    atLeast(bad_, na);
    for (std::size_t a = 0; a < na; ++a) {
      pa_[a] = p[active_[a]];
      f_[a] = 1.0;
      df_[a] = 0.0;
      bad_[a] = 0;
    }
    for (std::size_t r = 0; r < nm; ++r) {
      atLeast(ea_, na);
      atLeast(ra_, na);
      atLeast(da_, na);
      const double* er = e[r];
      for (std::size_t a = 0; a < na; ++a) ea_[a] = er[active_[a]];
      eos_[r]->density(na, pa_.data(), ea_.data(), ra_.data(), da_.data());
      const double* ph = hold ? pHold_[r].data() : nullptr;
      const double* rh = hold ? rhoHold_[r].data() : nullptr;
      const double* rr = rho[r];
      double* rm = rhoMicro[r];
      std::size_t a = 0;
      if (!ph)  // four slots at once (the lanes, lanes.h): the loop's operations, selects for its branches
        for (; a + 4 <= na; a += 4) {
          using lanes::v4d, lanes::v4m, lanes::load, lanes::sel;
          const std::int64_t* c = active_.data() + a;
          const v4d m = {rr[c[0]], rr[c[1]], rr[c[2]], rr[c[3]]}, ra = load(ra_.data() + a);
          const v4m present = ~(m <= 0), ok = ra > 0;
          for (int l = 0; l < 4; ++l)
            if (present[l] || ok[l]) rm[c[l]] = ra[l];  // an absent one keeps a positive density (absentDensity)
          if (lanes::any(present & ~ok))
            for (int l = 0; l < 4; ++l)
              if (present[l] && !ok[l]) bad_[a + static_cast<std::size_t>(l)] = 1;
          const v4d inv = 1.0 / ra, f = load(f_.data() + a), df = load(df_.data() + a);
          lanes::store(f_.data() + a, sel(present & ok, f - m * inv, f));
          lanes::store(df_.data() + a, sel(present & ok, df + m * inv * inv * load(da_.data() + a), df));
        }
      for (; a < na; ++a) {
        if (ph && pa_[a] < ph[active_[a] - c0_]) ra_[a] = rh[active_[a] - c0_], da_[a] = 0.0;  // held
        const double m = rr[active_[a]];
        // An absent material where its law gives no positive density at this iterate (an ideal gas
        // at p < 0, water under tension around it) keeps the one it has (absentDensity's).
        if (m > 0 || ra_[a] > 0) rm[active_[a]] = ra_[a];
        if (m <= 0) continue;
        if (!(ra_[a] > 0)) {
          bad_[a] = 1;
          continue;
        }
        const double inv = 1.0 / ra_[a];
        f_[a] -= m * inv;
        df_[a] += m * inv * inv * da_[a];
      }
    }
    // The Newton steps pc - f / df, four at a time (read below only where taken).
    atLeast(next_, na);
    {
      std::size_t a = 0;
      for (; a + 4 <= na; a += 4)
        lanes::store(next_.data() + a,
                     lanes::load(pa_.data() + a) - lanes::load(f_.data() + a) / lanes::load(df_.data() + a));
      for (; a < na; ++a) next_[a] = pa_[a] - f_[a] / df_[a];
    }
    std::size_t keep = 0;
    for (std::size_t a = 0; a < na; ++a) {
      const std::int64_t c = active_[a];
      const double pc = pa_[a];
      double lo = lo_[a], hi = hi_[a];
      const double f = bad_[a] ? -inf : f_[a];
      // Converged: residual below the tolerance and the Newton update below 1e-13 p (or the
      // residual at round-off), so uniform states stay uniform to round-off.
      if (!bad_[a] && std::abs(f) <= tol_ &&
          (std::abs(f) <= 1e-15 || std::abs(f) <= 1e-13 * std::abs(pc) * df_[a])) {
        count(c, it);
        continue;
      }
      if (f < 0) lo = pc; else hi = pc;
      double next = (!bad_[a] && df_[a] > 0) ? next_[a] : std::numeric_limits<double>::quiet_NaN();  // pc - f / df
      const double F = floor_[a];
      unsigned char down = 0;  // a Newton step taken ends a run of steps towards the floor
      // A bracket seen from both sides that spans more than three decades above the floor is
      // bisected geometrically whatever Newton says: Newton in p from below a root where the
      // volumes depend on ln p (a solid_bulk trace) gains only a factor 1 + ln(root / p) a step.
      const bool wide = std::isfinite(F) && std::isfinite(hi) && lo > F && hi - F > 1e3 * (lo - F);
      // Below the root with nothing above it seen, Newton far from the root may gain only a factor
      // of the distance above the floor a step (2 for a gas trace filling the cell: f ~ 1 - B / p,
      // from a warm start at 1e-150 Pa left by a solid trace's root). After seven such steps (each
      // at least 1.5 x the distance: the root is more than 2^7 away; fewer leave Newton's path as
      // it was) the distance grows by 2^2, 2^4, 2^8, ... instead; the bracket found above is then
      // wide and bisected geometrically.
      unsigned char up = 0;
      if (!std::isfinite(hi) && std::isfinite(F) && f < 0 && pc > F) {
        const bool slow = !(next > lo) || next - F >= 1.5 * (pc - F);
        up = slow ? static_cast<unsigned char>(std::min<int>(up_[a] + 1, 17)) : 0;
        if (up >= 8) {
          const double grow = F + std::ldexp(pc - F, 1 << std::min<int>(up - 7, 9));
          if (std::isfinite(grow) && !(next > grow)) next = grow;
        }
      }
      if (wide || !(next > lo && next < hi)) {
        down = down_[a];
        if (std::isfinite(lo) && std::isfinite(hi)) {  // bisect; geometrically across decades above the floor
          const double base = std::isfinite(F) ? F : 0.0, a0 = lo - base, b0 = hi - base;
          if (std::isfinite(F) && lo == F && b0 > 0) {
            // Nothing below the root seen yet: step towards the floor by 2^-1, 2^-2, 2^-4, ... of the
            // distance (k-th consecutive step: 2^-(2^k)), so a root decades above the floor (a
            // solid_bulk trace's tension branch: p ~ 1e-190 Pa) is bracketed in about ten steps,
            // and the first step is the plain bisection.
            // A step that would pass the smallest normal distance above the floor (from 1e-176 Pa
            // a step of 2^-1024 lands on the floor itself) stops there instead: that
            // distance is the last probe, so a root between it and the step before is bracketed,
            // and f > 0 there is the failure below (no root above the floor in double range).
            double step = std::ldexp(b0, -(1 << std::min<int>(down, 10)));
            const double tiny = std::max(std::numeric_limits<double>::min(), std::nextafter(base, inf) - base);
            if (!(step >= tiny)) step = tiny;
            next = base + step;
            down = static_cast<unsigned char>(std::min<int>(down + 1, 11));
          } else {
            next = a0 > 0 && b0 > 1e3 * a0 ? base + std::sqrt(a0) * std::sqrt(b0) : 0.5 * (lo + hi);
          }
        } else if (std::isfinite(lo)) {
          next = lo + 2.0 * std::max(std::abs(lo), 1.0);
        } else {
          next = hi - 2.0 * std::abs(hi) - 1.0;
        }
      }
      // The bracket resolved to round-off, or no double strictly inside it (a root in the last
      // representable step above the floor).
      const bool collapsed = std::isfinite(lo) && std::isfinite(hi) &&
                             (hi - lo <= 4e-16 * std::max(std::abs(hi), std::abs(lo)) || !(next > lo && next < hi));
      // No iterate below the root seen yet (a cavitating floor F has f(F) < 0: the root is above it).
      const bool atFloor = std::isfinite(F) && lo == F && !cavFloor_[a];
      if (collapsed && atFloor) {  // f > 0 down to the floor: no admissible root
        fail(EquilibriumFailure::Kind::NoRootAboveFloor, a, c, pc, lo, hi, f, it + 1);
        continue;
      }
      if (collapsed && !bad_[a]) {  // the root is resolved to round-off
        count(c, it);
        continue;
      }
      if (it + 1 >= maxIt_) {
        fail(EquilibriumFailure::Kind::NotConverged, a, c, pc, lo, hi, bad_[a] ? inf : f, it + 1);
        continue;
      }
      p[c] = next;
      active_[keep] = c;
      lo_[keep] = lo;
      hi_[keep] = hi;
      down_[keep] = down;
      up_[keep] = up;
      floor_[keep] = F;
      floorMat_[keep] = floorMat_[a];
      cavFloor_[keep] = cavFloor_[a];
      ++keep;
    }
    na = keep;
    active_.resize(na);
    lo_.resize(na);
    hi_.resize(na);
    down_.resize(na);
    up_.resize(na);
    floor_.resize(na);
    floorMat_.resize(na);
    cavFloor_.resize(na);
  }
  if (hold)
    for (const std::int64_t c : all_)
      for (std::size_t r = 0; r < nm; ++r)
        if (p[c] < pHold_[r][static_cast<std::size_t>(c - c0_)]) held_.emplace_back(static_cast<int>(r), c);
}

}  // namespace mpmice::ice
