#include "mpm/particles/particle_set.h"

#include <algorithm>
#include <numeric>

namespace mpmice::mpm {

std::vector<ParticleSet::ColumnInfo> ParticleSet::allColumns() {
  const ParticleLayout& lay = layout_;
  const bool planar = lay.dim < 3;
  std::vector<ColumnInfo> c;
  c.reserve(51);
  for (auto* a : {&x, &v, &halfSize})
    for (auto& col : *a) c.push_back({&col, 0.0, true});
  for (auto& col : fext) c.push_back({&col, 0.0, lay.loads});
  for (auto& col : x0) c.push_back({&col, 0.0, true});
  for (auto& col : fsurf) c.push_back({&col, 0.0, lay.surface});
  for (auto* s : {&mass, &vol0, &vol, &temperature}) c.push_back({s, 0.0, true});
  c.push_back({&eqps, 0.0, lay.plastic});
  c.push_back({&failed, 0.0, lay.plastic});
  c.push_back({&work, 0.0, true});
  c.push_back({&loadArea, 0.0, lay.loads});
  c.push_back({&surface, 0.0, lay.surface});
  // In 1D / 2D the components with a z index are exact zeros (F_zz the exact 1) and not stored.
  for (int k = 0; k < 9; ++k) {
    const bool outOfPlane = k == 2 || k >= 5;
    c.push_back({&F[k], k == 8 ? 1.0 : 0.0, !(planar && outOfPlane)});
  }
  for (int k = 0; k < 9; ++k) c.push_back({&L[k], 0.0, !(planar && (k == 2 || k >= 5))});
  for (int k = 0; k < 6; ++k) c.push_back({&stress[k], 0.0, !(planar && (k == kYZ || k == kXZ))});
  return c;
}

std::vector<ParticleSet::Col*> ParticleSet::columns() {
  std::vector<Col*> c;
  for (const ColumnInfo& k : allColumns())
    if (k.stored) c.push_back(k.col);
  return c;
}

std::vector<const ParticleSet::Col*> ParticleSet::columns() const {
  auto c = const_cast<ParticleSet*>(this)->columns();
  return {c.begin(), c.end()};
}

void ParticleSet::setLayout(const ParticleLayout& layout) {
  const std::size_t n = size();
  layout_ = layout;
  for (const ColumnInfo& k : allColumns())
    if (k.stored)
      k.col->resize(n, k.value);  // a column stored from now on holds its constant
    else
      Col().swap(*k.col);
  if (layout_.loads)
    load.resize(n, -1);
  else
    std::vector<std::int32_t>().swap(load);
}

const ParticleSet::Col& ParticleSet::column(const Col& c) const {
  if (stored(c)) return c;
  const bool one = &c == &F[8];
  Col& k = one ? ones_ : zeros_;
  k.assign(size(), one ? 1.0 : 0.0);
  return k;
}

void ParticleSet::resize(std::size_t n) {
  for (Col* c : columns()) c->resize(n, 0.0);
  material.resize(n, 0);
  if (layout_.loads) load.resize(n, -1);
  id.resize(n, 0);
}

void ParticleSet::reserve(std::size_t n) {
  for (Col* c : columns()) c->reserve(n);
  material.reserve(n);
  if (layout_.loads) load.reserve(n);
  id.reserve(n);
}

std::size_t ParticleSet::addParticle(const std::array<double, 3>& pos,
                                     const std::array<double, 3>& vel, double m, double volume,
                                     const std::array<double, 3>& half, int mat, double temp,
                                     std::int64_t gid) {
  const std::size_t i = size();
  resize(i + 1);
  for (int d = 0; d < 3; ++d) {
    x[d][i] = pos[d];
    x0[d][i] = pos[d];
    v[d][i] = vel[d];
    halfSize[d][i] = half[d];
  }
  mass[i] = m;
  vol0[i] = volume;
  vol[i] = volume;
  temperature[i] = temp;
  F[0][i] = F[4][i] = 1.0;
  if (stored(F[8])) F[8][i] = 1.0;
  material[i] = mat;
  id[i] = gid;
  return i;
}

void ParticleSet::permute(const std::vector<std::uint32_t>& perm, std::vector<double>& scratch) {
  const std::size_t n = size();
  scratch.resize(n);
  for (Col* c : columns()) {
    for (std::size_t i = 0; i < n; ++i) scratch[i] = (*c)[perm[i]];
    std::copy(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(n), c->begin());
  }
  auto permInt = [&](auto& col) {
    auto tmp = col;  // integer columns: small, only on re-sorts
    for (std::size_t i = 0; i < n; ++i) col[i] = tmp[perm[i]];
  };
  permInt(material);
  if (layout_.loads) permInt(load);
  permInt(id);
}

void ParticleSet::compact(const std::vector<char>& keep) {
  const std::size_t n = size();
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i]) continue;
    if (i != j) {
      for (Col* c : columns()) (*c)[j] = (*c)[i];
      material[j] = material[i];
      if (layout_.loads) load[j] = load[i];
      id[j] = id[i];
    }
    ++j;
  }
  resize(j);
}

std::size_t ParticleSet::packedSize() {
  ParticleSet p;
  return p.allColumns().size() + 3;
}

void ParticleSet::pack(std::size_t i, std::vector<double>& buf) const {
  for (const ColumnInfo& k : const_cast<ParticleSet*>(this)->allColumns()) buf.push_back(k.stored ? (*k.col)[i] : k.value);
  buf.push_back(material[i]);
  buf.push_back(layout_.loads ? load[i] : -1);
  buf.push_back(static_cast<double>(id[i]));  // exact below 2^53
}

std::size_t ParticleSet::unpack(const double* buf) {
  const std::size_t i = size();
  resize(i + 1);
  std::size_t k = 0;
  for (const ColumnInfo& c : allColumns()) {  // the value of a column not stored is its constant
    if (c.stored) (*c.col)[i] = buf[k];
    ++k;
  }
  material[i] = static_cast<std::int32_t>(buf[k++]);
  if (layout_.loads) load[i] = static_cast<std::int32_t>(buf[k]);
  ++k;
  id[i] = static_cast<std::int64_t>(buf[k++]);
  return k;
}

void ParticleSet::sortBy(const std::vector<std::uint64_t>& key, std::vector<std::uint32_t>& perm,
                         std::vector<double>& scratch) {
  const std::size_t n = size();
  perm.resize(n);
  std::iota(perm.begin(), perm.end(), 0u);
  std::stable_sort(perm.begin(), perm.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (material[a] != material[b]) return material[a] < material[b];
    if (key[a] != key[b]) return key[a] < key[b];
    return id[a] < id[b];
  });
  permute(perm, scratch);
}

void ParticleSet::updateMaterialRanges(int nmat) {
  // The particles are sorted by material (the precondition): each range ends at the first
  // particle of a later material, found by bisection rather than by a pass over the particles.
  ranges_.assign(static_cast<std::size_t>(nmat) + 1, 0);
  auto it = material.begin();
  for (int m = 0; m < nmat; ++m) {
    ranges_[m] = static_cast<std::size_t>(it - material.begin());
    if (it != material.end() && *it == m) it = std::upper_bound(it, material.end(), m);
  }
  ranges_[nmat] = static_cast<std::size_t>(it - material.begin());
}

bool ParticleSet::groupedByMaterial() const {
  // std::is_sorted without its early exit: the loop vectorizes (called every step).
  const std::int32_t* m = material.data();
  int unsorted = 0;
  for (std::size_t i = 1; i < material.size(); ++i) unsorted |= m[i] < m[i - 1];
  return unsorted == 0;
}

}  // namespace mpmice::mpm
