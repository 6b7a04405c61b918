/* A plugin of the C interface that is not objective, for `mpm material-test --check` (tests/user_material): linear
 * elasticity of the small strain sym(F) - 1 of the global F, returned as if it were the corotational stress. A rigid
 * rotation Q makes sym(Q F) - 1 a strain, so the stress invariants change. props: E (Pa), nu. */
#include "mpm_user_material.h"

int mpm_user_material_abi_version(void) { return MPM_USER_MATERIAL_ABI_VERSION; }

int mpm_user_material_update(mpm_user_material_block* b) {
  const double E = b->props[0], nu = b->props[1];
  const double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  static const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int i = 0; i < b->n; ++i) {
    const double* F = b->F_new + 9 * i;
    double e[6];
    for (int c = 0; c < 6; ++c) {
      const int r = pairs[c][0], k = pairs[c][1];
      e[c] = 0.5 * (F[3 * r + k] + F[3 * k + r]) - (c < 3 ? 1 : 0);
    }
    const double tr = e[0] + e[1] + e[2];
    for (int c = 0; c < 6; ++c) b->stress_new[6 * i + c] = 2 * G * e[c] + (c < 3 ? lambda * tr : 0);
  }
  return MPM_USER_MATERIAL_OK;
}
