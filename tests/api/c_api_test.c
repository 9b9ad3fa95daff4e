/* The C ABI from plain C99: argument checks and messages, world mode (a scenario file, summary text
 * byte-identical to the command's summary.json, equal state hashes at 1, 2 and 4 threads), and
 * force-provider mode (bodies from arrays, a host integrating them with the loads it is given).
 * Usage: c_api_test DATA_DIR DYMESH_CLI WORK_DIR. Prints each failed check; exits 1 if any failed. */
#define _POSIX_C_SOURCE 200809L /* strdup, pthreads */
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "dymesh/dymesh.h"

static int failures = 0;

#define CHECK(cond)                                                              \
  do {                                                                           \
    if (!(cond)) {                                                               \
      fprintf(stderr, "%s:%d: check failed: %s (%s)\n", __FILE__, __LINE__, #cond, \
              dm_last_error());                                                  \
      ++failures;                                                                \
    }                                                                            \
  } while (0)

/* whole file as a malloc'd string (NULL when missing) */
static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* text = malloc((size_t)n + 1);
  size_t got = fread(text, 1, (size_t)n, f);
  text[got] = '\0';
  fclose(f);
  return text;
}

static int contains(const char* text, const char* part) { return strstr(text, part) != NULL; }

/* every entry point refuses bad arguments with a status and a message */
static void test_arguments(const char* scenario) {
  dm_world* w = NULL;
  CHECK(dm_abi_version() == DM_ABI_VERSION);
  CHECK(dm_world_load_scenario(NULL, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "path is null"));
  CHECK(dm_world_load_scenario("/nonexistent/s.json", &w) == DM_ERROR_INPUT && contains(dm_last_error(), "file not found"));
  CHECK(w == NULL);
  CHECK(dm_world_body_count(NULL) == -1);
  CHECK(dm_world_run(NULL) == DM_ERROR_ARGUMENT);
  CHECK(dm_world_load_scenario(scenario, &w) == DM_OK && w != NULL);
  double dv[3];
  CHECK(dm_body_delta_v(w, 2, dv) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "body 2 is out of range 0..1"));
  CHECK(dm_body_delta_v(w, -1, dv) == DM_ERROR_ARGUMENT);
  CHECK(dm_body_delta_v(w, 0, NULL) == DM_ERROR_ARGUMENT);
  dm_body_state states[2];
  dm_loads loads[2];
  CHECK(dm_body_state_get(w, 0, &states[0]) == DM_OK && dm_body_state_get(w, 1, &states[1]) == DM_OK);
  CHECK(dm_world_host_step(w, states, 1, 0.0005, loads) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "expected 2 body states, got 1"));
  CHECK(dm_world_host_step(w, states, 2, 0.0, loads) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "dt"));
  CHECK(dm_world_host_step(w, states, 2, -1.0, loads) == DM_ERROR_ARGUMENT);
  states[0].velocity[0] = NAN;
  CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_ERROR_ARGUMENT &&
        contains(dm_last_error(), "states[0].velocity[0]: expected a finite number, got nan"));
  size_t needed = 0;
  char small[8];
  CHECK(dm_world_copy_summary_json(w, small, sizeof small, &needed) == DM_ERROR_ARGUMENT && needed > sizeof small);
  dm_world_desc desc = {.struct_size = sizeof(dm_world_desc), .time_step = 0.0005, .duration = 0.2, .stop_at_separation = 1, .passes_per_step = 2};
  dm_body_desc one;
  memset(&one, 0, sizeof one);
  CHECK(dm_world_create(&desc, &one, 1, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "at least 2 bodies"));
  dm_world_destroy(w);
  CHECK(dm_set_threads(-1) == DM_ERROR_ARGUMENT);
}

