/* A C host: checks the ABI version, builds a box car and a fixed wall from arrays, runs the world,
 * prints the car's delta-V. Exits 0 when the car stopped and rebounded (delta-V between v and 2v). */
#include <stdio.h>

#include "dymesh/dymesh.h"

/* a closed box about the origin: 8 vertices, 12 triangles wound outward */
static void box(double lx, double ly, double lz, double v[24]) {
  for (int i = 0; i < 8; ++i) {
    v[3 * i] = (i & 1 ? 0.5 : -0.5) * lx;
    v[3 * i + 1] = (i & 2 ? 0.5 : -0.5) * ly;
    v[3 * i + 2] = (i & 4 ? 0.5 : -0.5) * lz;
  }
}

int main(void) {
  static const int32_t faces[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                    2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  if (dm_abi_version() != DM_ABI_VERSION) return 1;
  double car[24], wall[24];
  box(4.5, 1.7, 0.8, car);
  box(1.0, 10.0, 2.5, wall);
  dm_body_desc bodies[2] = {
      {sizeof(dm_body_desc), "car", car, 8, faces, 12, 1500.0, {400, 2500, 2700}, 1.0e5, 1.0e6, 0.1, 0.0, 0, 0,
       {{0, 0, 0}, 0, 0, 0, {13.4, 0, 0}, {0, 0, 0}}, DM_MOTION_PLANAR},
      {sizeof(dm_body_desc), "wall", wall, 8, faces, 12, 0.0, {0, 0, 0}, 0.0, 0.0, 0.1, 0.0, 1, 1,
       {{2.76, 0, 0}, 0, 0, 0, {0, 0, 0}, {0, 0, 0}}, DM_MOTION_DEFAULT}};
  dm_world_desc desc = {.struct_size = sizeof(dm_world_desc), .time_step = 0.0005, .duration = 0.3,
                        .stop_at_separation = 1, .passes_per_step = 2};
  dm_world* w = NULL;
  double dv[3];
  if (dm_world_create(&desc, bodies, 2, &w) != DM_OK || dm_world_run(w) != DM_OK || dm_body_delta_v(w, 0, dv) != DM_OK) {
    fprintf(stderr, "error: %s\n", dm_last_error());
    dm_world_destroy(w);
    return 1;
  }
  printf("C consumer: delta-V %.3f m/s\n", dv[0]);
  dm_world_destroy(w);
  return dv[0] < -13.4 && dv[0] > -26.8 ? 0 : 1;
}
