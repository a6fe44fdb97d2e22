#include "ice/face/solid_faces.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ice/ice_constants.h"

namespace mpmice::ice {

using core::forEach;

namespace {
constexpr double kCoverTolerance = 1e-9;  // relative, of the face cover comparisons
}  // namespace

void computeSolidFaces(IceState& st, const core::Mesh& mesh, const core::Box& owned, const IceBoundary& bc) {
  SolidFaces& sf = st.solidFaces;
  const int dim = mesh.dim();
  const core::Box domain = mesh.cellBox();
  const core::Box& sb = st.press.box();
  std::vector<double> coverAt, fluxAt;  // per face of fb and its neighbours in d
  for (int d = 0; d < dim; ++d) {
    const core::Box fb = owned.faces(d);
    if (sf.cover[d].npts() == 0) {
      sf.cover[d] = core::Field("solid_face_cover", core::Centering::Cell, fb, 1, 0);
      sf.flux[d] = core::Field("solid_face_flux", core::Centering::Cell, fb, 1, 0);
      sf.inside[d] = core::Field("solid_face_inside", core::Centering::Cell, fb, 1, 0);
    }
    // Cover and volume flux of the low face of stored cell (i, j, k) in d (on an open boundary
    // face the boundary cell's solid, 0 on the other boundary faces and beyond them). The external
    // materials with a face transport, as flat arrays over the stored box (every cell field of the
    // state is stored over it).
    struct Ext {
      const double *m, *v, *D, *F, *u;
    };
    std::vector<Ext> ext;
    for (const MaterialState& m : st.mat)
      if (m.external && m.faceDensity.npts() != 0)
        ext.push_back({m.mass.data(), m.spvol.data(), m.faceDensity.data(d), m.faceFlux.data(d), m.vel.data(d)});
    const bool openLo = core::isOpenBoundary(bc.type(2 * d)), openHi = core::isOpenBoundary(bc.type(2 * d + 1));
    const double V = mesh.cellVolume();
    const std::int64_t sd = d == 0 ? 1 : (d == 1 ? sb.length(0) : std::int64_t(sb.length(0)) * sb.length(1));
    auto faceValues = [&](int i, int j, int k, double& cover, double& flux) {
      cover = flux = 0;
      const int idx[3] = {i, j, k};
      const bool atLo = idx[d] == domain.lo[d] && openLo, atHi = idx[d] == domain.hi[d] + 1 && openHi;
      if (atLo || atHi) {  // the boundary cell's solid, continued beyond the face
        int in[3] = {i, j, k};
        if (atHi) in[d] -= 1;
        if (!sb.contains(in[0], in[1], in[2])) return;
        const std::int64_t c = sb.index(in[0], in[1], in[2]);
        for (const Ext& e : ext) {
          const double th = e.m[c] * e.v[c] / V;
          cover += th;
          flux += th * e.u[c];
        }
        cover = std::clamp(cover, 0.0, kMaxSolidFraction);
        return;
      }
      if (idx[d] <= domain.lo[d] || idx[d] > domain.hi[d]) return;
      int l[3] = {i, j, k};
      l[d] -= 1;
      if (!sb.contains(i, j, k) || !sb.contains(l[0], l[1], l[2])) return;
      const std::int64_t c = sb.index(i, j, k), cl = c - sd;
      for (const Ext& e : ext) {
        const double v = faceSpecificVolume(e.m[cl], e.v[cl], e.m[c], e.v[c]);
        cover += e.D[c] * v;
        flux += e.F[c] * v;
      }
      cover = std::clamp(cover, 0.0, kMaxSolidFraction);
    };
    // Each face's cover and flux once, over the faces and their neighbours in d (the inside test
    // reads the covers of the faces below and above).
    const core::Box fx = fb.growDir(d, 1);
    const std::int64_t step = d == 0 ? 1 : (d == 1 ? fx.length(0) : std::int64_t(fx.length(0)) * fx.length(1));
    coverAt.resize(static_cast<std::size_t>(fx.numPts()));
    fluxAt.resize(static_cast<std::size_t>(fx.numPts()));
    forEach(fx, [&](int i, int j, int k) {
      const auto n = static_cast<std::size_t>(fx.index(i, j, k));
      faceValues(i, j, k, coverAt[n], fluxAt[n]);
    });
    double *coverF = sf.cover[d].data(), *fluxF = sf.flux[d].data(), *insideF = sf.inside[d].data();
    forEach(fb, [&](int i, int j, int k) {
      const std::int64_t n = fx.index(i, j, k), f = fb.index(i, j, k);
      const double c = coverAt[static_cast<std::size_t>(n)];
      const double cLo = coverAt[static_cast<std::size_t>(n - step)];
      const double cHi = coverAt[static_cast<std::size_t>(n + step)];
      coverF[f] = c;
      fluxF[f] = fluxAt[static_cast<std::size_t>(n)];
      // A relative tolerance on the comparisons: a uniform solid's plateau, or the half-covered
      // face of a solid one cell thick, must not flip with the round-off of the sums (the order
      // of the particles' and the ranks' contributions).
      const double cUp = c * (1 + kCoverTolerance);
      insideF[f] =
          cUp >= 0.5 || (c > kPresentFraction && cUp >= cLo && cUp >= cHi) ? 1.0 : 0.0;
    });
  }
}

}  // namespace mpmice::ice