/* world mode: the summary text equals the command's summary.json, byte for byte */
static void test_world_mode(const char* scenario, const char* cli, const char* work) {
  char command[16384], path[8192];
  snprintf(command, sizeof command, "%s run \"%s\" --quiet --out \"%s/cli\"", cli, scenario, work);
  CHECK(system(command) == 0);
  dm_world* w = NULL;
  CHECK(dm_world_load_scenario(scenario, &w) == DM_OK);
  CHECK(dm_world_body_count(w) == 2);
  CHECK(dm_world_run(w) == DM_OK);
  dm_run_status status;
  CHECK(dm_world_run_status(w, &status) == DM_OK && status == DM_RUN_COMPLETE);
  double dv[3];
  CHECK(dm_body_delta_v(w, 0, dv) == DM_OK && dv[0] < -30.0 && dv[0] > -40.0); /* mph, about 33 */
  const char* text = NULL;
  CHECK(dm_world_summary_json(w, &text) == DM_OK);
  snprintf(path, sizeof path, "%s/cli/summary.json", work);
  char* file = read_file(path);
  CHECK(file != NULL && text != NULL && strcmp(file, text) == 0);
  free(file);
  /* the views: vertices and deformation of the car, read-only, as many as the mesh has */
  const double* xyz = NULL;
  const double* delta = NULL;
  int32_t n = 0, m = 0;
  CHECK(dm_body_vertices(w, 0, &xyz, &n) == DM_OK && n == 4383 && xyz != NULL);
  CHECK(dm_body_deformation(w, 0, &delta, &m) == DM_OK && m == n);
  double* crush = malloc(sizeof(double) * (size_t)n);
  CHECK(dm_body_copy_crush(w, 0, crush, n, &m) == DM_OK && m == n);
  double largest = 0.0;
  for (int i = 0; i < n; ++i) largest = crush[i] > largest ? crush[i] : largest;
  CHECK(largest > 0.4 && largest < 0.6); /* [m] the demo's 20.85 in */
  free(crush);
  snprintf(path, sizeof path, "%s/abi", work);
  CHECK(dm_world_write_outputs(w, path) == DM_OK);
  /* a folder that cannot take the outputs is an I/O failure naming the parameter (not the command
     line's --out); a file given as the folder is left as it was */
  snprintf(path, sizeof path, "%s/abi/summary.json", work);
  CHECK(dm_world_write_outputs(w, path) == DM_ERROR_IO && contains(dm_last_error(), "summary.json: dir: exists and is not a folder") &&
        !contains(dm_last_error(), "--out"));
  CHECK(dm_world_write_outputs(w, "") == DM_ERROR_ARGUMENT && contains(dm_last_error(), "dir: expected a folder name"));
  dm_world_destroy(w);
}

/* the same run at 1, 2 and 4 threads: equal state hashes */
static void test_threads(const char* scenario) {
  uint64_t hashes[3];
  const int32_t threads[3] = {1, 2, 4};
  for (int k = 0; k < 3; ++k) {
    dm_world* w = NULL;
    CHECK(dm_set_threads(threads[k]) == DM_OK);
    CHECK(dm_world_load_scenario(scenario, &w) == DM_OK);
    CHECK(dm_world_run(w) == DM_OK);
    CHECK(dm_world_state_hash(w, &hashes[k]) == DM_OK);
    dm_world_destroy(w);
  }
  CHECK(dm_set_threads(0) == DM_OK);
  CHECK(hashes[0] == hashes[1] && hashes[1] == hashes[2]);
  printf("state hash 0x%016llx at 1, 2 and 4 threads\n", (unsigned long long)hashes[0]);
}

/* a closed box of size (lx, ly, lz) about the origin: 8 vertices, 12 triangles wound outward */
static void make_box(double lx, double ly, double lz, double v[24], int32_t t[36]) {
  for (int i = 0; i < 8; ++i) {
    v[3 * i] = (i & 1 ? 0.5 : -0.5) * lx;
    v[3 * i + 1] = (i & 2 ? 0.5 : -0.5) * ly;
    v[3 * i + 2] = (i & 4 ? 0.5 : -0.5) * lz;
  }
  static const int32_t faces[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                    2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  memcpy(t, faces, sizeof faces);
}

/* a 4.5 m box car of 1500 kg and a fixed rigid wall 1 m thick, 10 m wide, described from arrays */
typedef struct car_and_wall {
  double car_v[24], wall_v[24];
  int32_t car_t[36], wall_t[36];
  dm_body_desc bodies[2];
} car_and_wall;

/* the car starts in `car` with the given motion; the wall's centre is at x = wall_x */
static void make_car_and_wall(car_and_wall* s, dm_body_state car, double wall_x, int32_t motion) {
  make_box(4.5, 1.7, 0.8, s->car_v, s->car_t);
  make_box(1.0, 10.0, 2.5, s->wall_v, s->wall_t);
  memset(s->bodies, 0, sizeof s->bodies);
  s->bodies[0] = (dm_body_desc){sizeof(dm_body_desc), "car", s->car_v, 8, s->car_t, 12, 1500.0, {400, 2500, 2700},
                                1.0e5, 1.0e6, 0.1, 0.0, 0, 0, car, motion};
  s->bodies[1] = (dm_body_desc){sizeof(dm_body_desc), "wall", s->wall_v, 8, s->wall_t, 12, 0.0, {0, 0, 0}, 0.0, 0.0,
                                0.1, 0.0, 1, 1, {{wall_x, 0, 0}, 0, 0, 0, {0, 0, 0}, {0, 0, 0}}, DM_MOTION_DEFAULT};
}

/* the box car at 13.4 m/s, 1 cm before the wall */
static void make_car_at_wall(car_and_wall* s) {
  make_car_and_wall(s, (dm_body_state){{0, 0, 0}, 0, 0, 0, {13.4, 0, 0}, {0, 0, 0}}, 2.76, DM_MOTION_DEFAULT);
}

/* the world the car-and-wall tests run in: 0.5 ms steps, 0.3 s, stop at separation, 2 passes */
static dm_world_desc wall_run_desc(void) {
  return (dm_world_desc){.struct_size = sizeof(dm_world_desc), .time_step = 0.0005, .duration = 0.3, .stop_at_separation = 1, .passes_per_step = 2};
}

/* the box car at the wall (make_car_at_wall, wall_run_desc): a new world */
static dm_world* car_into_wall(car_and_wall* s) {
  make_car_at_wall(s);
  dm_world_desc desc = wall_run_desc();
  dm_world* w = NULL;
  CHECK(dm_world_create(&desc, s->bodies, 2, &w) == DM_OK);
  return w;
}

/* the box car's mesh wound inward, or with one face wound against its neighbours: turned outward, the
   same run bit for bit as the car wound outward (before, the inward car ran 2.75 m through the wall) */
static void test_winding(void) {
  uint64_t reference = 0;
  for (int variant = 0; variant < 3; ++variant) {
    car_and_wall s;
    make_car_at_wall(&s);
    for (int t = 0; t < 12; ++t)
      if (variant == 2 || (variant == 1 && t == 0)) {
        const int32_t corner = s.car_t[3 * t + 1];
        s.car_t[3 * t + 1] = s.car_t[3 * t + 2];
        s.car_t[3 * t + 2] = corner;
      }
    dm_world_desc desc = wall_run_desc();
    dm_world* w = NULL;
    CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_OK);
    if (!w) return;
    CHECK(dm_world_run(w) == DM_OK);
    uint64_t hash = 0;
    double dv[3];
    CHECK(dm_world_state_hash(w, &hash) == DM_OK && dm_body_delta_v(w, 0, dv) == DM_OK);
    CHECK(dv[0] < -13.4); /* stopped by the wall */
    if (variant == 0) reference = hash;
    CHECK(hash == reference);
    dm_world_destroy(w);
  }
}

