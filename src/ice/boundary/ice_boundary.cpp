#include "ice/boundary/ice_boundary.h"

namespace mpmice::ice {

using core::BoundaryType;

IceBoundary::IceBoundary(const std::array<core::BoundarySpec, 6>& spec, const core::Mesh& mesh,
                         const core::Box& owned, std::array<bool, 3> periodic, std::array<InflowState, 6> inflow)
    : spec_(spec), inflow_(inflow), owned_(owned), cellVolume_(mesh.cellVolume()), dim_(mesh.dim()) {
  const core::Box dom = mesh.cellBox();
  for (int s = 0; s < 6; ++s) {
    const int d = s / 2;
    touch_[s] = d < dim_ && !periodic[d] &&
                (s % 2 == 0 ? owned.lo[d] == dom.lo[d] : owned.hi[d] == dom.hi[d]);
  }
}

void IceBoundary::apply(core::Field& f, FieldKind kind, int material) const {
  const core::Box& st = f.box();
  const int ng = f.nghost();
  for (int s = 0; s < 6; ++s) {
    if (!touch_[s]) continue;
    const int d = s / 2;
    const bool low = s % 2 == 0;
    const BoundaryType t = spec_[s].type;
    const InflowState& in = inflow_[s];
    for (int g = 1; g <= ng; ++g) {
      core::Box layer = st;
      const int gi = low ? owned_.lo[d] - g : owned_.hi[d] + g;
      const int mi = low ? owned_.lo[d] + g - 1 : owned_.hi[d] - g + 1;  // mirror image
      const int ci = low ? owned_.lo[d] : owned_.hi[d];                  // nearest cell
      layer.lo[d] = layer.hi[d] = gi;
      for (int c = 0; c < f.ncomp(); ++c) {
        core::View v = f.view(c);
        auto src = [&](int i, int j, int k, int idx) -> double {
          int q[3] = {i, j, k};
          q[d] = idx;
          return v(q[0], q[1], q[2]);
        };
        core::forEach(layer, [&](int i, int j, int k) {
          double& out = v(i, j, k);
          switch (t) {
            case BoundaryType::Symmetry:
            case BoundaryType::SlipWall:
            case BoundaryType::NoSlipWall: {
              double val = src(i, j, k, mi);
              if (kind == FieldKind::Velocity && (c == d || t == BoundaryType::NoSlipWall)) val = -val;
              out = val;
              break;
            }
            case BoundaryType::Inflow: {
              const bool mine = material == in.material;
              switch (kind) {
                case FieldKind::Mass: out = mine ? in.rho * cellVolume_ : 0.0; break;
                case FieldKind::Velocity: out = in.velocity[c]; break;
                case FieldKind::Energy: out = mine ? in.e : src(i, j, k, ci); break;
                case FieldKind::SpecificVolume: out = mine ? 1.0 / in.rho : src(i, j, k, ci); break;
                case FieldKind::VolumeFraction: out = mine ? 1.0 : 0.0; break;
                case FieldKind::Pressure: out = in.fixedPressure ? in.p : src(i, j, k, ci); break;
                case FieldKind::Increment: out = in.fixedPressure ? 0.0 : src(i, j, k, mi); break;
                case FieldKind::Scalar: out = src(i, j, k, ci); break;
              }
              break;
            }
            default: {  // outflow, free: zero gradient, optionally fixed pressure
              const bool fixedP = spec_[s].pressure.has_value();
              if (kind == FieldKind::Pressure && fixedP) out = *spec_[s].pressure;
              else if (kind == FieldKind::Increment) out = fixedP ? 0.0 : src(i, j, k, mi);
              else out = src(i, j, k, ci);
            }
          }
        });
      }
    }
  }
}

}  // namespace mpmice::ice
