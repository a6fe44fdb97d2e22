#pragma once
/// @brief The solids' face transport in ICE's volume balance (coupling.solid_transport mpm).
///
/// The node-to-cell average smears a solid over its surface cells, and as the solid moves that
/// average moves its volume between cells in a way ICE's face fluxes of the cell fractions do not
/// see (the upwinded fractions of two equal cells carry nothing across their face): the fluid in a
/// mixed cell was squeezed by a solid volume its fluxes never let out, with the fluid's stiffness
/// gamma p (docs/flap.md "Mixed cells"). With the face transport, MPM sends, per face, the face
/// density D_f and mass flux F_f of its smeared mass (NodeCellOperators::solidFaceTransport), whose
/// face differences are exactly the change of the cell masses ICE's equilibrium sees. Here:
///   cover   c_f = sum_s D_f,s v_f,s      the fraction of the face the solids cover (v: the solid's
///                                        face specific volume, its EOS's at the equilibrium pressure)
///   flux    Q_f = sum_s F_f,s v_f,s      the solids' volume flux through the face
///   inside  c_f >= 1/2, or a ridge of c along the face normal (a solid thinner than its smearing;
///           a plateau counts), both to a relative 1e-9, and c_f above kPresentFraction
/// ICE's face volume flux is then Q_f + (1 - c_f) times the fluids' own (each fluid's share of the
/// open part from its upwind fraction), the fluids' mass fluxes share the open part the same way,
/// and the momentum exchange at a face locks the fluids to a solid only inside it: outside, a
/// fluid moves relative to the solid under the pressure difference.
#include <cstdint>

#include "core/mesh/box.h"
#include "core/mesh/mesh.h"
#include "ice/boundary/ice_boundary.h"
#include "ice/state/ice_state.h"

namespace mpmice::ice {

/// Fills st.solidFaces (cover, flux, inside) on the faces of `owned` from every external
/// material's faceDensity / faceFlux (ghosts filled) and its mass and specific volume. On an open
/// boundary face (free, outflow) the solid continues beyond the mesh as ICE's zero-gradient ghosts
/// and MPM's images continue it: the face carries the boundary cell's solid, cover sum_s m_s v_s / V
/// and flux sum_s m_s v_s u_s,d / V (its volume fraction moving with its velocity). The other
/// boundary faces (walls, symmetry planes, inflow) carry no solid.
void computeSolidFaces(IceState& st, const core::Mesh& mesh, const core::Box& owned, const IceBoundary& bc);

/// At face `fi` (index in owned.faces(d)) with the face transport on: zeroes the face volume
/// fraction of every external material where the face is not inside a solid (the momentum
/// exchange at the face then leaves the fluids free of it). `theta` as faceMaterialValues fills it.
inline void openSolidFaceExchange(const IceState& st, int d, std::int64_t fi, double* theta) {
  if (!st.solidFaces.on || st.solidFaces.inside[d].data()[fi] > 0) return;
  for (std::size_t r = 0; r < st.mat.size(); ++r)
    if (st.mat[r].external) theta[r] = 0.0;
}

}  // namespace mpmice::ice
