/* A plugin built for another version of the C interface (tests/user_material): refused when the scene is read. */
#include "mpm_user_material.h"

int mpm_user_material_abi_version(void) { return MPM_USER_MATERIAL_ABI_VERSION + 1; }
int mpm_user_material_update(mpm_user_material_block* b) { return b ? 0 : 1; }