/* force-provider mode: the host integrates a box car into a fixed wall with the loads it gets */
static void test_force_provider(void) {
  car_and_wall s;
  dm_world* w = car_into_wall(&s);
  if (!w) return;
  dm_body_state states[2];
  dm_loads loads[2];
  CHECK(dm_body_state_get(w, 0, &states[0]) == DM_OK && dm_body_state_get(w, 1, &states[1]) == DM_OK);
  /* the host: planar semi-implicit Euler on the car, the wall held */
  double impulse = 0.0;
  for (int step = 0; step < 600; ++step) {
    CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_OK);
    impulse += loads[0].force_earth[0] * 0.0005;
    states[0].velocity[0] += loads[0].force_earth[0] / 1500.0 * 0.0005;
    states[0].position[0] += states[0].velocity[0] * 0.0005;
  }
  CHECK(dm_world_host_finish(w, states, 2) == DM_OK);
  CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_ERROR_STATE);
  /* the engine's delta-V is the host's: impulse / m (SI world: m/s) */
  double dv[3];
  CHECK(dm_body_delta_v(w, 0, dv) == DM_OK);
  CHECK(fabs(dv[0] - impulse / 1500.0) < 1e-9 * 13.4);
  CHECK(dv[0] < -13.4 && dv[0] > -2 * 13.4); /* stopped and rebounded */
  const char* text = NULL;
  CHECK(dm_world_summary_json(w, &text) == DM_OK && contains(text, "\"name\": \"car\""));
  printf("force provider: delta-V %.3f m/s\n", dv[0]);
  dm_world_destroy(w);
}

/* the final state of a box car coasting clear of a fixed wall (no contact), set off at 1 m/s along x,
   `down` m/s down and pitching at 0.5 rad/s; its description `struct_size` bytes long, with `motion` */
static dm_body_state coast(size_t struct_size, int32_t motion, double down) {
  car_and_wall s;
  make_car_and_wall(&s, (dm_body_state){{0, 0, 0}, 0, 0, 0, {1.0, 0, down}, {0, 0.5, 0}}, 20.0, motion);
  /* an older caller's array: elements struct_size bytes apart */
  unsigned char packed[2 * sizeof(dm_body_desc)];
  for (int i = 0; i < 2; ++i) {
    s.bodies[i].struct_size = struct_size;
    memcpy(packed + i * struct_size, &s.bodies[i], struct_size);
  }
  dm_world_desc desc = {.struct_size = sizeof(dm_world_desc), .time_step = 0.0005, .duration = 0.1, .stop_at_separation = 0, .passes_per_step = 2};
  dm_body_state end;
  memset(&end, 0, sizeof end);
  dm_world* w = NULL;
  CHECK(dm_world_create(&desc, (const dm_body_desc*)packed, 2, &w) == DM_OK);
  if (!w) return end;
  CHECK(dm_world_run(w) == DM_OK);
  CHECK(dm_body_state_get(w, 0, &end) == DM_OK);
  dm_world_destroy(w);
  return end;
}

/* the motion model of a body built from arrays: planar by default (and for a caller whose struct
   ends before `motion`), free on request; bad values refused */
