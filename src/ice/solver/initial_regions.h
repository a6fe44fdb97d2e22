#pragma once
/// @brief The scene's geometry as ICE reads it at start: which objects hold fluid, each fluid's
/// background state, and what covers a cell centre. IceSolver::initialize builds its initial
/// state from it; `coupler check` runs the same rules over the whole mesh (startup_check.h).
///
/// Errors are std::invalid_argument naming the scene file and line, the region, the material and
/// what was expected.
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "ice/eos/eos.h"

namespace mpmice::ice {

/// Throws std::invalid_argument "<file>:<line>:<column>: msg" (the place when the scene gives one).
[[noreturn]] void badInput(const core::SourceLoc& where, const std::string& msg);

/// Material density and specific energy from a state (pressure, temperature, optional density).
void resolveState(const Eos& eos, double p, double T, std::optional<double> rho, double* rhoOut, double* eOut);

/// A fluid's state where a region places it and in cells no region fills for it.
struct BackgroundState {
  bool set = false;
  double rho = 1, e = 1;
};

struct RegionPlan {
  std::vector<const core::RegionSpec*> fluid;  // objects whose fill holds a fluid, scene order
  std::vector<const core::RegionSpec*> solid;  // objects of solids only, scene order
  std::vector<BackgroundState> background;     // per material (fluids: the first region filling it)
  int firstFluid = -1;                         // the scene's first fluid material (-1: none)
};

/// Validates every geometry object (fill, fractions summing to 1, pressure, density and
/// temperature > 0) and each fluid's state there: a finite density > 0 and a finite energy.
/// `eos[m]`: material m's equation of state (solids included).
RegionPlan planRegions(const core::Scene& scene, const std::vector<const Eos*>& eos);

/// What covers a cell centre: the last fluid region holding it, and whether a solid object
/// declared after that region holds it (then the cell starts with a trace of each fluid).
struct CellCover {
  const core::RegionSpec* fluid = nullptr;
  bool inSolid = false;
};
CellCover coverAt(const RegionPlan& plan, const core::RealVect& x, int dim);

/// What each fluid region fills against its shape: cells are filled by their centre (the last
/// region holding it wins), so a face of a region between two cell centres rounds to the nearer
/// one. Per scene.geometry entry (0 for solid objects): the cells' volume the region fills (outside
/// solids) and the volume its shape wins at points (the same rule point by point), the cells whose
/// corners and centre all have one cover counted whole, the others sampled at kFillSamples points
/// per direction. This rank's owned cells; sums over ranks add.
struct FillVolume {
  double cells = 0, shape = 0;
};
std::vector<FillVolume> measureFill(const core::Scene& scene, const RegionPlan& plan, const core::Mesh& mesh,
                                    const core::Box& owned);
/// One message per fluid region whose cells' volume differs from its shape's by more than
/// `tolerance` (relative), naming the region, both volumes and the cell spacing.
std::vector<std::string> fillWarnings(const core::Scene& scene, const std::vector<FillVolume>& v, double tolerance);

/// A cell (i, j, k) of a scene with a fluid that no fluid region and no solid covers is an error.
void requireCovered(const RegionPlan& plan, const CellCover& cover, int i, int j, int k);

}  // namespace mpmice::ice
