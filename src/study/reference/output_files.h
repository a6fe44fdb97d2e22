#pragma once
/// @brief The output files of a finished run that the references read: the first and the last
/// output step of a scene in a folder, from mpmice (<scene>_NNNNNN.h5) or from the MPMD
/// participants (<scene>_solid_NNNNNN.h5 for the particles, <scene>_fluid_NNNNNN.h5 for the grid).
#include <string>

namespace mpmice::study {

/// The last output step of scene `scene` in `dir`. Throws when there is none.
struct LastOutput {
  std::string particles, grid;
};
LastOutput lastOutput(const std::string& dir, const std::string& scene);

/// The last output step and the first step's particles and grid (the initial state).
struct OutputSpan {
  LastOutput last;
  std::string firstParticles, firstGrid;
};
OutputSpan outputSpan(const std::string& dir, const std::string& scene);

}  // namespace mpmice::study
