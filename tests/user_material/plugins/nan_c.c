/* A broken plugin of the C interface for the failure tests (tests/user_material): elastic in shear until its time
 * passes props[0] (s), then stresses that are not numbers. */
#include <math.h>

#include "mpm_user_material.h"

int mpm_user_material_abi_version(void) { return MPM_USER_MATERIAL_ABI_VERSION; }

int mpm_user_material_update(mpm_user_material_block* b) {
  const double G = 1.0e6;
  for (int i = 0; i < b->n; ++i)
    for (int c = 0; c < 6; ++c)
      b->stress_new[6 * i + c] =
          b->time > b->props[0] ? NAN : b->stress_old[6 * i + c] + 2 * G * b->strain_increment[6 * i + c];
  return MPM_USER_MATERIAL_OK;
}
