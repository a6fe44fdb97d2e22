#pragma once
/// @brief `coupler check [--quiet] <scene.yaml>`: validates a scene without starting any solver.
///
/// Prints the scene as understood (dumpScene: every default filled in, a valid scene itself)
/// followed by a one-line summary as a YAML comment, so the output can be saved and run.
/// With --quiet, only the summary. On an invalid scene prints the SceneError message (file, line,
/// key, value, what was expected) to `err` and returns 2. Does not initialise MPI.
///
/// A valid scene then meets the start-up validation of each program that would run it (the
/// programs of its launch: coupler run's composeLaunch): `checks` maps a program's name to the
/// function that program calls at start (mpm::validateStartup, ice::validateStartup; the coupler
/// program supplies them, this library knows no solver). A rule it breaks is printed as
/// "<scene file>[:line:column]: <program> refuses the scene at start: <key>: <what was expected>"
/// and the exit status is 2.
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::coupler {

/// A program's start-up validation by program name ("mpm_solver", "ice_solver"); each throws
/// std::invalid_argument naming the scene key and what was expected.
using StartupChecks = std::map<std::string, std::function<void(const core::Scene&)>>;

/// Runs the check on `args` (after "check"); returns the exit status.
int runCheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const StartupChecks& checks = {});

/// The usage text of `coupler check` (`coupler check --help`).
std::string checkUsage();

/// "scene 'sod': 1D, 100 cells ...; 1 material (air: fluid, ideal_gas); ..."
std::string summarizeScene(const core::Scene& s);

}  // namespace mpmice::coupler