static void test_motion(void) {
  /* free, no loads: x, z and pitch all grow linearly, so z / x = 0.2 and pitch / x = 0.5 (1e-9:
     round-off of a constant-rate integration) */
  const dm_body_state free6 = coast(sizeof(dm_body_desc), DM_MOTION_FREE, 0.2);
  CHECK(free6.position[0] > 0.09);
  CHECK(fabs(free6.position[2] / free6.position[0] - 0.2) < 1e-9);
  CHECK(fabs(free6.pitch / free6.position[0] - 0.5) < 1e-9);
  CHECK(fabs(free6.omega[1] - 0.5) < 1e-12);
  /* planar (the default, and an older caller's struct whatever lies beyond it): height and pitch held
     (a vertical velocity is refused below) */
  const dm_body_state planar = coast(sizeof(dm_body_desc), DM_MOTION_DEFAULT, 0.0);
  const dm_body_state older = coast(offsetof(dm_body_desc, motion), DM_MOTION_FREE, 0.0);
  CHECK(planar.position[0] == free6.position[0]);
  CHECK(planar.position[2] == 0.0 && planar.pitch == 0.0 && planar.omega[1] == 0.0);
  CHECK(memcmp(&planar, &older, sizeof planar) == 0);
  CHECK(memcmp(&planar, &(dm_body_state){0}, sizeof planar) != 0);
  /* a bad motion, and a fixed body asked to move */
  double v[24];
  int32_t t[36];
  make_box(1, 1, 1, v, t);
  dm_body_desc bad[2];
  memset(bad, 0, sizeof bad);
  bad[0] = (dm_body_desc){sizeof(dm_body_desc), "a", v, 8, t, 12, 1.0, {1, 1, 1}, 1e5, 1e6, 0, 0, 0, 0,
                          {{0, 0, 0}, 0, 0, 0, {0, 0, 0}, {0, 0, 0}}, 7};
  bad[1] = bad[0];
  bad[1].name = "b";
  bad[1].initial.position[0] = 5.0;
  dm_world_desc desc = wall_run_desc();
  dm_world* w = NULL;
  CHECK(dm_world_create(&desc, bad, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].motion"));
  bad[0].motion = DM_MOTION_DEFAULT;
  bad[1].fixed = 1;
  bad[1].motion = DM_MOTION_FREE;
  CHECK(dm_world_create(&desc, bad, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].motion: a fixed body"));
  /* a fixed body given a velocity: refused as for a scenario file */
  bad[1].motion = DM_MOTION_DEFAULT;
  bad[1].initial.velocity[0] = 1.0;
  CHECK(dm_world_create(&desc, bad, 2, &w) == DM_ERROR_INPUT &&
        contains(dm_last_error(), "bodies[1].initial: a body with motion \"fixed\" does not move"));
  CHECK(w == NULL);
}

/* a world from arrays is held to a scenario file's checks (found by a fuzz of the C ABI, 2026-11-28:
   each of these was accepted, or crashed) */
static void test_create_checks(void) {
  car_and_wall s;
  dm_world_desc desc = wall_run_desc();
  dm_world* w = NULL;
  /* a struct_size far beyond any dm_body_desc was taken as the stride and read past the array */
  make_car_at_wall(&s);
  s.bodies[0].struct_size = s.bodies[1].struct_size = (size_t)1 << 40;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].struct_size"));
  /* names become output file names: a path or a name used twice would write outside or overwrite */
  make_car_at_wall(&s);
  s.bodies[0].name = "../escaped";
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].name: expected a name usable in file names"));
  s.bodies[0].name = "wall";
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].name: duplicate body name \"wall\""));
  /* a planar body's vertical velocity would be dropped */
  make_car_and_wall(&s, (dm_body_state){{0, 0, 0}, 0, 0, 0, {13.4, 0, 5.0}, {0, 0, 0}}, 2.76, DM_MOTION_PLANAR);
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].initial.velocity[2]: a planar body holds its height"));
  /* values outside their physical ranges (README "Physical ranges") */
  make_car_at_wall(&s);
  s.bodies[0].mass = 1e300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].mass: expected a physically possible mass"));
  s.bodies[0].mass = 1500.0;
  s.bodies[0].friction = 1e300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].friction"));
  s.bodies[0].friction = 0.0;
  s.bodies[0].inertia[2] = 1e-300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].inertia[2]: expected a physically possible radius of gyration"));
  s.bodies[0].inertia[2] = 2700.0;
  s.bodies[0].initial.velocity[0] = 1e5;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].initial.velocity: expected a physically possible speed"));
  s.bodies[0].initial.velocity[0] = 13.4;
  s.bodies[0].initial.yaw = 1e300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].initial.yaw"));
  /* a mesh of no size, and a deformable one that encloses no volume (a flat box) */
  make_car_at_wall(&s);
  for (int k = 0; k < 24; ++k) s.car_v[k] = 0.25;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].vertices: expected a physically possible body size"));
  make_box(4.5, 1.7, 0.0, s.car_v, s.car_t);
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_INPUT && contains(dm_last_error(), "must enclose a volume"));
  /* a run of a billion steps would fill the memory with its history */
  make_car_at_wall(&s);
  desc.duration = 1e9;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.duration"));
  desc.duration = 1e3;
  desc.time_step = 1e-5;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "at most 1e7 steps"));
  CHECK(w == NULL);
  /* an implausible value is accepted and warned, as in a scenario file */
  desc.duration = 0.3;
  desc.time_step = 0.0005;
  s.bodies[0].friction = 2.0;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_OK);
  const char* text = NULL;
  CHECK(dm_world_summary_json(w, &text) == DM_OK && contains(text, "implausible_value") && contains(text, "bodies[0].friction"));
  dm_world_destroy(w);
}

