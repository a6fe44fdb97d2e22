#pragma once
/// @brief The solid side of a surface coupling: mpm_solver coupled to a fluid that owns a mesh
/// whose boundary patch is the solid's surface (the OpenFOAM adapter, adapters/openfoam).
///
/// Start: the handshake (same scene, interface and schedule), the fluid's patch (face centres,
/// points) and time window; the solid marks the surface particles of coupling.interface.solid
/// and builds two maps from them at t = 0 (Lagrangian: computed once): to the face centres
/// (forces, conservative: f_particles = M^T f_faces) and to the patch points (displacements,
/// consistent: u_points = M u_particles), by coupling.interface.mapping.
/// Each window (the fluid's deltaT), two_way:
///   explicit_serial  the fluid solves the window, its face forces arrive, the solid sub-cycles
///                    MPM over the window with those forces held, its displacements go back
///                    (the fluid's mesh follows them in its next window);
///   implicit_serial  the same, repeated from both sides' checkpoints until the displacements
///                    the fluid used and those the solid returns agree (coupling.convergence on
///                    interface_displacement / interface_force; coupling.acceleration on the
///                    displacements).
/// one_way: the fluid runs alone with the undeformed solid (the solid only answers) to time.end,
/// to a steady state; its last forces are then held while the solid relaxes for time.end
/// (quasi-static with mpm.damping): the classic sequential CFD -> structure workflow.
/// Writes particles (HDF5/XDMF), probes, and <scene>_coupling.csv (per window: time, iterations,
/// MPM sub-steps, total interface force, timings).
/// Restart (two_way): with output.checkpoint_interval, after each window at which a checkpoint is
/// due the solid writes <scene>_checkpoint_<window>.h5 (particles, clock, window counters, the
/// displacements the fluid holds, the acceleration's history, the patch of t = 0) and its reply
/// tells the fluid to write its state of the same time; `restart` (a checkpoint file or an output
/// directory) resumes from one, the fluid from its matching time directory.
#include <ostream>
#include <string>

#include "coupler/launch/participant.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Returns the exit status. Throws CouplingTimeout, HandshakeMismatch, std::invalid_argument
/// (a fluid case that disagrees with the scene).
int runSurfaceSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                               const std::string& restart = "");

}  // namespace mpmice::coupler
