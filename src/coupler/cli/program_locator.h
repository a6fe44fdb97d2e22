#pragma once
/// @brief Where `coupler run` finds what it launches: the programs, the OpenFOAM adapter and the
/// MPI launch helper, in a build tree or in an installed prefix.
///
///   --bin-dir DIR   DIR/<program> (an installed bin directory) or DIR/<program>/<program> (a build
///                   directory); the adapter DIR/../lib/libmpmiceFoamAdapter.so or
///                   DIR/adapters/openfoam/libmpmiceFoamAdapter.so
///   default         beside this coupler (<its dir>/<program>: installed), its build tree
///                   (<its dir>/../<program>/<program>), then PATH
/// The launch helper: <coupler's dir>/../libexec/mpmice/mpirun when installed, else the build's
/// scripts/mpirun, else `mpirun` from PATH.
#include <string>
#include <vector>

namespace mpmice::coupler {

/// The folder of the running program (/proc/self/exe), "." when unknown.
std::string ownDirectory();

/// The directories searched for `program`, in order, for --bin-dir `binDir` (empty: the default).
std::vector<std::string> programCandidates(const std::string& program, const std::string& binDir,
                                           const std::string& ownDir);

/// The first candidate that is an executable file; without one, the PATH entry (default only);
/// without that, the first candidate (for the error message that names it).
std::string locateProgram(const std::string& program, const std::string& binDir, const std::string& ownDir);

/// The OpenFOAM adapter library, found as locateProgram finds programs (first candidate if none).
std::string locateAdapterLibrary(const std::string& binDir, const std::string& ownDir);

/// The MPI launch helper (installed, the build's, or mpirun from PATH).
std::string locateLaunchHelper(const std::string& ownDir);

}  // namespace mpmice::coupler
