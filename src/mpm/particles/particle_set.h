#pragma once
/// @brief The material points of one rank, stored as structure of arrays.
///
/// Every per-particle quantity is one contiguous column (positions and velocities per direction,
/// the deformation gradient and velocity gradient per component, the Cauchy stress as six
/// components xx, yy, zz, xy, yz, xz). Particles are kept grouped by material (contiguous ranges,
/// see materialRange()) and, within a material, sorted by cell when sortByCell() is called, so
/// the constitutive update runs over a range and the grid loops touch memory in order.
/// resize()/permute()/pack() treat all columns alike, so adding a column is one line in columns().
///
/// Columns a scene does not use are not stored (ParticleLayout, setLayout(): left empty): in 1D and
/// 2D the out-of-plane tensor components (F and L: xz, yz, zx, zy, zz; stress yz, xz), which are
/// exact zeros there (F_zz the exact 1), the load columns (fext, loadArea, load) without loads, the
/// surface-coupling columns (fsurf, surface) until a surface coupling enables them, the plastic
/// history (eqps, failed) without a plastic model. stored(c) says whether a column is kept;
/// column(c) gives a stored column or a column of its constant value (for output). pack() writes
/// every column (the constant of one not stored), so checkpoints and migration buffers keep one
/// format whatever the layout. A ParticleSet built directly keeps every column (the default layout).
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace mpmice::mpm {

enum StressComp { kXX = 0, kYY = 1, kZZ = 2, kXY = 3, kYZ = 4, kXZ = 5 };

/// Which column groups a ParticleSet stores (see ParticleSet).
struct ParticleLayout {
  int dim = 3;           ///< 1, 2: out-of-plane tensor components not stored
  bool loads = true;     ///< fext, loadArea, load
  bool surface = true;   ///< fsurf, surface
  bool plastic = true;   ///< eqps, failed
};

class ParticleSet {
 public:
  using Col = std::vector<double>;

  std::array<Col, 3> x, v;        // position, velocity
  std::array<Col, 3> halfSize;    // initial half-width per direction (GIMP), physical units
  std::array<Col, 3> fext;        // external force of loads this step
  std::array<Col, 3> x0;          // position at t = 0 (displacements, probes)
  std::array<Col, 3> fsurf;       // force of a surface coupling (set by the coupler, held until changed)
  Col surface;                    // 1 on the surface particles of a coupled solid, else 0
  Col mass, vol0, vol, temperature;
  Col eqps;                       // equivalent plastic strain
  Col failed;                     // 1 once the failure strain was reached
  Col work;                       // stress work per particle (strain + dissipated energy) [J] (mpm.stress_work)
  Col loadArea;                   // surface area a load acts on (0: volume / particle size)
  std::array<Col, 9> F;           // deformation gradient, row-major
  std::array<Col, 9> L;           // velocity gradient of the current step, row-major
  std::array<Col, 6> stress;      // Cauchy stress
  std::vector<std::int32_t> material;  // index into the scene's materials
  std::vector<std::int32_t> load;      // index into the scene's loads, -1 = none
  std::vector<std::int64_t> id;        // global id (stable across ranks and runs)

  [[nodiscard]] std::size_t size() const { return mass.size(); }
  /// Sets the stored column groups: newly stored columns get their constant value for every
  /// particle, columns no longer stored are freed.
  void setLayout(const ParticleLayout& layout);
  [[nodiscard]] const ParticleLayout& layout() const { return layout_; }
  /// Whether column c (a member of this set) is stored.
  [[nodiscard]] bool stored(const Col& c) const { return c.size() == size() || size() == 0; }
  /// Column c if stored, else a column of size() values of its constant (0; F_zz 1).
  [[nodiscard]] const Col& column(const Col& c) const;
  void resize(std::size_t n);
  void reserve(std::size_t n);
  /// Appends one particle with identity F and zero stress; returns its index.
  std::size_t addParticle(const std::array<double, 3>& pos, const std::array<double, 3>& vel,
                          double m, double volume, const std::array<double, 3>& half,
                          int mat, double temp, std::int64_t gid);

  /// Reorders every column: new[i] = old[perm[i]]. `scratch` is reused storage.
  void permute(const std::vector<std::uint32_t>& perm, std::vector<double>& scratch);
  /// Keeps the particles with keep[i] != 0 (in order).
  void compact(const std::vector<char>& keep);

  /// Number of doubles pack() writes per particle.
  [[nodiscard]] static std::size_t packedSize();
  /// Appends particle i to buf; unpack appends a particle read from buf (returns doubles read).
  void pack(std::size_t i, std::vector<double>& buf) const;
  std::size_t unpack(const double* buf);

  /// Sorts by (material, key) where key[i] is e.g. the cell index; updates the material ranges.
  void sortBy(const std::vector<std::uint64_t>& key, std::vector<std::uint32_t>& perm,
              std::vector<double>& scratch);
  /// Recomputes the ranges of materials 0..nmat-1 (requires grouping by material).
  void updateMaterialRanges(int nmat);
  [[nodiscard]] std::pair<std::size_t, std::size_t> materialRange(int m) const {
    return {ranges_[m], ranges_[m + 1]};
  }
  [[nodiscard]] bool groupedByMaterial() const;

 private:
  struct ColumnInfo {
    Col* col;
    double value;  // the constant of a column not stored
    bool stored;
  };
  /// Every double column with its constant and whether the layout stores it (pack order).
  std::vector<ColumnInfo> allColumns();
  std::vector<Col*> columns();  // the stored ones
  std::vector<const Col*> columns() const;
  std::vector<std::size_t> ranges_{0, 0};
  ParticleLayout layout_;
  mutable Col zeros_, ones_;  // column(): constants of columns not stored
};

}  // namespace mpmice::mpm
