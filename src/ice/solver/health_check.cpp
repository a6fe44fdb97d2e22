#include "ice/solver/health_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/health/health.h"
#include "ice/ice_constants.h"

namespace mpmice::ice {

namespace {
std::string describe(const IceSolver& s, const std::string& quantity, const std::string& material, double value,
                     const std::string& expected, int i, int j, int k) {
  const core::Mesh& mesh = s.mesh();
  const double x[3] = {mesh.cellCenter(0, i), mesh.cellCenter(1, j), mesh.cellCenter(2, k)};
  std::ostringstream os;
  os.precision(6);
  os << "ice: non-physical state: " << quantity;
  if (!material.empty()) os << " of " << material;
  os << " = " << value << " (expected " << expected << ") in cell (" << i << "," << j << "," << k << ") at x = "
     << core::formatPoint(x, mesh.dim()) << " m, t = " << s.time() << " s (step " << s.steps() << ")";
  return os.str();
}
}  // namespace

namespace {
// The first violation in cell (i,j,k) of the stored box index c, "" when there is none (the
// quantity, material, cell and time; cellViolation adds the cell's contents and why).
std::string cellViolationOnly(const IceSolver& s, int i, int j, int k, std::int64_t c) {
  const IceState& st = s.state();
  const int dim = s.mesh().dim();
  auto bad = [&](const std::string& q, const std::string& mat, double v, const std::string& expected) {
    return describe(s, q, mat, v, expected, i, j, k);
  };
  if (!std::isfinite(st.press.data()[c])) return bad("pressure", "", st.press.data()[c], "finite");
  double sum = 0;
  for (const MaterialState& m : st.mat) {
    const double th = m.theta.data()[c];
    const std::string who = (m.external ? "external material '" : "fluid '") + m.name + "'";
    const int r = static_cast<int>(&m - st.mat.data());
    if (!std::isfinite(th) || th < -kFractionSumTolerance) return bad("volume fraction", who, th, "finite, >= 0");
    sum += th;
    if (m.external) continue;
    const double mass = m.mass.data()[c], e = m.eint.data()[c], v = m.spvol.data()[c];
    if (!std::isfinite(mass) || mass < 0) return bad("mass [kg]", who, mass, "finite, >= 0");
    for (int d = 0; d < dim; ++d)
      if (!std::isfinite(m.vel.data(d)[c]))
        return bad("velocity component " + std::to_string(d) + " [m/s]", who, m.vel.data(d)[c], "finite");
    if (!std::isfinite(e)) return bad("specific internal energy [J/kg]", who, e, "finite");
    if (!std::isfinite(v) || (mass > 0 && !(v > 0)))
      return bad("specific volume [m^3/kg]", who, v, "finite, > 0 where there is mass");
    // The sound speed where the fluid was present at the step's equilibrium (recorded there).
    for (const IceSolver::SoundSpeedViolation& b : s.soundSpeedViolations())
      if (b.material == r && b.cell == c)
        return bad("sound speed [m/s]", who, b.c2 > 0 ? std::sqrt(b.c2) : b.c2, "in (0, speed of light)");
    if (!(th > kPresentFraction) || !(mass > 0)) continue;  // ranges only where the fluid is present
    const double T = m.eos->temperature(1.0 / v, e);
    if (!(T > 0 && T <= core::kMaxTemperature)) return bad("temperature [K]", who, T, "in (0, 1e9]");
  }
  if (!(std::abs(sum - 1.0) <= kFractionSumTolerance)) {
    std::ostringstream exp;
    exp << "1 within " << kFractionSumTolerance;
    return bad("sum of the volume fractions", "all materials", sum, exp.str());
  }
  return "";
}

// The same checks as cellViolation over a row of n cells from stored index c0 (x fastest,
// contiguous), without strings or early exits (the fast pass). `sum`: scratch of n entries.
bool rowOk(const IceState& st, std::int64_t c0, int n, int dim, std::vector<double>& sum) {
  int ok = 1;  // an int, not a bool: the loops' and-reductions vectorise
  const double* p = st.press.data() + c0;
  for (int a = 0; a < n; ++a) ok &= std::isfinite(p[a]);
  sum.assign(static_cast<std::size_t>(n), 0.0);
  for (const MaterialState& m : st.mat) {
    const double* th = m.theta.data() + c0;
    for (int a = 0; a < n; ++a) {
      ok &= std::isfinite(th[a]) & (th[a] >= -kFractionSumTolerance);
      sum[static_cast<std::size_t>(a)] += th[a];
    }
    if (m.external) continue;
    const double *ms = m.mass.data() + c0, *en = m.eint.data() + c0, *sv = m.spvol.data() + c0;
    for (int d = 0; d < dim; ++d) {
      const double* u = m.vel.data(d) + c0;
      for (int a = 0; a < n; ++a) ok &= std::isfinite(u[a]);
    }
    const double cvTmax = m.eos->cv() * core::kMaxTemperature;
    // T = (e - e_cold(rho)) / cv. Only stiffened gas has a cold energy (eos.h): the others skip
    // its virtual call per cell.
    const bool cold = m.eos->hasColdEnergy();
    // Cold: the EOS has a cold energy (a virtual call per cell); without it (no call) the loop vectorises.
    auto cells = [&]<bool Cold>() {
      int good = 1;
      for (int a = 0; a < n; ++a) {
        const double mass = ms[a], e = en[a], v = sv[a];
        good &= std::isfinite(mass) & (mass >= 0) & std::isfinite(e) & std::isfinite(v) & (!(mass > 0) | (v > 0));
        double eT = e;
        if constexpr (Cold) eT = e - m.eos->coldEnergy(1.0 / v);
        const bool present = (th[a] > kPresentFraction) & (mass > 0);
        good &= (!present) | ((eT > 0) & (eT <= cvTmax));
      }
      ok &= good != 0;
    };
    if (cold) cells.template operator()<true>();
    else cells.template operator()<false>();
  }
  for (int a = 0; a < n; ++a) ok &= std::abs(sum[static_cast<std::size_t>(a)] - 1.0) <= kFractionSumTolerance;
  return ok != 0;
}
}  // namespace

namespace {
// The energy audit (energy_audit.h): the same totals on every rank; the rank that holds its
// largest fallback names that cell.
std::string auditViolation(const IceSolver& s) {
  const EnergyAudit& a = s.energyAudit();
  if (!a.exceeded() || a.worstCell < 0) return "";
  const core::Box& sb = s.state().press.box();
  const std::int64_t nx = sb.length(0), ny = sb.length(1), c = a.worstCell;
  const int i = static_cast<int>(c % nx) + sb.lo[0], j = static_cast<int>((c / nx) % ny) + sb.lo[1],
            k = static_cast<int>(c / (nx * ny)) + sb.lo[2];
  std::ostringstream exp;
  exp.precision(6);
  exp << "at most " << kMaxCreatedEnergyShare << " of the fluids' total energy " << a.energy
      << " J; the largest single fallback, " << a.worst << " J, was of fluid '"
      << s.state().mat[static_cast<std::size_t>(a.worstMaterial)].name << "'";
  return describe(s, "energy created by the non-conservative internal-energy fallbacks [J]", "", a.created,
                  exp.str(), i, j, k);
}
}  // namespace

namespace {
// "; the cell holds 'a' (theta .., density .. kg/m^3, |u| .. m/s), ..." over the materials present
// in stored cell c (density: the material's own, mass / (theta V)).
std::string cellContents(const IceSolver& s, std::int64_t c) {
  const IceState& st = s.state();
  const double V = s.mesh().cellVolume();
  std::ostringstream os;
  os.precision(4);
  bool first = true;
  for (const MaterialState& m : st.mat) {
    const double th = m.theta.data()[c], mass = m.mass.data()[c];
    if (!(th > kPresentFraction)) continue;
    double u2 = 0;
    for (int d = 0; d < m.vel.ncomp(); ++d) u2 += m.vel.data(d)[c] * m.vel.data(d)[c];
    os << (first ? "; the cell holds '" : ", '") << m.name << "' (theta " << th << ", density " << mass / (th * V)
       << " kg/m^3, |u| " << std::sqrt(u2) << " m/s)";
    first = false;
  }
  return os.str();
}
}  // namespace

std::string weakExchangeNote(const IceSolver& s, int i, int j, int k, int fluid, double dtJudge) {
  const IceState& st = s.state();
  const core::Box& ob = s.ownedBox();
  const core::Box& sb = st.press.box();
  const int dim = s.mesh().dim();
  const MaterialState& f = st.mat.at(static_cast<std::size_t>(fluid));
  if (f.external) return "";
  const std::int64_t c = sb.index(i, j, k);
  const double thf = f.theta.data()[c], mf = f.mass.data()[c];
  if (!(thf > 0) || !(mf > 0)) return "";
  const double rho = mf / (thf * s.mesh().cellVolume());
  // The solid with the largest volume fraction in the cell and its owned neighbours.
  int solid = -1, at[3] = {i, j, k};
  double ths = 0;
  const int lo[3] = {std::max(i - 1, ob.lo[0]), dim > 1 ? std::max(j - 1, ob.lo[1]) : j, dim > 2 ? std::max(k - 1, ob.lo[2]) : k};
  const int hi[3] = {std::min(i + 1, ob.hi[0]), dim > 1 ? std::min(j + 1, ob.hi[1]) : j, dim > 2 ? std::min(k + 1, ob.hi[2]) : k};
  for (int r = 0; r < static_cast<int>(st.mat.size()); ++r) {
    const MaterialState& m = st.mat[static_cast<std::size_t>(r)];
    if (!m.external) continue;
    for (int kk = lo[2]; kk <= hi[2]; ++kk)
      for (int jj = lo[1]; jj <= hi[1]; ++jj)
        for (int ii = lo[0]; ii <= hi[0]; ++ii) {
          const double th = m.theta.data()[sb.index(ii, jj, kk)];
          if (th > ths) ths = th, solid = r, at[0] = ii, at[1] = jj, at[2] = kk;
        }
  }
  if (solid < 0 || !(ths > kPresentFraction)) return "";
  const double K = s.momentumExchange(fluid, solid), dt = dtJudge < 0 ? s.dt() : dtJudge;
  const double share = dt * K * ths / rho;
  if (!(share < 1)) return "";  // the exchange holds the fluid to the solid within a step
  std::ostringstream os;
  os.precision(4);
  os << "; weak momentum exchange: '" << f.name << "' and '" << st.mat[static_cast<std::size_t>(solid)].name
     << "' (theta " << ths << " in cell (" << at[0] << "," << at[1] << "," << at[2] << ")) exchange momentum with K = " << K
     << " kg/(m^3 s) (ice.exchange.momentum, or ice.exchange.pairs for the pair), which removes dt K theta_s / rho = " << share
     << " of their velocity difference per step (dt " << dt << " s, rho " << rho
     << " kg/m^3): the solid does not hold the fluid, and a pressure difference across the solid drives the fluid "
        "through it (to the fluid the solid is a porous medium with slip velocity |grad p| / (K theta_s)); a K that "
        "removes many times the difference per step (the default 1e15) makes it a wall";
  return os.str();
}

namespace {
// The first violation in cell (i,j,k) of the stored box index c, "" when there is none.
std::string cellViolation(const IceSolver& s, int i, int j, int k, std::int64_t c) {
  const std::string bad = cellViolationOnly(s, i, j, k, c);
  if (bad.empty()) return bad;
  std::string note;
  for (int r = 0; r < static_cast<int>(s.state().mat.size()) && note.empty(); ++r)
    if (bad.find("'" + s.state().mat[static_cast<std::size_t>(r)].name + "'") != std::string::npos)
      note = weakExchangeNote(s, i, j, k, r);
  return bad + cellContents(s, c) + note;
}
}  // namespace

std::string findViolation(const IceSolver& s) {
  if (std::string bad = auditViolation(s); !bad.empty()) return bad;
  const IceState& st = s.state();
  const core::Box& sb = st.press.box();
  const int dim = s.mesh().dim();
  const core::Box& ob = s.ownedBox();
  bool ok = s.soundSpeedViolations().empty();
  std::vector<double> sum;
  for (int k = ob.lo[2]; k <= ob.hi[2]; ++k)
    for (int j = ob.lo[1]; j <= ob.hi[1]; ++j) ok &= rowOk(st, sb.index(ob.lo[0], j, k), ob.length(0), dim, sum);
  if (ok) return "";
  // Something is wrong: the first cell (x fastest) and its first violation.
  std::string found;
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    if (found.empty()) found = cellViolation(s, i, j, k, sb.index(i, j, k));
  });
  return found;
}

void checkHealth(const IceSolver& solver) { core::stopOnViolation(solver.comm(), findViolation(solver)); }

}  // namespace mpmice::ice