/* a world is driven one way, and a summary view outlives calls that do not change the world */
static void test_states(void) {
  car_and_wall s;
  dm_world* w = car_into_wall(&s);
  if (!w) return;
  CHECK(dm_world_run(w) == DM_OK);
  const char* view = NULL;
  CHECK(dm_world_summary_json(w, &view) == DM_OK);
  char* kept = view ? strdup(view) : NULL;
  /* a second summary and a copy (even one refused for its size) leave the view as it was: it was
     freed by them before (valgrind: read of freed memory) */
  const char* again = NULL;
  char small[16];
  size_t needed = 0;
  CHECK(dm_world_summary_json(w, &again) == DM_OK && again == view);
  CHECK(dm_world_copy_summary_json(w, small, sizeof small, &needed) == DM_ERROR_ARGUMENT);
  CHECK(kept != NULL && strcmp(view, kept) == 0);
  free(kept);
  /* a finished run takes no more steps, of either kind */
  int32_t finished = 0;
  CHECK(dm_world_step(w, &finished) == DM_ERROR_STATE && finished == 1 && contains(dm_last_error(), "the run is finished"));
  CHECK(dm_world_run(w) == DM_ERROR_STATE);
  dm_world_destroy(w);
  /* a run stepped by its own integrator takes no host step, and a host-driven one no step of its own */
  dm_body_state states[2];
  dm_loads loads[2];
  w = car_into_wall(&s);
  CHECK(dm_world_step(w, &finished) == DM_OK && finished == 0);
  CHECK(dm_body_state_get(w, 0, &states[0]) == DM_OK && dm_body_state_get(w, 1, &states[1]) == DM_OK);
  CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_ERROR_STATE && contains(dm_last_error(), "stepped by its own integrator"));
  dm_world_destroy(w);
  w = car_into_wall(&s);
  CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_OK);
  CHECK(dm_world_host_step(w, states, 2, 1e300, loads) == DM_ERROR_ARGUMENT);
  CHECK(dm_world_step(w, &finished) == DM_ERROR_STATE && contains(dm_last_error(), "host-driven"));
  CHECK(dm_world_run(w) == DM_ERROR_STATE);
  dm_world_destroy(w);
}

/* the box car at 13.4 m/s into the wall with `desc`'s search; its delta-V along x [m/s] and its most
   crushed vertex's deformation (body axes); -1 / zeros when refused */
static double searched(const dm_world_desc* desc, int deformable_wall, double deformation[3]) {
  car_and_wall s;
  make_car_at_wall(&s);
  if (deformable_wall) s.bodies[1].rigid = 0, s.bodies[1].stiffness_a = 1.0e5, s.bodies[1].stiffness_b = 1.0e6;
  memset(deformation, 0, 3 * sizeof(double));
  dm_world* w = NULL;
  if (dm_world_create(desc, s.bodies, 2, &w) != DM_OK) return -1.0;
  CHECK(dm_world_run(w) == DM_OK);
  double dv[3];
  CHECK(dm_body_delta_v(w, 0, dv) == DM_OK);
  const double* delta = NULL;
  int32_t n = 0;
  CHECK(dm_body_deformation(w, 0, &delta, &n) == DM_OK);
  for (int v = 0; v < n; ++v)
    if (hypot(hypot(delta[3 * v], delta[3 * v + 1]), delta[3 * v + 2]) >
        hypot(hypot(deformation[0], deformation[1]), deformation[2]))
      memcpy(deformation, delta + 3 * v, 3 * sizeof(double));
  const char* text = NULL;
  CHECK(dm_world_summary_json(w, &text) == DM_OK);
  CHECK(contains(text, "passed_through") == (dv[0] == 0.0));
  const int shared = contains(text, "specified_direction_shared");
  CHECK(shared == (desc->search_direction == DM_SEARCH_SPECIFIED && deformable_wall));
  dm_world_destroy(w);
  return dv[0]; /* an SI world: m/s */
}

/* a world from arrays takes the scenario file's contact search and stop rule (appended 2026-11-28): an
   older caller's shorter struct runs with the defaults; every search stops the car as the barrier's
   closed form says; a specified direction pushes the crush along it; bad values refused */
