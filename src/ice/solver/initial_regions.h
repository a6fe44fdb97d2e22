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
  /// Per geometry object (scene order), per material: the state the object places each fluid of
  /// its fill at (set for the fluids it names; solid objects and the rest unset).
  std::vector<std::vector<BackgroundState>> state;
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

/// The fluid regions a cell's fluid comes from, each with its share of the cell's fluid volume
/// (the shares sum to 1), as Uintah's ICE fills a cell from sub-cell points: a cell whose corners
/// and centre all have one cover takes that region whole; the others are sampled at kFillSamples
/// points per direction (the last region holding a point wins it), points inside a solid object
/// declared after their region, or in no region, skipped (the cell's solid part is the solid's).
/// A cell whose centre lies in a solid takes its centre's region whole (its fluids start as traces
/// there), as does a cell none of whose points count. A region's face between two cell centres
/// then holds the region's volume to the sampling's 1/(2 kFillSamples) of a cell instead of
/// rounding to a whole cell (the underwater scenes' charge held 25 % more products that way).
struct RegionShare {
  const core::RegionSpec* region = nullptr;
  double share = 0;
};
void cellShares(const RegionPlan& plan, const core::Mesh& mesh, const int ijk[3], const CellCover& centre,
                std::vector<RegionShare>* out);

/// A cell (i, j, k) of a scene with a fluid that no fluid region and no solid covers is an error.
void requireCovered(const RegionPlan& plan, const CellCover& cover, int i, int j, int k);

}  // namespace mpmice::ice
