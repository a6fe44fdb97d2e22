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
// branches (the fast pass: one read of each column), and the range of the density.
bool particlesOk(const ParticleSet& p, std::size_t b, std::size_t e, int dim, double& rhoMin, double& rhoMax) {
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
  const double *m = p.mass.data(), *v = p.vol.data(), *T = p.temperature.data();
  for (std::size_t i = b; i < e; ++i) {
    ok &= (m[i] > 0) & std::isfinite(m[i]) & (v[i] > 0) & std::isfinite(v[i]) & (T[i] > 0) &
          (T[i] <= core::kMaxTemperature);
    const double rho = m[i] / v[i];
    rhoMin = std::min(rhoMin, rho);
    rhoMax = std::max(rhoMax, rho);
  }
  return ok;
}

// The wave speed c(rho) of every model is sqrt(M / rho) (monotone in rho): in range at the
// lightest and the densest particle of a material means in range at all of them.
inline bool waveSpeedOk(double c) { return c > 0 && c < core::kMaxSoundSpeed; }
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
    // Fast pass: all well, and the density range (for the wave speed at its two ends)?
    double rhoMin = std::numeric_limits<double>::infinity(), rhoMax = 0;
    const bool ok = particlesOk(p, b, e, dim, rhoMin, rhoMax);
    if (ok && waveSpeedOk(model.waveSpeed(rhoMin)) && waveSpeedOk(model.waveSpeed(rhoMax))) continue;
    // Something is wrong: find the first particle and name it.
    for (std::size_t i = b; i < e; ++i) {
      const char* q = nullptr;
      const char* expected = "finite";
      double v = 0;
      for (int d = 0; d < dim && !q; ++d) {
        if (!std::isfinite(p.x[d][i])) q = "position [m]", v = p.x[d][i];
        else if (!std::isfinite(p.v[d][i])) q = "velocity [m/s]", v = p.v[d][i];
      }
      for (int c = 0; c < 6 && !q; ++c)
        if (p.stored(p.stress[c]) && !std::isfinite(p.stress[c][i])) q = "stress [Pa]", v = p.stress[c][i];
      if (!q && !(p.mass[i] > 0 && std::isfinite(p.mass[i]))) q = "mass [kg]", v = p.mass[i], expected = "finite, > 0";
      if (!q && !(p.vol[i] > 0 && std::isfinite(p.vol[i])))
        q = "volume [m^3]", v = p.vol[i], expected = "finite, > 0";
      if (!q && !(p.temperature[i] > 0 && p.temperature[i] <= core::kMaxTemperature))
        q = "temperature [K]", v = p.temperature[i], expected = "in (0, 1e9]";
      if (!q) {
        const double c = model.waveSpeed(p.mass[i] / p.vol[i]);
        if (!waveSpeedOk(c)) q = "wave speed [m/s]", v = c, expected = "in (0, speed of light)";
      }
      if (!q) continue;
      double x[3];
      for (int d = 0; d < 3; ++d) x[d] = d < dim ? p.x[d][i] : 0.0;
      if (where)
        for (int d = 0; d < 3; ++d) where[d] = x[d];
      std::ostringstream os;
      os.precision(6);
      os << "mpm: non-physical state: " << q << " of solid '" << mats[m].name << "' = " << v << " (expected "
         << expected << ") at particle " << p.id[i] << ", x = " << core::formatPoint(x, dim) << " m, t = " << s.time()
         << " s (step " << s.stepCount() << ")";
      return os.str();
    }
  }
  return "";
}

void checkHealth(const MpmSolver& solver) { core::stopOnViolation(solver.comm(), findViolation(solver)); }

}  // namespace mpmice::mpm