static void test_search_options(void) {
  double crush[3];
  dm_world_desc desc = wall_run_desc();
  const double reference = searched(&desc, 0, crush);
  /* the older struct, garbage beyond its end: the defaults, bit for bit */
  unsigned char older[sizeof(dm_world_desc)];
  memset(older, 0x7f, sizeof older);
  dm_world_desc shorter = desc;
  shorter.struct_size = offsetof(dm_world_desc, search_direction);
  memcpy(older, &shorter, shorter.struct_size);
  CHECK(searched((const dm_world_desc*)older, 0, crush) == reference);
  /* a rigid wall, frictionless, e = 0.1 at the car: delta-V = -(1 + e) v = -14.74 m/s; 2 %: the 8-node car's
     rebound over a 0.5 ms step (the barrier validation row) */
  const int32_t searches[3] = {DM_SEARCH_VELOCITY, DM_SEARCH_LOCAL_AVERAGE_NORMAL, DM_SEARCH_POLY_NORMAL};
  const int32_t rules[3] = {DM_STOP_AFTER_ONE, DM_STOP_BEST_OF_TWO, DM_STOP_BEST_OF_ALL};
  for (int k = 0; k < 3; ++k) {
    desc.search_direction = searches[k];
    desc.stop_rule = rules[k];
    const double dv = searched(&desc, 0, crush);
    CHECK(fabs(dv + 1.1 * 13.4) < 0.02 * 1.1 * 13.4);
    CHECK(crush[0] < 0.0 && fabs(crush[1]) < 1e-9 * fabs(crush[0])); /* the front pushed back along x */
    printf("search %d, stop rule %d: delta-V %.4f m/s (closed form %.4f)\n", searches[k], rules[k], dv, -1.1 * 13.4);
  }
  /* specified: the direction each slave node looks along, in its body's axes. Along the car's -x it
     finds the wall as the velocity search does; along +x or sideways it never looks into the wall, so
     the car runs on through it with no force (the field reaches the engine; the run is marked
     passed_through), and against a deformable wall the specified direction is warned */
  desc.search_direction = DM_SEARCH_SPECIFIED;
  desc.stop_rule = DM_STOP_DEFAULT;
  desc.specified_direction[0] = -2.0;
  CHECK(fabs(searched(&desc, 0, crush) + 1.1 * 13.4) < 0.02 * 1.1 * 13.4);
  desc.specified_direction[0] = 0.0;
  desc.specified_direction[1] = -3.0;
  CHECK(searched(&desc, 0, crush) == 0.0);
  CHECK(searched(&desc, 1, crush) == 0.0);
  /* refused naming the field */
  dm_world* w = NULL;
  car_and_wall s;
  make_car_at_wall(&s);
  desc.specified_direction[1] = 0.0;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.specified_direction: expected a vector of nonzero length"));
  desc.search_direction = DM_SEARCH_VELOCITY;
  desc.specified_direction[2] = 1.0;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "acts only with DM_SEARCH_SPECIFIED"));
  desc.specified_direction[2] = 0.0;
  desc.search_direction = 9;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.search_direction"));
  desc.search_direction = DM_SEARCH_DEFAULT;
  desc.stop_rule = -1;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.stop_rule"));
  desc.stop_rule = DM_STOP_DEFAULT;
  desc.struct_size = 3;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.struct_size"));
  CHECK(w == NULL);
}

/* a definition struct's size taken (`accepted`) or refused naming `field` and the two published sizes */
static void check_size_verdict(dm_status status, int accepted, const char* field, size_t current, size_t first) {
  if (accepted) {
    CHECK(status == DM_OK);
    return;
  }
  char sizes[96];
  snprintf(sizes, sizeof sizes, "%zu (this header) or %zu", current, first);
  CHECK(status == DM_ERROR_ARGUMENT && contains(dm_last_error(), field) && contains(dm_last_error(), sizes));
}

/* the published sizes of the definition structs (found by a sweep of the C ABI, 2026-11-28: a size past
   sizeof, or one ending partway through a field, was taken and the bytes beyond it ignored or half read) */
