/* J2 plasticity with linear isotropic hardening through the program's C interface (mpm_user_material.h): the law of
 * the built-in `j2_plasticity` (physics/plasticity, voce_saturation_stress 0, no damage, no temperature), as
 * j2_vumat.f90 writes it, for users who write C or C++.
 *
 *   s_trial = dev(stress_old) + 2 G dev(strain_increment)     (corotational frame)
 *   sigma_f = sigma_y + H eps_p;  radial return;  p = K (1 - det F_new);  stress_new = s - p 1
 *
 * props: E (Pa), nu, sigma_y (Pa), H (Pa). State: 1 equivalent plastic strain, 2 plastic work per reference volume
 * (J/m^3). Energies per unit mass as j2_vumat.f90.
 *
 * Build: gcc -shared -fPIC -O2 -I ../../physics/user_material/include j2_c.c -o libj2_c.so
 * Reentrant: it keeps nothing between calls. */
#include <math.h>
#include <stdio.h>

#include "mpm_user_material.h"

int mpm_user_material_abi_version(void) { return MPM_USER_MATERIAL_ABI_VERSION; }

int mpm_user_material_update(mpm_user_material_block* b) {
  if (b->nprops != 4) {
    snprintf(b->message, sizeof b->message, "expected 4 properties (E, nu, sigma_y, H), got %d", b->nprops);
    return MPM_USER_MATERIAL_BAD_PROPERTIES;
  }
  if (b->nstatev < 2) {
    snprintf(b->message, sizeof b->message, "expected 2 state variables (eps_p, plastic work), got %d", b->nstatev);
    return MPM_USER_MATERIAL_BAD_STATE;
  }
  const double E = b->props[0], nu = b->props[1], sy = b->props[2], H = b->props[3];
  /* the elastic constants as the program computes them (ElasticConstants::from_young_poisson) */
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double G = E / (2 * (1 + nu));
  const double K = lambda + 2 * G / 3;
  for (int i = 0; i < b->n; ++i) {
    const double* so = b->stress_old + 6 * i;
    const double* de_in = b->strain_increment + 6 * i;
    const double* F = b->F_new + 9 * i; /* row-major */
    const double* state_old = b->state_old + (long)b->nstatev * i;
    double* state_new = b->state_new + (long)b->nstatev * i;
    double* sn = b->stress_new + 6 * i;
    double s[6], de[6];
    for (int c = 0; c < 6; ++c) {
      s[c] = so[c];
      de[c] = de_in[c];
    }
    double mean = (s[0] + s[1] + s[2]) * (1.0 / 3);
    for (int c = 0; c < 3; ++c) s[c] -= mean;
    mean = (de[0] + de[1] + de[2]) * (1.0 / 3);
    for (int c = 0; c < 3; ++c) de[c] -= mean;
    for (int c = 0; c < 6; ++c) s[c] += 2 * G * de[c];
    const double eq =
        sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
    const double sf = sy + H * state_old[0];
    double dep = 0;
    if (eq > sf) {
      dep = (eq - sf) / (3 * G);
      const double scale = sf / eq;
      for (int c = 0; c < 6; ++c) s[c] *= scale;
    }
    const double J =
        F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
    const double p = K * (1 - J);
    for (int c = 0; c < 6; ++c) sn[c] = c < 3 ? s[c] - p : s[c];
    state_new[0] = state_old[0] + dep;
    state_new[1] = state_old[1] + J * sf * dep;
    double power = 0;
    for (int c = 0; c < 6; ++c) power += (c < 3 ? 1 : 2) * (so[c] + sn[c]) * de_in[c];
    b->energy_internal_new[i] = b->energy_internal_old[i] + 0.5 * power / b->density[i];
    b->energy_inelastic_new[i] = b->energy_inelastic_old[i] + sf * dep / b->density[i];
  }
  return MPM_USER_MATERIAL_OK;
}
