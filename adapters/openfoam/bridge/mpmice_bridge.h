/* mpmice_bridge: the coupler seen from a fluid program that owns its own mesh (OpenFOAM).
 *
 * A plain C interface, so that the OpenFOAM function object (built with OpenFOAM's C++11 flags)
 * can call the coupler (C++20) without sharing any C++ type. The bridge is the fluid's launch
 * layer: it initialises MPI if the program has not (a serial OpenFOAM solver does not), joins
 * the MPMD launch as the participant "openfoam", checks the scene with the solid (handshake) and
 * carries the interface data of src/couplings/surface/surface_protocol.h.
 *
 * Every function returns 0 on success; on failure non-zero, and mpmice_bridge_error() says why
 * (the caller stops the program with that message: OpenFOAM's FatalError).
 */
#ifndef MPMICE_BRIDGE_H
#define MPMICE_BRIDGE_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mpmice_bridge mpmice_bridge;

/* What the scene says about the interface (filled by mpmice_bridge_start). */
typedef struct {
  int coupled;            /* 1: a solid participant is in the launch; 0: the fluid runs alone */
  int two_way;            /* 1: two_way (displacements come back), 0: one_way */
  int implicit;           /* 1: implicit_serial (windows may be repeated) */
  double fluid_density;   /* coupling.interface.fluid_density */
  char patch[256];        /* coupling.interface.patch */
} mpmice_bridge_info;

/* Reads the scene, initialises MPI if needed, joins the launch. Returns NULL only when out of
 * memory; check mpmice_bridge_error() for a failure (the handle is still valid to query and free). */
mpmice_bridge* mpmice_bridge_start(const char* scene_file);
const char* mpmice_bridge_error(const mpmice_bridge* b);
int mpmice_bridge_info_get(const mpmice_bridge* b, mpmice_bridge_info* info);

/* The patch at the start: face centres (3 per face), points (3 per point, in the order
 * displacements come back), depth of a 2D mesh (1 in 3D), the fluid's time step (the coupling
 * window), start (0, or a restart's time; the solid keeps the geometry of t = 0 in its checkpoint)
 * and end time. */
int mpmice_bridge_set_patch(mpmice_bridge* b, int n_faces, const double* face_centres, int n_points,
                            const double* points, double depth, double dt, double start, double end);

/* One window: the fluid has solved up to t_end; face_forces (3 per face, N) go to the solid;
 * point_displacements (3 per point, m, from t = 0) come back with the action: 0 = advance,
 * 1 = repeat the window (implicit) from the fluid's checkpoint with the new displacements.
 * last: 1 on the fluid's last window. */
int mpmice_bridge_exchange(mpmice_bridge* b, double t_end, double dt, int last, const double* face_forces,
                           double* point_displacements, int* action, int* iterations);

/* 1 when the solid writes a restart checkpoint at the window the last mpmice_bridge_exchange
 * accepted (output.checkpoint_interval): the fluid writes its own state at that time too (OpenFOAM:
 * its time directory, after the new displacements are set), so `coupler run --restart` resumes
 * both from one time. 0 otherwise (and after a repeated window). */
int mpmice_bridge_write_due(const mpmice_bridge* b);

/* Leaves the launch (finalises MPI if the bridge initialised it) and frees the handle. */
void mpmice_bridge_finish(mpmice_bridge* b);

#ifdef __cplusplus
}
#endif

#endif
