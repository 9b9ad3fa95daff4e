/* dymesh.h: the stable C ABI of the DyMESH contact engine (C99; every name starts with dm_).
 *
 * Conventions (Embree-style):
 * - Opaque handles (dm_world); every call returns a dm_status (DM_OK = 0) unless it only reads a
 *   count; on failure dm_last_error() gives a message for the calling thread. No exception crosses
 *   this boundary.
 * - Every entry point checks its arguments: null pointers, body indices out of range, non-finite
 *   states, dt <= 0 and counts that do not match the world are refused with DM_ERROR_ARGUMENT,
 *   the message naming the argument or field (e.g. "states[0].velocity[0]").
 * - Definition structs begin with struct_size (set it to sizeof the struct): later versions append
 *   fields and accept each size the struct was published with (listed at the struct); any other
 *   size (past sizeof, or ending partway through a field) is DM_ERROR_ARGUMENT.
 * - Views (const pointers into the engine) are read-only and valid until the next call that
 *   changes the world (step, run, host step, destroy); the dm_..._copy variants write into memory
 *   the host owns.
 * - Units: SI (m, kg, s, rad, N) everywhere, except where a call says "in the scenario's units".
 *   Earth frame SAE: x forward, y right, z down; body axes likewise, about the CG.
 * - Threads: different worlds are independent (each in its own thread, at once). One world takes
 *   one call that changes it at a time: dm_world_run, dm_world_step, dm_world_host_step,
 *   dm_world_host_finish and dm_world_write_outputs are refused with DM_ERROR_STATE ("another call
 *   on this world is in progress") while any other call on the same world runs in another thread,
 *   and every other call on it (they only read) is refused the same way while one of those runs;
 *   calls that only read may run beside each other. Nothing waits: the host orders its calls.
 *   Not checked: dm_world_body_count (it never changes), dm_world_destroy (call it only when no
 *   other call on the world runs), and reading a view: a view read in one thread while another
 *   steps the world may show a step in progress.
 *
 * Two ways to use it:
 * - World mode: dm_world_load_scenario (or dm_world_create from arrays), dm_world_run or
 *   dm_world_step, then read states, delta-V, crush and the summary JSON text.
 *   A world is driven one way: once stepped in world mode it takes no host step, once host-driven no
 *   world-mode step or run, and a finished run takes neither (DM_ERROR_STATE).
 * - Force-provider mode (how DyMESH sits inside a host's vehicle dynamics): each collision step,
 *   dm_world_host_step passes every body's pose and velocities and returns the force and moment at
 *   each CG in the body frame, updating crush; dm_world_host_finish ends the run. The summary,
 *   delta-V and outputs then describe the host-driven run.
 */
#ifndef DYMESH_DYMESH_H
#define DYMESH_DYMESH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Exported from libdymesh_c.so (everything else in it is hidden). */
#if defined(__GNUC__) || defined(__clang__)
#define DM_API __attribute__((visibility("default")))
#else
#define DM_API
#endif

/** ABI version: bumped when a signature or a struct layout changes incompatibly. */
#define DM_ABI_VERSION 1u

typedef enum dm_status {
  DM_OK = 0,
  DM_ERROR_ARGUMENT = 1, /**< a null pointer, an index out of range, a non-finite value, a wrong count */
  DM_ERROR_INPUT = 2,    /**< a scenario, mesh or definition refused (message: file, field, what was expected) */
  DM_ERROR_STATE = 3,    /**< the call does not fit the world's state (e.g. stepping a finished run) */
  DM_ERROR_IO = 4,       /**< a file could not be written */
  DM_ERROR_INTERNAL = 5  /**< anything else (out of memory, a bug): the message says what */
} dm_status;

/** How a run ended (summary.json "status"). */
typedef enum dm_run_status {
  DM_RUN_COMPLETE = 0,
  DM_RUN_ENDED_IN_CONTACT = 1,
  DM_RUN_INTERRUPTED = 2, /**< not finished yet, or stopped early */
  DM_RUN_FAILED_NUMERICS = 3
} dm_run_status;

typedef struct dm_world dm_world;

/** Pose and velocities of one body (earth frame; omega in body axes). */
typedef struct dm_body_state {
  double position[3]; /**< [m] CG */
  double roll, pitch, yaw; /**< [rad] */
  double velocity[3]; /**< [m/s] CG, earth frame */
  double omega[3];    /**< [rad/s] p, q, r, body frame */
} dm_body_state;

/** Collision loads at one body's CG over a step. */
typedef struct dm_loads {
  double force_body[3];  /**< [N] body frame */
  double moment_body[3]; /**< [N m] about the CG, body frame */
  double force_earth[3]; /**< [N] earth frame */
} dm_loads;

/** How a body moves besides the collision loads (dm_body_desc.motion; a scenario's "motion"). */
typedef enum dm_motion {
  DM_MOTION_DEFAULT = 0, /**< planar for a moving body; a `fixed` body does not move */
  DM_MOTION_PLANAR = 1,  /**< x, y and yaw; height, roll and pitch held ("planar") */
  DM_MOTION_FREE = 2,    /**< all six degrees of freedom, no gravity ("free") */
  DM_MOTION_GRAVITY = 3  /**< six degrees of freedom, gravity and a ground support at the initial CG height ("gravity") */
} dm_motion;

