#pragma once
/// @brief The material points of one rank, stored as structure of arrays.
///
/// Every per-particle quantity is one contiguous column (positions and velocities per direction,
/// the deformation gradient and velocity gradient per component, the Cauchy stress as six
/// components xx, yy, zz, xy, yz, xz). Particles are kept grouped by material (contiguous ranges,
/// see materialRange()) and, within a material, sorted by cell when sortByCell() is called, so
/// the constitutive update runs over a range and the grid loops touch memory in order.
/// resize()/permute()/pack() treat all columns alike, so adding a column is one line in columns().
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace mpmice::mpm {

enum StressComp { kXX = 0, kYY = 1, kZZ = 2, kXY = 3, kYZ = 4, kXZ = 5 };

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
  std::vector<Col*> columns();
  std::vector<const Col*> columns() const;
  std::vector<std::size_t> ranges_{0, 0};
};

}  // namespace mpmice::mpm
