#include "mpm/solver/health_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/health/health.h"

namespace mpmice::mpm {

namespace {
// Every per-particle check but the wave speed over particles [b, e), column by column without
// branches (the fast pass: one read of each column), the range of the density and the sum of the
// stress work (the stored-energy check).
bool particlesOk(const ParticleSet& p, std::size_t b, std::size_t e, int dim, double& rhoMin, double& rhoMax,
                 double& workSum) {
  bool ok = true;
  auto finite = [&](const std::vector<double>& col) {
    const double* x = col.data();
    for (std::size_t i = b; i < e; ++i) ok &= std::isfinite(x[i]);
  };
  for (int d = 0; d < dim; ++d) {
    finite(p.x[d]);
    finite(p.v[d]);
  }
  for (int c = 0; c < 6; ++c)
    if (p.stored(p.stress[c])) finite(p.stress[c]);
  const double *m = p.mass.data(), *v = p.vol.data(), *T = p.temperature.data(), *w = p.work.data();
  double work = 0;
  for (std::size_t i = b; i < e; ++i) {
    ok &= (m[i] > 0) & std::isfinite(m[i]) & (v[i] > 0) & std::isfinite(v[i]) & (T[i] > 0) &
          (T[i] <= core::kMaxTemperature) & std::isfinite(w[i]);
    const double rho = m[i] / v[i];
    rhoMin = std::min(rhoMin, rho);
    rhoMax = std::max(rhoMax, rho);
    work += w[i];
  }
  workSum = work;
  return ok;
}

// The sums the stored-energy check compares a negative work with (a second pass, only then):
// the kinetic energy sum 1/2 m |v|^2 and the mass of particles [b, e).
struct EnergySums {
  double work = 0, kinetic = 0, mass = 0;
};
EnergySums energySums(const ParticleSet& p, std::size_t b, std::size_t e, int dim, double work) {
  EnergySums s;
  s.work = work;
  double twiceKinetic = 0;
  for (std::size_t i = b; i < e; ++i) {
    double v2 = 0;
    for (int d = 0; d < dim; ++d) v2 += p.v[d][i] * p.v[d][i];
    twiceKinetic += p.mass[i] * v2;
    s.mass += p.mass[i];
  }
  s.kinetic = 0.5 * twiceKinetic;
  return s;
}

// The stored-energy check of one material's particles on this rank. Their stress work (elastic
// energy stored + energy dissipated) is >= 0 for every model from a stress-free start; the books
// may take it below 0 by the time integration's error (it trades the work with the kinetic
// energy; mpm.stress_work grid books what the internal forces did on the nodes, which in a solid
// the exchange drives drifts from the stress's energy). Below minus (their kinetic energy + the
// elastic energy of a uniform strain kStrainFloor in all of them, 1/2 eps^2 sum m c^2) it is no
// error of a healthy step: an unstable step pumps kinetic energy into the nodes that the
// particle-grid transfers remove, and the stored energy runs away below 0 (docs/mpm.md "Health check").
constexpr double kStrainFloor = 1e-2;
inline bool storedEnergyOk(const EnergySums& s, double massTimesWaveSpeed2) {
  return s.work >= -(s.kinetic + 0.5 * kStrainFloor * kStrainFloor * massTimesWaveSpeed2);
}

// The wave speed c(rho) of every model is sqrt(M / rho) (monotone in rho): in range at the
// lightest and the densest particle of a material means in range at all of them.
inline bool waveSpeedOk(double c) { return c > 0 && c < core::kMaxSoundSpeed; }

// "... at particle <id>, x = (...) m, t = <t> s (step <n>)" of particle i; its position to `where`.
std::string particleAndTime(const MpmSolver& s, std::size_t i, double* where) {
  const ParticleSet& p = s.particles();
  const int dim = s.scene().mesh.dim();
  double x[3];
  for (int d = 0; d < 3; ++d) x[d] = d < dim ? p.x[d][i] : 0.0;
  if (where)
    for (int d = 0; d < 3; ++d) where[d] = x[d];
  std::ostringstream os;
  os.precision(6);
  os << " at particle " << p.id[i] << ", x = " << core::formatPoint(x, dim) << " m, t = " << s.time() << " s (step "
     << s.stepCount() << ")";
  return os.str();
}

// The first particle of [b, e) with a non-physical quantity, named ("" when there is none).
std::string firstBadParticle(const MpmSolver& s, const ConstitutiveModel& model, const std::string& name,
                             std::size_t b, std::size_t e, double* where) {
  const ParticleSet& p = s.particles();
  const int dim = s.scene().mesh.dim();
  for (std::size_t i = b; i < e; ++i) {
    const char* q = nullptr;
    std::string expected = "finite";
    double v = 0;
    for (int d = 0; d < dim && !q; ++d) {
      if (!std::isfinite(p.x[d][i])) q = "position [m]", v = p.x[d][i];
      else if (!std::isfinite(p.v[d][i])) q = "velocity [m/s]", v = p.v[d][i];
    }
    for (int c = 0; c < 6 && !q; ++c)
      if (p.stored(p.stress[c]) && !std::isfinite(p.stress[c][i])) q = "stress [Pa]", v = p.stress[c][i];
    if (!q && !std::isfinite(p.work[i])) q = "stress work [J]", v = p.work[i];
    if (!q && !(p.mass[i] > 0 && std::isfinite(p.mass[i]))) q = "mass [kg]", v = p.mass[i], expected = "finite, > 0";
    if (!q && !(p.vol[i] > 0 && std::isfinite(p.vol[i]))) {
      // V = V0 det F (the deformation update): J = det F is what went wrong
      std::ostringstream j;
      j.precision(6);
      j << "finite, > 0; J = det F = V / V0 = " << p.vol[i] / p.vol0[i];
      q = "volume [m^3]", v = p.vol[i], expected = j.str();
    }
    if (!q && !(p.temperature[i] > 0 && p.temperature[i] <= core::kMaxTemperature))
      q = "temperature [K]", v = p.temperature[i], expected = "in (0, 1e9]";
    if (!q) {
      const double c = model.waveSpeed(p.mass[i] / p.vol[i]);
      if (!waveSpeedOk(c)) q = "wave speed [m/s]", v = c, expected = "in (0, speed of light)";
    }
    if (!q) continue;
    std::ostringstream os;
    os.precision(6);
    os << "mpm: non-physical state: " << q << " of solid '" << name << "' = " << v << " (expected " << expected << ")"
       << particleAndTime(s, i, where);
    return os.str();
  }
  return "";
}
}  // namespace

std::string findViolation(const MpmSolver& s, double* where) {
  const ParticleSet& p = s.particles();
  const int dim = s.scene().mesh.dim();
  const auto& mats = s.scene().materials;
  const std::size_t nm = mats.size();
  for (std::size_t m = 0; m < nm; ++m) {
    const auto [b, e] = p.materialRange(static_cast<int>(m));
    if (b == e) continue;
    const ConstitutiveModel& model = s.model(static_cast<int>(m));
    // Fast pass: all well, the density range (for the wave speed at its two ends), the work sum.
    double rhoMin = std::numeric_limits<double>::infinity(), rhoMax = 0, work = 0;
    const bool ok = particlesOk(p, b, e, dim, rhoMin, rhoMax, work);
    if (!ok || !waveSpeedOk(model.waveSpeed(rhoMin)) || !waveSpeedOk(model.waveSpeed(rhoMax))) {
      std::string bad = firstBadParticle(s, model, mats[m].name, b, e, where);  // something is wrong: name it
      if (!bad.empty()) return bad;
      continue;
    }
    if (work >= 0) continue;
    const EnergySums sums = energySums(p, b, e, dim, work);
    // sum m c^2 (c^2 = M / rho falls with rho: at the lightest particle's density it bounds it from above).
    const double c = model.waveSpeed(rhoMin), mc2 = sums.mass * c * c;
    if (storedEnergyOk(sums, mc2)) continue;
    // Every particle is well, the material's stored energy is not: name the most negative.
    std::size_t bad = b;
    for (std::size_t i = b; i < e; ++i)
      if (p.work[i] < p.work[bad]) bad = i;
    std::ostringstream os;
    os.precision(6);
    os << "mpm: non-physical state: stored stress work [J] (elastic + dissipated) of solid '" << mats[m].name
       << "' = " << sums.work << " over its " << e - b << " particles here (expected >= 0; the time integration may "
       << "take it to minus their kinetic energy " << sums.kinetic << " J plus the elastic energy of a "
       << kStrainFloor << " strain " << 0.5 * kStrainFloor * kStrainFloor * mc2
       << " J, not beyond: an unstable step pumps energy the particle-grid transfers remove; lower time.cfl, "
       << "docs/mpm.md \"Health check\"); most negative " << p.work[bad] << " J (" << p.work[bad] / p.vol[bad]
       << " J/m^3)" << particleAndTime(s, bad, where);
    return os.str();
  }
  return "";
}

void checkHealth(const MpmSolver& solver) { core::stopOnViolation(solver.comm(), findViolation(solver)); }

}  // namespace mpmice::mpm
