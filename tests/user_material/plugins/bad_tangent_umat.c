/* A UMAT (written in C with the Fortran calling convention: symbol umat_, every argument by reference, CMNAME's
 * length last) whose tangent is wrong, for `mpm material-test --check` (tests/user_material): isotropic hypoelastic,
 * STRESS += C DSTRAN with C's shear entries G (engineering shear strains), but DDSDDE reports 2G there, the classic
 * slip between tensor and engineering shear. props: E (Pa), nu. */
#include <stddef.h>

void umat_(double* stress, double* statev, double* ddsdde, double* sse, double* spd, double* scd, double* rpl,
           double* ddsddt, double* drplde, double* drpldt, const double* stran, const double* dstran,
           const double* time, const double* dtime, const double* temp, const double* dtemp, const double* predef,
           const double* dpred, const char* cmname, const int* ndi, const int* nshr, const int* ntens,
           const int* nstatv, const double* props, const int* nprops, const double* coords, const double* drot,
           double* pnewdt, const double* celent, const double* dfgrd0, const double* dfgrd1, const int* noel,
           const int* npt, const int* layer, const int* kspt, const int* kstep, const int* kinc, size_t cmname_len) {
  (void)statev, (void)sse, (void)spd, (void)scd, (void)rpl, (void)ddsddt, (void)drplde, (void)drpldt, (void)stran;
  (void)time, (void)dtime, (void)temp, (void)dtemp, (void)predef, (void)dpred, (void)cmname, (void)ndi, (void)nshr;
  (void)nstatv, (void)nprops, (void)coords, (void)drot, (void)pnewdt, (void)celent, (void)dfgrd0, (void)dfgrd1;
  (void)noel, (void)npt, (void)layer, (void)kspt, (void)kstep, (void)kinc, (void)cmname_len;
  const int n = *ntens;
  const double E = props[0], nu = props[1];
  const double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) ddsdde[a + n * b] = 0;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) ddsdde[a + n * b] = lambda;
    ddsdde[a + n * a] += 2 * G;
  }
  for (int a = 3; a < n; ++a) ddsdde[a + n * a] = G;
  double d[6];
  for (int a = 0; a < n; ++a) {
    d[a] = 0;
    for (int b = 0; b < n; ++b) d[a] += ddsdde[a + n * b] * dstran[b];
  }
  for (int a = 0; a < n; ++a) stress[a] += d[a];
  for (int a = 3; a < n; ++a) ddsdde[a + n * a] = 2 * G; /* the bug: the tangent of tensor shear strains */
}
