/* A plugin of the C interface that refuses its properties (tests/user_material): the error code and the message
 * must reach the user with the material, the library and the point. */
#include <stdio.h>

#include "mpm_user_material.h"

int mpm_user_material_abi_version(void) { return MPM_USER_MATERIAL_ABI_VERSION; }

int mpm_user_material_update(mpm_user_material_block* b) {
  snprintf(b->message, sizeof b->message, "expected 3 properties, got %d", b->nprops);
  b->failed_point = b->n - 1;
  return MPM_USER_MATERIAL_BAD_PROPERTIES;
}
