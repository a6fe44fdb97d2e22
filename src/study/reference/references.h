#pragma once
/// @brief The references a study measures its points against, by name: each takes a finished
/// run (its folder, its scene file, the scene's name) and gives one error (a finite number >= 0,
/// smaller is better). Today: `lame_cylinder` (Eq. 13 against the exact Lame solution),
/// `piston` (the adiabatic piston's pressure), `shock_slab` (the reflected pressure) and
/// `probe_curve` (a probe's record against a reference curve the study file names: the flap's tip
/// against MPM + OpenFOAM).
#include <functional>
#include <stdexcept>
#include <string>

namespace mpmice::study {

struct RunFiles {
  std::string dir;    // the run's output folder
  std::string scene;  // the scene file the run read
  std::string name;   // the scene's `scene:` name (the output files' prefix)
  std::string curve;  // the study's `reference_curve` (resolved), for a reference that reads one
  std::string column; // the study's `reference_column`
};

struct Reference {
  std::string name;
  std::string description;
  std::function<double(const RunFiles&)> error;  // throws std::exception when it cannot measure
  bool readsCurve = false;  // needs the study's `reference_curve` and `reference_column`
};

/// The reference called `name`; std::invalid_argument naming the valid choices otherwise.
const Reference& findReference(const std::string& name);

/// The valid names, comma-separated.
std::string referenceNames();

}  // namespace mpmice::study