static void test_struct_sizes(void) {
  car_and_wall s;
  make_car_at_wall(&s);
  dm_world* w = NULL;
  /* the world: this header's size and the first ABI's (before search_direction) are taken */
  unsigned char buffer[sizeof(dm_world_desc) + 16];
  const size_t world_sizes[] = {offsetof(dm_world_desc, search_direction), sizeof(dm_world_desc),
                                /* refused: */ 0, 12, offsetof(dm_world_desc, stop_rule),
                                offsetof(dm_world_desc, specified_direction) + 8, sizeof(dm_world_desc) + 8};
  for (int k = 0; k < 7; ++k) {
    dm_world_desc desc = {.struct_size = world_sizes[k], .time_step = 0.0005, .duration = 0.3, .stop_at_separation = 1, .passes_per_step = 2};
    memset(buffer, 0, sizeof buffer);
    memcpy(buffer, &desc, sizeof desc);
    check_size_verdict(dm_world_create((const dm_world_desc*)buffer, s.bodies, 2, &w), k < 2, "world.struct_size: expected",
                       sizeof(dm_world_desc), offsetof(dm_world_desc, search_direction));
    dm_world_destroy(w);
    w = NULL;
  }
  /* the bodies: this header's size and the first ABI's (before motion), elements that far apart */
  dm_world_desc desc = wall_run_desc();
  unsigned char packed[2 * (sizeof(dm_body_desc) + 16)];
  const size_t body_sizes[] = {offsetof(dm_body_desc, motion), sizeof(dm_body_desc),
                               /* refused: */ offsetof(dm_body_desc, motion) + 4, offsetof(dm_body_desc, initial),
                               sizeof(dm_body_desc) + 8, sizeof(dm_body_desc) + 16};
  for (int k = 0; k < 6; ++k) {
    memset(packed, 0, sizeof packed);
    for (int i = 0; i < 2; ++i) {
      dm_body_desc b = s.bodies[i];
      b.struct_size = body_sizes[k];
      memcpy(packed + i * body_sizes[k], &b, body_sizes[k] < sizeof b ? body_sizes[k] : sizeof b);
    }
    check_size_verdict(dm_world_create(&desc, (const dm_body_desc*)packed, 2, &w), k < 2, "bodies[0].struct_size: expected",
                       sizeof(dm_body_desc), offsetof(dm_body_desc, motion));
    dm_world_destroy(w);
    w = NULL;
  }
  /* one array, two sizes: the elements are bodies[0]'s size apart */
  s.bodies[1].struct_size = offsetof(dm_body_desc, motion);
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].struct_size: expected bodies[0]'s"));
  CHECK(w == NULL);
}

/* refusals name the field and what was expected, with short numbers (a sweep of the C ABI, 2026-11-28:
   "state of body 0 is not finite", a NaN duration "expected a duration >= the step", a 1e-300 step
   blamed on the duration with 300 digits, a roll rate called a yaw rate; a name not UTF-8 taken, its
   summary then failing with the JSON library's type_error.316; a fixed body's NaN mass taken) */
static void test_messages(void) {
  car_and_wall s;
  dm_world_desc desc = wall_run_desc();
  dm_world* w = NULL;
  make_car_at_wall(&s);
  s.bodies[0].initial.velocity[0] = NAN;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].initial.velocity[0]: expected a finite number, got nan"));
  s.bodies[0].initial.velocity[0] = 13.4;
  s.bodies[1].initial.yaw = -INFINITY;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].initial.yaw: expected a finite number, got -inf"));
  s.bodies[1].initial.yaw = 0.0;
  s.bodies[0].initial.omega[0] = 1e300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].initial.omega[0]: expected a physically possible roll rate") &&
        !contains(dm_last_error(), "yaw rate"));
  s.bodies[0].initial.omega[0] = 0.0;
  /* a fixed body's mass and inertia are not used, but a non-finite one is still a mistake */
  s.bodies[1].mass = NAN;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].mass: expected a finite number"));
  s.bodies[1].mass = 0.0;
  s.bodies[1].inertia[2] = INFINITY;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[1].inertia[2]: expected a finite number"));
  s.bodies[1].inertia[2] = 0.0;
  /* names: UTF-8 text, or refused before the summary needs them */
  const char* bad_names[] = {"\xff\xfe", "ab\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80"};
  for (int k = 0; k < 5; ++k) {
    s.bodies[0].name = bad_names[k];
    CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "bodies[0].name: expected UTF-8 text"));
  }
  s.bodies[0].name = "Citro\xc3\xabn C4 \xe2\x80\x93 \xf0\x9f\x9a\x97";
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_OK);
  const char* text = NULL;
  CHECK(dm_world_summary_json(w, &text) == DM_OK && contains(text, s.bodies[0].name));
  dm_world_destroy(w);
  w = NULL;
  s.bodies[0].name = "car";
  /* the world's times */
  desc.duration = NAN;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.duration: expected a finite duration"));
  desc.duration = 0.3;
  desc.time_step = 2.0;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.time_step: expected a step no longer than world.duration (0.3 s), got 2 s"));
  desc.time_step = 1e-300;
  CHECK(dm_world_create(&desc, s.bodies, 2, &w) == DM_ERROR_ARGUMENT && contains(dm_last_error(), "world.time_step: expected at most 1e7 steps") &&
        strlen(dm_last_error()) < 200);
  desc.time_step = 0.0005;
  CHECK(w == NULL);
  /* a copy's refusal is the copy's */
  char small[8];
  size_t needed = 0;
  CHECK(dm_world_copy_summary_json(NULL, small, sizeof small, &needed) == DM_ERROR_ARGUMENT &&
        contains(dm_last_error(), "dm_world_copy_summary_json: world is null"));
  w = car_into_wall(&s);
  CHECK(dm_world_copy_summary_json(w, small, sizeof small, &needed) == DM_ERROR_ARGUMENT &&
        contains(dm_last_error(), "dm_world_copy_summary_json: buffer of 8 bytes"));
  /* a host run ended before its first step (it reported "complete" with 0 steps) */
  dm_body_state states[2];
  dm_loads loads[2];
  CHECK(dm_body_state_get(w, 0, &states[0]) == DM_OK && dm_body_state_get(w, 1, &states[1]) == DM_OK);
  CHECK(dm_world_host_finish(w, states, 2) == DM_ERROR_STATE && contains(dm_last_error(), "dm_world_host_finish: no host step taken"));
  CHECK(dm_world_host_step(w, states, 2, 0.0005, loads) == DM_OK && dm_world_host_finish(w, states, 2) == DM_OK);
  dm_world_destroy(w);
}

