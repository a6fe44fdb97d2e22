#include "ice/state/ice_state.h"

namespace mpmice::ice {

void IceState::allocate(const core::Box& owned, const core::Box& stored, int dim, bool semiImplicit,
                        bool keepIterations) {
  using core::Centering;
  using core::Field;
  auto cell = [&](const std::string& n, int nc, double init = 0.0) {
    return Field(n, Centering::Cell, stored, nc, kGhost, init);
  };
  // The Lagrangian specific volume apart from kappa only where the exchange's trace rule reads
  // both (external materials; MaterialState::lagSpvol).
  bool anyExternal = false;
  for (const auto& m : mat) anyExternal = anyExternal || m.external;
  for (auto& m : mat) {
    m.mass = cell(m.name + "/mass", 1);
    m.vel = cell(m.name + "/velocity", dim);
    m.eint = cell(m.name + "/internal_energy", 1);
    m.spvol = cell(m.name + "/specific_volume", 1, 1.0);
    m.theta = cell(m.name + "/volume_fraction", 1);
    m.kappa = cell(m.name + "/compressibility", 1);
    m.velL = m.external ? cell(m.name + "/velocity_L", dim) : Field();
    m.eintL = m.external ? cell(m.name + "/internal_energy_L", 1) : Field();
    m.spvolL = anyExternal ? cell(m.name + "/specific_volume_L", 1, 1.0) : Field();
    // Faces only in the mesh's directions; the exchange increments only where another
    // participant reads them (external materials): empty fields otherwise.
    for (int d = 0; d < 3; ++d)
      m.velFace[d] = d < dim ? Field(m.name + "/face_velocity", Centering::Cell, owned.faces(d), 1, 0) : Field();
    m.dMom = m.external ? Field(m.name + "/exchange_momentum", Centering::Cell, owned, 3, 0) : Field();
    m.dEnergy = m.external ? Field(m.name + "/exchange_energy", Centering::Cell, owned, 1, 0) : Field();
    m.couplingWork = m.external ? Field(m.name + "/coupling_work", Centering::Cell, owned, 1, 0) : Field();
    m.volumeChange = m.external ? Field(m.name + "/volume_change", Centering::Cell, owned, 1, 0) : Field();
  }
  press = cell("pressure", 1);
  dp = semiImplicit ? cell("pressure_increment", 1) : Field();
  iters.assign(keepIterations ? static_cast<std::size_t>(stored.numPts()) : 0, 0);
  for (int d = 0; d < dim; ++d) {
    pressFace[d] = Field("face_pressure", Centering::Cell, owned.faces(d), 1, 0);
    volFlux[d] = Field("face_volume_flux", Centering::Cell, owned.faces(d), 1, 0);
  }
}

}  // namespace mpmice::ice
