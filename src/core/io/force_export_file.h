#pragma once
/// @brief Point forces exported by a fluid code: the file format of the sequential (one-way)
/// workflow, as CFX-Post writes it (docs/openfoam.md "The sequential workflow with files").
///
///     # any number of comment lines (a '#' in the first non-blank column), blank lines allowed
///     # Depth [m]: 0.1          <- optional: the fluid mesh's depth of a 2D case (forces per it)
///     x, y, z, Fx1, Fy1, Fz1 [, Fx2, Fy2, Fz2 ...]
///
/// One data line per point: its coordinates and one force vector per fluid phase [N]
/// (comma-separated; 3 + 3k numbers, k >= 1, the same on every line). The phases' vectors are
/// summed. adapters/openfoam writes this format for its patch's face forces (one phase).
#include <array>
#include <string>
#include <vector>

namespace mpmice::core {

struct ForceExport {
  std::string file;            // the path it was read from
  std::vector<double> points;  // 3 per point
  std::vector<double> forces;  // 3 per point: the sum over the phases
  int phases = 0;              // force vectors per line
  double depth = 0;            // "# Depth [m]:" comment; 0 = not given
  [[nodiscard]] std::size_t size() const { return points.size() / 3; }
  /// Total force and its moment about `origin` (M = sum (x - origin) x f).
  [[nodiscard]] std::array<double, 3> totalForce() const;
  [[nodiscard]] std::array<double, 3> totalMoment(const std::array<double, 3>& origin) const;
};

/// Reads `path`; std::invalid_argument naming the file, the line and what was expected for an
/// unreadable file, a malformed number, a wrong column count, a non-finite value or no data.
ForceExport readForceExport(const std::string& path);
/// The same from text (`file` names it in errors).
ForceExport parseForceExport(const std::string& text, const std::string& file);

}  // namespace mpmice::core
