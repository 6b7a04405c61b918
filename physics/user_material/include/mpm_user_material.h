/* mpm_user_material.h — the C interface of the `mpm` program's user materials (`model: user`, `interface: c`).
 *
 * A plugin is a shared library (.so) that defines two functions with C linkage:
 *
 *   int mpm_user_material_abi_version(void);                  returns MPM_USER_MATERIAL_ABI_VERSION
 *   int mpm_user_material_update(mpm_user_material_block* b); updates the points of one block, returns
 *                                                             MPM_USER_MATERIAL_OK or an error code
 *
 * (the second one's name can be changed with the scene key `symbol:`). The program loads the library with
 * dlopen(RTLD_NOW | RTLD_LOCAL) when the scene is built, checks the version, and calls the update once per block of
 * at most MPM_USER_MATERIAL_MAX_BLOCK points per step.
 *
 * Conventions (physics/user_material/README.md says more):
 *   - SI units (Pa, s, kg/m^3, J/kg) unless the scene's numbers are in others: the program never converts props.
 *   - Tensors are 3x3 whatever the dimension of the run (2D plane strain: F_zz = 1; axisymmetric: r, z, theta with
 *     F_33 = F_theta_theta the hoop stretch; 1D: uniaxial strain, F_22 = F_33 = 1).
 *   - Point-major storage: point i's values are contiguous. A full 3x3 matrix is 9 numbers in row-major order
 *     (F11, F12, F13, F21, ..., F33); a symmetric tensor is 6 numbers in the order 11, 22, 33, 12, 23, 31 (tensor
 *     shear components, not engineering ones: the order and meaning of Abaqus' VUMAT).
 *   - Stresses and the strain increment are in the corotational frame of the Green-Naghdi rotation R of F = R U
 *     (the frame of Abaqus' VUMAT): stress_old = R_old^T sigma_old R_old, and the program turns stress_new back
 *     into the Cauchy stress R_new stress_new R_new^T. Cauchy stress, tension positive.
 *   - strain_increment = R_new^T sym(L) R_new dt (L the velocity gradient of the step), the same as the VUMAT's
 *     strainInc.
 *   - Energies are per unit mass (J/kg): internal (stress power, elastic and inelastic) and inelastic (dissipated).
 *     The program books m (internal - inelastic) as strain energy and m inelastic as dissipated energy. A plugin
 *     that does not compute them leaves the *_new values as they are given (equal to the old ones).
 *   - Threads: the program calls the update from several threads at once, on different blocks. It must be
 *     reentrant: no static or global variables that it writes.
 *   - The update must not keep any pointer of the block after it returns.
 *
 * Error codes: a non-zero return stops the run with an error that names the material, the library, the code, the
 * point `failed_point` (an index in the block; -1: none in particular) and `message` (a C string the plugin may
 * write, at most MPM_USER_MATERIAL_MESSAGE_SIZE bytes with its terminating 0).
 */
#ifndef MPM_USER_MATERIAL_H
#define MPM_USER_MATERIAL_H

#ifdef __cplusplus
extern "C" {
#endif

/** The version of this interface; a plugin built against another version is refused. */
#define MPM_USER_MATERIAL_ABI_VERSION 1
/** The most points one call receives. */
#define MPM_USER_MATERIAL_MAX_BLOCK 136
/** Bytes of the message buffer, including the terminating 0. */
#define MPM_USER_MATERIAL_MESSAGE_SIZE 256

/** Return codes of mpm_user_material_update. Any other non-zero value is reported as it is. */
enum {
  MPM_USER_MATERIAL_OK = 0,
  MPM_USER_MATERIAL_ERROR = 1,          /**< a failure the message explains */
  MPM_USER_MATERIAL_BAD_PROPERTIES = 2, /**< props (or their number) not what the plugin expects */
  MPM_USER_MATERIAL_BAD_STATE = 3       /**< state variables (or their number) not what the plugin expects */
};

/** One block of material points. Arrays marked "n x k" hold k values per point, point after point. */
typedef struct mpm_user_material_block {
  int abi_version;                   /**< MPM_USER_MATERIAL_ABI_VERSION */
  int n;                             /**< points in this block, 1 .. MPM_USER_MATERIAL_MAX_BLOCK */
  int dimension;                     /**< 1, 2 or 3: the run's dimension (tensors are 3x3 all the same) */
  int axisymmetric;                  /**< 1 for an axisymmetric body (component 3 is the hoop direction), else 0 */
  int nprops;                        /**< number of props */
  int nstatev;                       /**< state variables per point */
  const char* name;                  /**< the material's name in the scene (or its `name:` key), 0-terminated */
  double dt;                         /**< time increment, s */
  double time;                       /**< time at the end of the increment, s (> 0) */
  const double* props;               /**< nprops: the scene's `properties` */
  const double* density;             /**< n: current density rho0 / det F, kg/m^3 */
  const double* coordinates;         /**< n x 3: the points' positions (padded with 0), m */
  const double* char_length;         /**< n: the points' size (current volume^(1/dimension)), m */
  const double* temperature;         /**< n: temperature, K (the thermal field; 0 when no module tracks it) */
  const double* F_old;               /**< n x 9: deformation gradient at the start of the increment */
  const double* F_new;               /**< n x 9: deformation gradient at the end of the increment */
  const double* stretch_old;         /**< n x 6: U of F_old = R_old U_old */
  const double* stretch_new;         /**< n x 6: U of F_new = R_new U_new */
  const double* rotation_new;        /**< n x 9: R_new (row-major): what turns the corotational frame into the global */
  const double* strain_increment;    /**< n x 6: R_new^T sym(L) R_new dt, tensor shear components */
  const double* stress_old;          /**< n x 6: corotational Cauchy stress at the start, Pa */
  double* stress_new;                /**< n x 6: out: corotational Cauchy stress at the end, Pa (given: stress_old) */
  const double* state_old;           /**< n x nstatev: state variables at the start */
  double* state_new;                 /**< n x nstatev: out: at the end (given: state_old) */
  const double* energy_internal_old; /**< n: internal energy per unit mass at the start, J/kg */
  double* energy_internal_new;       /**< n: out: at the end (given: the old value) */
  const double* energy_inelastic_old; /**< n: dissipated (inelastic) energy per unit mass at the start, J/kg */
  double* energy_inelastic_new;       /**< n: out: at the end (given: the old value) */
  int failed_point; /**< out: the point an error is about (index in the block), -1 when none (given: -1) */
  char message[MPM_USER_MATERIAL_MESSAGE_SIZE]; /**< out: an error message (given: empty) */
} mpm_user_material_block;

/** The interface version the plugin was built with: return MPM_USER_MATERIAL_ABI_VERSION. */
int mpm_user_material_abi_version(void);
/** Updates the points of one block (see the conventions above). */
int mpm_user_material_update(mpm_user_material_block* block);

#ifdef __cplusplus
}
#endif

#endif /* MPM_USER_MATERIAL_H */
