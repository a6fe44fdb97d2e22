#include "ice/solver/health_check.h"

#include <cmath>
#include <sstream>

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

std::string findViolation(const IceSolver& s) {
  const IceState& st = s.state();
  const core::Box& owned = s.ownedBox();
  const core::Box& sb = st.press.box();
  const int dim = s.mesh().dim();
  std::string found;
  // One pass over the cells: the first violation (in x-fastest order) ends the search.
  core::forEach(owned, [&](int i, int j, int k) {
    if (!found.empty()) return;
    const std::int64_t c = sb.index(i, j, k);
    auto bad = [&](const std::string& q, const std::string& mat, double v, const std::string& expected) {
      found = describe(s, q, mat, v, expected, i, j, k);
    };
    if (!std::isfinite(st.press.data()[c])) return bad("pressure", "", st.press.data()[c], "finite");
    double sum = 0;
    for (const MaterialState& m : st.mat) {
      const double th = m.theta.data()[c];
      const std::string who = (m.external ? "external material '" : "fluid '") + m.name + "'";
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
      if (!(th > kPresentFraction) || !(mass > 0)) continue;  // ranges only where the fluid is present
      const double T = m.eos->temperature(1.0 / v, e);
      if (!(T > 0 && T <= core::kMaxTemperature))
        return bad("temperature [K]", who, T, "in (0, 1e9]");
      const double c2 = v / m.kappa.data()[c];
      if (!(c2 > 0 && std::sqrt(c2) < core::kMaxSoundSpeed))
        return bad("sound speed [m/s]", who, c2 > 0 ? std::sqrt(c2) : c2, "in (0, speed of light)");
    }
    if (!(std::abs(sum - 1.0) <= kFractionSumTolerance)) {
      std::ostringstream exp;
      exp << "1 within " << kFractionSumTolerance;
      return bad("sum of the volume fractions", "all materials", sum, exp.str());
    }
  });
  return found;
}

void checkHealth(const IceSolver& solver) { core::stopOnViolation(solver.comm(), findViolation(solver)); }

}  // namespace mpmice::ice