/* a world run in one thread, and calls on it from another */
typedef struct running {
  dm_world* w;
  dm_status status;
  int done;
  pthread_mutex_t lock;
} running;

static void* run_world(void* arg) {
  running* r = arg;
  const dm_status status = dm_world_run(r->w);
  pthread_mutex_lock(&r->lock);
  r->status = status, r->done = 1;
  pthread_mutex_unlock(&r->lock);
  return NULL;
}

static int run_done(running* r) {
  pthread_mutex_lock(&r->lock);
  const int done = r->done;
  pthread_mutex_unlock(&r->lock);
  return done;
}

/* refused because another thread's call is under way on the same world */
static int busy(dm_status status) {
  return status == DM_ERROR_STATE && contains(dm_last_error(), "another call on this world is in progress");
}

/* one call at a time on a world: while one thread runs it, every call from another is refused (a
   sweep of the C ABI, 2026-11-28: a step beside a run corrupted the heap) and the run is as alone */
static void test_one_call_at_a_time(const char* scenario, const char* work) {
  dm_world* alone = NULL;
  uint64_t expected = 0, hash = 0;
  CHECK(dm_world_load_scenario(scenario, &alone) == DM_OK && dm_world_run(alone) == DM_OK &&
        dm_world_state_hash(alone, &expected) == DM_OK);
  dm_world_destroy(alone);
  int conclusive = 0;
  /* the calls are made while the run lasts (0.3 s; a few microseconds for the calls), once it has
     begun (20 ms after its thread started; a call of this thread as it begins would refuse it): tried
     again should a loaded machine stall either thread */
  for (int attempt = 0; attempt < 5 && !conclusive; ++attempt) {
    running r = {NULL, DM_OK, 0, PTHREAD_MUTEX_INITIALIZER};
    CHECK(dm_world_load_scenario(scenario, &r.w) == DM_OK);
    if (!r.w) return;
    char dir[8192];
    struct stat made;
    for (int k = 0; k == 0 || stat(dir, &made) == 0; ++k) /* a folder no earlier attempt made */
      snprintf(dir, sizeof dir, "%s/while_running_%d", work, k);
    pthread_t thread;
    CHECK(pthread_create(&thread, NULL, run_world, &r) == 0);
    const struct timespec begun = {0, 20000000};
    nanosleep(&begun, NULL);
    double t = 0.0;
    int refused = 0;
    if (busy(dm_world_time(r.w, &t))) {
      int32_t finished = 0, count = 0;
      dm_body_state states[2];
      dm_loads loads[2];
      double dv[3];
      const char* text = NULL;
      char small[8];
      size_t needed = 0;
      memset(states, 0, sizeof states);
      refused += busy(dm_world_step(r.w, &finished));
      refused += busy(dm_world_run(r.w));
      refused += busy(dm_world_host_step(r.w, states, 2, 0.0005, loads));
      refused += busy(dm_world_host_finish(r.w, states, 2));
      refused += busy(dm_world_write_outputs(r.w, dir));
      refused += busy(dm_world_summary_json(r.w, &text));
      refused += busy(dm_world_copy_summary_json(r.w, small, sizeof small, &needed));
      refused += busy(dm_body_delta_v(r.w, 0, dv));
      refused += busy(dm_body_state_get(r.w, 0, &states[0]));
      refused += busy(dm_body_copy_crush(r.w, 0, dv, 0, &count));
      refused += busy(dm_world_state_hash(r.w, &hash));
      conclusive = busy(dm_world_time(r.w, &t)) && !run_done(&r);
    }
    pthread_join(thread, NULL);
    if (conclusive) {
      CHECK(r.status == DM_OK);
      CHECK(refused == 11);
      CHECK(stat(dir, &made) != 0); /* the refused write made no folder */
      CHECK(dm_world_state_hash(r.w, &hash) == DM_OK && hash == expected);
    }
    dm_world_destroy(r.w);
  }
  CHECK(conclusive);
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: c_api_test DATA_DIR DYMESH_CLI WORK_DIR\n");
    return 2;
  }
  char scenario[4096];
  snprintf(scenario, sizeof scenario, "%s/scenarios/barrier_frontal.json", argv[1]);
  test_arguments(scenario);
  test_world_mode(scenario, argv[2], argv[3]);
  test_threads(scenario);
  test_force_provider();
  test_winding();
  test_motion();
  test_create_checks();
  test_states();
  test_search_options();
  test_struct_sizes();
  test_messages();
  test_one_call_at_a_time(scenario, argv[3]);
  if (failures) fprintf(stderr, "%d checks failed\n", failures);
  return failures ? 1 : 0;
}
