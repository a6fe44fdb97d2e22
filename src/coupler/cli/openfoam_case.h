#pragma once
/// @brief The OpenFOAM side of `coupler run` for coupling.fluid: openfoam.
///
/// The case named by coupling.interface.case (relative to the scene file) is copied fresh to
/// <output.directory>/<case name> (never over the case itself: copyCaseFresh), its system/controlDict gets the mpmiceAdapter function object
/// (library, scene), and blockMesh builds its mesh when the case has none. The solver then runs
/// in that copy (`<solver> -case <copy>`), serial, as one participant of the MPMD launch.
#include <filesystem>
#include <ostream>
#include <string>

#include "core/scene/scene.h"

namespace mpmice::coupler {

/// The function object entry `coupler run` adds to a case's controlDict.
std::string adapterEntry(const std::string& adapterLibrary, const std::string& sceneFile);

/// controlDict text with `entry` inside its `functions` dictionary (created if absent).
std::string withFunctionObject(const std::string& controlDict, const std::string& entry);

/// Prepares the working copy; returns its absolute path. Throws std::invalid_argument naming the
/// scene key (missing case, no controlDict, missing adapter library) and std::runtime_error when
/// blockMesh fails (with the tail of its log).
std::string prepareOpenFoamCase(const core::Scene& scene, const std::string& sceneFile, const std::string& binDir,
                                std::ostream& out);  // binDir: --bin-dir (cli/program_locator.h)

/// `coupler run --restart PATH`: the case copy of the run that wrote the checkpoint PATH means
/// (the scene's checkpoint there, core::resolveCheckpoint) is resumed in place: its controlDict
/// starts from the time directory of the checkpoint's time (startFrom startTime) and ends at the
/// scene's time.end; nothing is copied or deleted. Returns the copy's path. Throws
/// std::invalid_argument naming the checkpoint and the case copy when the copy or its time
/// directory of that time is missing.
std::string resumeOpenFoamCase(const core::Scene& scene, const std::string& sceneFile, const std::string& restart,
                               std::ostream& out);

/// Copies the case folder `source` to `target`, replacing an earlier copy made by coupler run.
/// Throws std::invalid_argument, deleting nothing, when target is, contains or lies inside source,
/// or when target exists and is not such a copy.
void copyCaseFresh(const std::filesystem::path& source, const std::filesystem::path& target);

}  // namespace mpmice::coupler