/** One body built from arrays (dm_world_create). */
typedef struct dm_body_desc {
  size_t struct_size;      /**< sizeof(dm_body_desc) */
  const char* name;        /**< used in the summary and output file names */
  const double* vertices;  /**< [m] x, y, z per vertex, body axes about the CG */
  int32_t vertex_count;
  const int32_t* triangles; /**< three vertex indices per triangle, wound outward (faces wound against their
                                 neighbours, or a whole mesh wound inward, are turned, as a mesh file's) */
  int32_t triangle_count;
  double mass;              /**< [kg]; ignored for a fixed body */
  double inertia[3];        /**< [kg m^2] Ixx, Iyy, Izz about the CG */
  double stiffness_a;       /**< [N/m^2] 3-D A (per area), every surface */
  double stiffness_b;       /**< [N/m^3] 3-D B (per area), every surface */
  double restitution;       /**< [0, 1] */
  double friction;          /**< >= 0 */
  int32_t rigid;            /**< nonzero: takes no crush */
  int32_t fixed;            /**< nonzero: does not move */
  dm_body_state initial;
  int32_t motion;           /**< a dm_motion; appended 2026-11-24: a struct_size that ends before it means DM_MOTION_DEFAULT */
} dm_body_desc;
/* dm_body_desc's published sizes: sizeof(dm_body_desc) (224 on LP64) and, from the first header
 * (2026-11-23), offsetof(dm_body_desc, motion) (216). Every element of one array has bodies[0]'s
 * struct_size, and the elements are that many bytes apart. */

/** Where a slave node looks for the master surface (a scenario's contact.search_direction; README
 *  "The model"): where to look, not the force's direction, which is the master surface's normal. */
typedef enum dm_search_direction {
  DM_SEARCH_DEFAULT = 0,              /**< the default, DM_SEARCH_VELOCITY */
  DM_SEARCH_VELOCITY = 1,             /**< along the relative velocity ("velocity") */
  DM_SEARCH_LOCAL_AVERAGE_NORMAL = 2, /**< along the node's averaged surface normal ("local_average_normal") */
  DM_SEARCH_POLY_NORMAL = 3,          /**< along the normal of the polygon first met ("poly_normal") */
  DM_SEARCH_SPECIFIED = 4             /**< along dm_world_desc.specified_direction ("specified") */
} dm_search_direction;

/** Which of the faces a search meets a node takes (a scenario's contact.stop_rule). */
typedef enum dm_stop_rule {
  DM_STOP_DEFAULT = 0,     /**< the default, DM_STOP_BEST_OF_ALL */
  DM_STOP_AFTER_ONE = 1,   /**< the first face found ("after_one") */
  DM_STOP_BEST_OF_TWO = 2, /**< the better of the first two ("best_of_two") */
  DM_STOP_BEST_OF_ALL = 3  /**< the best of all found ("best_of_all") */
} dm_stop_rule;

/** The run as a whole (dm_world_create). */
typedef struct dm_world_desc {
  size_t struct_size;        /**< sizeof(dm_world_desc) */
  double time_step;          /**< [s] */
  double duration;           /**< [s] */
  int32_t stop_at_separation; /**< nonzero: end 0.02 s after the last contact force */
  int32_t passes_per_step;    /**< master/slave passes per step (0: the default, 2) */
  /* appended 2026-11-28 (the three below): a struct_size that ends before them means the defaults */
  int32_t search_direction;       /**< a dm_search_direction */
  int32_t stop_rule;              /**< a dm_stop_rule */
  double specified_direction[3];  /**< with DM_SEARCH_SPECIFIED: a nonzero vector in each slave body's axes
                                       (normalized; with two deformable bodies warned specified_direction_shared);
                                       otherwise all zero */
} dm_world_desc;
/* dm_world_desc's published sizes: sizeof(dm_world_desc) (64 on LP64) and, from the first header
 * (2026-11-23), offsetof(dm_world_desc, search_direction) (32). */

/** The ABI version this library was built with (DM_ABI_VERSION); compare it with the header's. */
DM_API uint32_t dm_abi_version(void);

/** The message of the calling thread's last failure ("" when none); valid until its next call. */
DM_API const char* dm_last_error(void);

/** Limits the worker threads of every world (0: all cores). Results do not depend on it. */
DM_API dm_status dm_set_threads(int32_t threads);

/* ---- world mode ---------------------------------------------------------------------------- */

/** Loads and validates a scenario file and its meshes (as `dymesh check` does). */
DM_API dm_status dm_world_load_scenario(const char* path, dm_world** out);

