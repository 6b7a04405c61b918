#pragma once
// The arguments of one UMAT call (README.md, "UMAT"), shared by the material (user_material.cpp) and the tangent
// check (umat_tangent_check.cpp).
#include <cstdint>
#include <vector>

#include "mpm/user_material/abaqus_abi.hpp"
#include "mpm/user_material/corotational.hpp"
#include "mpm/user_material/user_material.hpp"

namespace mpm::user_material {

/// A 3x3 matrix into a Fortran (column-major) array.
inline void store_column_major(const Mat3& m, Real* a) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r + 3 * c] = m(r, c);
}

/// The arguments of one UMAT call (README.md, "UMAT"), made from a point's kinematics and record.
struct UmatCall {
  int ndi = 3, nshr = 3, ntens = 6, nstatv = 0, nprops = 0, noel = 1, npt = 1, layer = 1, kspt = 1, kstep = 1, kinc = 1;
  double stress[6] = {}, stran[6] = {}, dstran[6] = {}, ddsdde[36] = {}, sse = 0, spd = 0, scd = 0, rpl = 0;
  double ddsddt[6] = {}, drplde[6] = {}, drpldt = 0, pnewdt = 1, time[2] = {0, 0}, dtime = 0, temp = 0, dtemp = 0;
  double predef = 0, dpred = 0, coords[3] = {}, drot[9] = {}, celent = 0, dfgrd0[9] = {}, dfgrd1[9] = {};
  std::vector<double> statev;
  Mat3 strain_rotated, strain_increment;  ///< STRAN and DSTRAN as tensors (for the record of the next step)

  UmatCall(int dim, const PointKinematics& pt, const UserPointState& st, std::uint32_t id, Real dt) {
    nshr = dim == 3 ? 3 : 1;
    ntens = ndi + nshr;
    const Mat3 dR = pt.R_new * pt.R_old.transpose();
    const Mat3 sigma = dR * pt.stress_old * dR.transpose();
    strain_rotated = dR *
                     symmetric_from(
                         umat_pairs, 6, [&](int k) { return st.strain[k]; }, 2) *
                     dR.transpose();
    strain_increment = pt.D * dt;
    for (int k = 0; k < ntens; ++k) {
      const Real shear = k < 3 ? 1 : 2;
      stress[k] = sigma(umat_pairs[k][0], umat_pairs[k][1]);
      stran[k] = shear * strain_rotated(umat_pairs[k][0], umat_pairs[k][1]);
      dstran[k] = shear * strain_increment(umat_pairs[k][0], umat_pairs[k][1]);
    }
    store_column_major(dR, drot);
    store_column_major(pt.F_old, dfgrd0);
    store_column_major(pt.F_new, dfgrd1);
    sse = st.energy[0];
    spd = st.energy[1];
    scd = st.energy[2];
    time[0] = time[1] = st.time;
    dtime = dt;
    temp = pt.temperature;
    for (int c = 0; c < 3; ++c) coords[c] = pt.x[c];
    celent = pt.length;
    noel = static_cast<int>(id) + 1;
    kinc = static_cast<int>(st.increments) + 1;
  }

  /// Calls the UMAT of `plugin` with these arguments (they become its results).
  void call(const Plugin& plugin) {
    nstatv = static_cast<int>(statev.size());
    nprops = static_cast<int>(plugin.spec.properties.size());
    if (statev.empty()) statev.push_back(0);  // a valid address for NSTATV = 0
    const double* props = nprops ? plugin.spec.properties.data() : &predef;
    reinterpret_cast<UmatFunction>(plugin.entry)(
        stress, statev.data(), ddsdde, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran, time, &dtime,
        &temp, &dtemp, &predef, &dpred, plugin.cmname.data(), &ndi, &nshr, &ntens, &nstatv, props, &nprops, coords,
        drot, &pnewdt, &celent, dfgrd0, dfgrd1, &noel, &npt, &layer, &kspt, &kstep, &kinc, cmname_length);
    statev.resize(static_cast<std::size_t>(nstatv));
  }
};

}  // namespace mpm::user_material
