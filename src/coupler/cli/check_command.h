#pragma once
/// @brief `coupler check [--quiet] <scene.yaml>`: validates a scene without starting any solver.
///
/// Prints the scene as understood (dumpScene: every default filled in, a valid scene itself)
/// followed by a one-line summary as a YAML comment, so the output can be saved and run.
/// With --quiet, only the summary. On an invalid scene prints the SceneError message (file, line,
/// key, value, what was expected) to `err` and returns 2. Does not initialise MPI.
#include <ostream>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Runs the check on `args` (after "check"); returns the exit status.
int runCheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// The usage text of `coupler check` (`coupler check --help`).
std::string checkUsage();

/// "scene 'sod': 1D, 100 cells ...; 1 material (air: fluid, ideal_gas); ..."
std::string summarizeScene(const core::Scene& s);

}  // namespace mpmice::coupler
