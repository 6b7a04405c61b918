// The UMAT tangent check (umat_tangent_check.hpp): the arguments of each step made as the material makes them
// (UserMaterial::kinematics_of, UmatCall), the UMAT called on copies of them, then the step committed through the
// material itself.
#include "mpm/user_material/umat_tangent_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "umat_call.hpp"

namespace mpm::user_material {

TangentCheck check_umat_tangent(UserMaterial<3>& material, const std::vector<std::pair<double, Mat3>>& path) {
  const Plugin& plugin = material.plugin();
  TangentCheck result;
  ParticleSet<3> p;
  p.add(Vec<3>::Zero(), 1, 1);
  material.prepare_particles(p);
  const std::vector<std::string>& names = plugin.spec.state_names;
  double t = 0;
  for (const auto& [time, F] : path) {
    const double dt = time - t;
    const Mat3 F_old = p.F[0];
    const MatU<3> L = (F * F_old.inverse() - Mat3::Identity()) / dt;
    p.F[0] = F;
    const PointKinematics pt = material.kinematics_of(p, 0, L, 1, 0, 0);
    const UserPointState& st = p.field(keys::user_point)[0];
    UmatCall base(3, pt, st, p.id[0], dt);
    for (std::size_t k = 0; k < names.size(); ++k) base.statev.push_back(p.field<Real>(state_field_name(k))[0]);
    UmatCall tangent = base;
    tangent.call(plugin);
    const int n = tangent.ntens;
    double scale = 0;
    for (int k = 0; k < n * n; ++k) scale = std::max(scale, std::abs(tangent.ddsdde[k]));
    const double h = 1e-7;
    for (int column = 0; column < n; ++column) {
      Mat3 E = Mat3::Zero();  // the tensor of DSTRAN's component `column`, for a unit engineering value
      const int r = umat_pairs[column][0], c = umat_pairs[column][1];
      E(r, c) = E(c, r) = column < 3 ? 1.0 : 0.5;
      double stress[2][6];
      for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? 1 : -1;
        UmatCall probe = base;
        probe.dstran[column] += sign * h;
        const Mat3 F_probe = (Mat3::Identity() + sign * h * E) * F;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) probe.dfgrd1[a + 3 * b] = F_probe(a, b);
        probe.call(plugin);
        std::copy(probe.stress, probe.stress + n, stress[side]);
      }
      double best = std::numeric_limits<double>::infinity();
      int best_row = 0;
      for (int variant = 0; variant < 3; ++variant) {  // central, forward, backward
        double worst = 0;
        int worst_row = 0;
        for (int row = 0; row < n; ++row) {
          const double fd = variant == 0   ? (stress[0][row] - stress[1][row]) / (2 * h)
                            : variant == 1 ? (stress[0][row] - tangent.stress[row]) / h
                                           : (tangent.stress[row] - stress[1][row]) / h;
          const double d = std::abs(tangent.ddsdde[row + n * column] - fd);
          if (d > worst) {
            worst = d;
            worst_row = row;
          }
        }
        if (worst < best) {
          best = worst;
          best_row = worst_row;
        }
      }
      const double relative = scale > 0 ? best / scale : best;
      if (!(relative <= result.difference)) {
        result.difference = relative;
        result.time = time;
        result.row = best_row + 1;
        result.column = column + 1;
      }
    }
    material.update_stress(p, 0, 1, &L, dt);
    ++result.steps;
    t = time;
  }
  return result;
}

}  // namespace mpm::user_material