/** Builds a world from arrays (SI units); `bodies` holds `body_count` descriptions. Held to a
 *  scenario file's checks (README "Physical ranges"): DM_ERROR_ARGUMENT names the field of a
 *  struct_size that is not a published size, a non-finite number (a fixed body's unused mass and
 *  inertia included), a value outside its physical range, a name that is not UTF-8 text, unusable
 *  in file names or used twice, a planar body given a vertical velocity, a mesh of an impossible
 *  size (1 mm .. 1 km) or too many steps (1e7);
 *  DM_ERROR_INPUT a deformable mesh that encloses no volume, bodies overlapping deeply at the start
 *  or a step beyond the stable limit. Implausible values are warned in the summary. */
DM_API dm_status dm_world_create(const dm_world_desc* world, const dm_body_desc* bodies, int32_t body_count, dm_world** out);

/** Runs to the end (duration or separation); DM_ERROR_STATE for a finished or host-driven run. */
DM_API dm_status dm_world_run(dm_world* w);

/** One step; *finished is set nonzero once the run has ended. DM_ERROR_STATE for a finished or
 *  host-driven run (*finished still set), or while another call on the world runs (*finished not
 *  touched). */
DM_API dm_status dm_world_step(dm_world* w, int32_t* finished);

DM_API int32_t dm_world_body_count(const dm_world* w); /**< -1 for a null world */
DM_API dm_status dm_world_time(const dm_world* w, double* out_seconds);
DM_API dm_status dm_world_run_status(const dm_world* w, dm_run_status* out);

/** Body i's name (a view). */
DM_API dm_status dm_body_name(const dm_world* w, int32_t body, const char** out);

/** Body i's current pose and velocities. */
DM_API dm_status dm_body_state_get(const dm_world* w, int32_t body, dm_body_state* out);

/** Body i's delta-V since t = 0, earth frame, in the scenario's units (mph or m/s). */
DM_API dm_status dm_body_delta_v(const dm_world* w, int32_t body, double out_xyz[3]);

/** Body i's current (crushed) vertices, x, y, z per vertex, body frame [m]: a view. */
DM_API dm_status dm_body_vertices(const dm_world* w, int32_t body, const double** out_xyz, int32_t* out_count);

/** The same, copied into `xyz` (3 * capacity doubles); *out_count receives the vertex count. */
DM_API dm_status dm_body_copy_vertices(const dm_world* w, int32_t body, double* xyz, int32_t capacity, int32_t* out_count);

/** Body i's permanent deformation Delta per vertex, x, y, z, body frame [m]: a view. */
DM_API dm_status dm_body_deformation(const dm_world* w, int32_t body, const double** out_xyz, int32_t* out_count);

/** Body i's permanent crush |Delta| per vertex [m], copied into `crush` (capacity values). */
DM_API dm_status dm_body_copy_crush(const dm_world* w, int32_t body, double* crush, int32_t capacity, int32_t* out_count);

/** The run's summary as JSON text, byte-identical to the summary.json `dymesh run` writes: a view. */
DM_API dm_status dm_world_summary_json(dm_world* w, const char** out_text);

/** The same, copied into `buffer` (size bytes, with the terminating zero); *needed receives the
 *  size required (length + 1). DM_ERROR_ARGUMENT when it does not fit. */
DM_API dm_status dm_world_copy_summary_json(dm_world* w, char* buffer, size_t size, size_t* needed);

/** Writes the run's outputs (meshes, history.csv, report.html, summary.json) into `dir` (created when
 *  missing), replacing the files a previous dymesh run listed in the folder's manifest; other files
 *  are left as they are. DM_ERROR_IO when the folder cannot take them (not a folder, not writable,
 *  another run's lock, an output's name past the folder's name or path limit, or a file under an
 *  output's name that no dymesh run wrote, that is not a regular file or that is one of the run's
 *  inputs: the message names `dir` and the file) or a write fails; a refused folder is left as it
 *  was. A write that fails partway leaves no summary.json (written last: its presence means the
 *  files beside it are complete). DM_ERROR_ARGUMENT for a null or empty `dir`. */
DM_API dm_status dm_world_write_outputs(dm_world* w, const char* dir);

/** A hash of every body's final state (rigid state and vertices), equal at any thread count. */
DM_API dm_status dm_world_state_hash(const dm_world* w, uint64_t* out);

DM_API void dm_world_destroy(dm_world* w);

/* ---- force-provider mode ------------------------------------------------------------------- */

/** Every body's state now (`count` = body count); writes `count` loads for the coming step of
 *  length dt and updates crush. The host integrates the bodies with the loads. DM_ERROR_STATE for
 *  a finished run or one stepped in world mode. */
DM_API dm_status dm_world_host_step(dm_world* w, const dm_body_state* states, int32_t count, double dt, dm_loads* out_loads);

/** Ends a host-driven run with the states reached after the last step. DM_ERROR_STATE before the
 *  first dm_world_host_step ("no host step taken"), for a finished run or one stepped in world mode. */
DM_API dm_status dm_world_host_finish(dm_world* w, const dm_body_state* states, int32_t count);

#ifdef __cplusplus
}
#endif

#endif /* DYMESH_DYMESH_H */
