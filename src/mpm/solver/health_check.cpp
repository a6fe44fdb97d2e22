#include "mpm/solver/health_check.h"

#include <cmath>
#include <sstream>

#include "core/health/health.h"

namespace mpmice::mpm {

std::string findViolation(const MpmSolver& s) {
  const ParticleSet& p = s.particles();
  const int dim = s.scene().mesh.dim();
  const auto& mats = s.scene().materials;
  const std::size_t nm = mats.size();
  for (std::size_t m = 0; m < nm; ++m) {
    const auto [b, e] = p.materialRange(static_cast<int>(m));
    if (b == e) continue;
    const ConstitutiveModel& model = s.model(static_cast<int>(m));
    for (std::size_t i = b; i < e; ++i) {
      const char* q = nullptr;
      const char* expected = "finite";
      double v = 0;
      for (int d = 0; d < dim && !q; ++d) {
        if (!std::isfinite(p.x[d][i])) q = "position [m]", v = p.x[d][i];
        else if (!std::isfinite(p.v[d][i])) q = "velocity [m/s]", v = p.v[d][i];
      }
      for (int c = 0; c < 6 && !q; ++c)
        if (!std::isfinite(p.stress[c][i])) q = "stress [Pa]", v = p.stress[c][i];
      if (!q && !(p.mass[i] > 0 && std::isfinite(p.mass[i]))) q = "mass [kg]", v = p.mass[i], expected = "finite, > 0";
      if (!q && !(p.vol[i] > 0 && std::isfinite(p.vol[i])))
        q = "volume [m^3]", v = p.vol[i], expected = "finite, > 0";
      if (!q && !(p.temperature[i] > 0 && p.temperature[i] <= core::kMaxTemperature))
        q = "temperature [K]", v = p.temperature[i], expected = "in (0, 1e9]";
      if (!q) {
        const double c = model.waveSpeed(p.mass[i] / p.vol[i]);
        if (!(c > 0 && c < core::kMaxSoundSpeed))
          q = "wave speed [m/s]", v = c, expected = "in (0, speed of light)";
      }
      if (!q) continue;
      double x[3];
      for (int d = 0; d < 3; ++d) x[d] = p.x[d][i];
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
