#include "ice/pressure/equilibrium_pressure.h"

#include <cmath>
#include <limits>

namespace mpmice::ice {

EquilibriumPressure::EquilibriumPressure(std::vector<const Eos*> eos, double tolerance, int maxIterations)
    : eos_(std::move(eos)), tol_(tolerance), maxIt_(maxIterations) {}

std::vector<EquilibriumFailure> EquilibriumPressure::solve(const std::vector<std::int64_t>& cells,
                                                           const std::vector<const double*>& rho,
                                                           const std::vector<const double*>& e, double* p,
                                                           const std::vector<double*>& rhoMicro, double* iters) {
  const std::size_t nm = eos_.size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<EquilibriumFailure> failures;
  if (nm == 1) {  // one material fills the cell: theta = 1, p from the EOS directly
    for (const std::int64_t c : cells) {
      const double r = rho[0][c];
      double pc;
      eos_[0]->pressure(1, &r, &e[0][c], &pc);
      p[c] = pc;
      rhoMicro[0][c] = r;
      iters[c] = 0;
    }
    return failures;
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
      iters[c] = 0;
      for (std::size_t r = 0; r < nm; ++r) {
        double dd;
        if (r == o) rhoMicro[r][c] = rho[r][c];
        else eos_[r]->density(1, &p[c], &e[r][c], &rhoMicro[r][c], &dd);
      }
    } else {  // empty cells (no material yet) keep their pressure
      iters[c] = 0;
      for (std::size_t r = 0; r < nm; ++r) {
        double dd;
        eos_[r]->density(1, &p[c], &e[r][c], &rhoMicro[r][c], &dd);
      }
    }
  }
  std::size_t na = active_.size();
  lo_.assign(na, -inf);
  hi_.assign(na, inf);
  // Per active slot the bracket is kept in lo_/hi_, indexed by slot (compacted along with active_).
  for (int it = 0; na > 0; ++it) {
    pa_.resize(na);
    f_.assign(na, 1.0);
    df_.assign(na, 0.0);
    bad_.assign(na, 0);
    for (std::size_t a = 0; a < na; ++a) pa_[a] = p[active_[a]];
    for (std::size_t r = 0; r < nm; ++r) {
      ea_.resize(na);
      ra_.resize(na);
      da_.resize(na);
      const double* er = e[r];
      for (std::size_t a = 0; a < na; ++a) ea_[a] = er[active_[a]];
      eos_[r]->density(na, pa_.data(), ea_.data(), ra_.data(), da_.data());
      const double* rr = rho[r];
      double* rm = rhoMicro[r];
      for (std::size_t a = 0; a < na; ++a) {
        const double m = rr[active_[a]];
        rm[active_[a]] = ra_[a];
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
        iters[c] = it;
        continue;
      }
      if (f < 0) lo = pc; else hi = pc;
      double next = (!bad_[a] && df_[a] > 0) ? pc - f / df_[a] : std::numeric_limits<double>::quiet_NaN();
      if (!(next > lo && next < hi)) {
        if (std::isfinite(lo) && std::isfinite(hi))  // bisect; geometrically across decades
          next = lo > 0 && hi > 1e3 * lo ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
        else if (std::isfinite(lo)) next = lo + 2.0 * std::abs(lo) + 1.0;
        else next = hi - 2.0 * std::abs(hi) - 1.0;
      }
      const bool collapsed = std::isfinite(lo) && std::isfinite(hi) && hi - lo <= 4e-16 * std::max(std::abs(hi), std::abs(lo));
      if (collapsed && !bad_[a]) {  // the root is resolved to round-off
        iters[c] = it;
        continue;
      }
      if (it + 1 >= maxIt_) {
        failures.push_back({c, pc, lo, hi, bad_[a] ? inf : f, it + 1});
        iters[c] = it + 1;
        continue;
      }
      p[c] = next;
      active_[keep] = c;
      lo_[keep] = lo;
      hi_[keep] = hi;
      ++keep;
    }
    na = keep;
    active_.resize(na);
    lo_.resize(na);
    hi_.resize(na);
  }
  return failures;
}

}  // namespace mpmice::ice
