// The material `model: user` (user_material.hpp): the kinematics of each point (corotational.hpp), the arrays of
// the chosen interface filled from them, one call per block, the results checked and stored.
#include "mpm/user_material/user_material.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/user_material/abaqus_abi.hpp"
#include "mpm/user_material/corotational.hpp"
#include "mpm_user_material.h"
#include "umat_call.hpp"

namespace mpm::user_material {

using CUpdateFunction = int (*)(mpm_user_material_block*);
using CVersionFunction = int (*)();

const char* interface_name(Interface interface) {
  switch (interface) {
    case Interface::vumat:
      return "vumat";
    case Interface::umat:
      return "umat";
    case Interface::c:
      return "c";
  }
  return "?";
}

const char* default_symbol(Interface interface) {
  switch (interface) {
    case Interface::vumat:
      return "vumat_";
    case Interface::umat:
      return "umat_";
    case Interface::c:
      return "mpm_user_material_update";
  }
  return "?";
}

std::string state_field_name(std::size_t k) { return fmt::format("sdv{}", k + 1); }

std::shared_ptr<const Plugin> Plugin::load(const UserMaterialSpec& spec) {
  auto plugin = std::make_shared<Plugin>();
  plugin->spec = spec;
  plugin->library = SharedLibrary::open(spec.library);
  plugin->entry = plugin->library->symbol(spec.symbol);
  if (spec.interface == Interface::c) {
    void* version = plugin->library->find("mpm_user_material_abi_version");
    if (!version)
      throw LibraryError(
          fmt::format("the library '{}' has no symbol 'mpm_user_material_abi_version': it is not a "
                      "plugin of the C interface (mpm_user_material.h); with interface: c it must "
                      "define int mpm_user_material_abi_version(void)",
                      spec.library));
    const int v = reinterpret_cast<CVersionFunction>(version)();
    if (v != MPM_USER_MATERIAL_ABI_VERSION)
      throw LibraryError(
          fmt::format("the library '{}' was built for version {} of the C interface; this program "
                      "has version {} (rebuild it against mpm_user_material.h)",
                      spec.library, v, MPM_USER_MATERIAL_ABI_VERSION));
  }
  plugin->cmname.replace(0, std::min(spec.name.size(), cmname_length), spec.name, 0, cmname_length);
  plugin->c_name = spec.name;
  return plugin;
}

namespace {

/// The most points one call receives (Abaqus/Explicit's largest block; MPM_USER_MATERIAL_MAX_BLOCK).
constexpr Index max_block = MPM_USER_MATERIAL_MAX_BLOCK;

Mat3 row_major(const Real* a) {
  Mat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = a[3 * r + c];
  return m;
}
void store_row_major(const Mat3& m, Real* a) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[3 * r + c] = m(r, c);
}

bool all_finite(const double* a, std::size_t n) {
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) sum += a[k] * 0;  // NaN or inf make the sum NaN
  return sum == 0;
}

}  // namespace

/// The arrays of one call, kept per thread (a block of at most max_block points).
template <int Dim>
struct UserMaterial<Dim>::Scratch {
  std::vector<PointKinematics> points;
  std::vector<double> coord, length, density, strain_inc, spin_inc, temp, stretch_old, stretch_new, defgrad_old,
      defgrad_new, rotation_new, stress_old, stress_new, state_old, state_new, energy_old[2], energy_new[2], field;
  std::vector<Real*> sdv;
};

template <int Dim>
UserMaterial<Dim>::UserMaterial(std::shared_ptr<const Plugin> plugin, const UserMaterialParams& params)
    : plugin_(std::move(plugin)), params_(params) {
  for (std::size_t k = 0; k < plugin_->spec.initial_state.size(); ++k) state_fields_.push_back(state_field_name(k));
}

template <int Dim>
void UserMaterial<Dim>::prepare_particles(ParticleSet<Dim>& p) const {
  p.add_field(keys::user_point, UserPointState{});
  for (std::size_t k = 0; k < state_fields_.size(); ++k)
    p.template add_field<Real>(state_fields_[k], plugin_->spec.initial_state[k]);
}

template <int Dim>
Real UserMaterial<Dim>::wave_speed(Real J) const {
  if (params_.wave_speed > 0) return params_.wave_speed;
  const Real K = std::max(params_.bulk * J, params_.bulk);
  return std::sqrt((K + 4 * params_.shear / 3) * std::max(J, Real(0)) * (1 / params_.density));
}

template <int Dim>
WaveSpeedBound<Dim> UserMaterial<Dim>::wave_speed_bound(const ParticleSet<Dim>& p) const {
  const Real* hoop = axisym::hoop_stretch_of(p);
  WaveSpeedBound<Dim> bound;
  for (Index i = 0; i < p.size(); ++i) {
    const Real c = wave_speed(axisym::volume_ratio(p, i, hoop));
    bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
  }
  return bound;
}

template <int Dim>
bool UserMaterial<Dim>::particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const {
  const Real* hoop = axisym::hoop_stretch_of(p);
  c.resize(static_cast<std::size_t>(p.size()));
  for (Index i = 0; i < p.size(); ++i) c[static_cast<std::size_t>(i)] = wave_speed(axisym::volume_ratio(p, i, hoop));
  return true;
}

template <int Dim>
void UserMaterial<Dim>::add_strain_energy(const ParticleSet<Dim>& p, ExactSum& sum) const {
  const auto& state = p.field(keys::user_point);
  for (Index i = 0; i < p.size(); ++i) {
    const UserPointState& s = state[static_cast<std::size_t>(i)];
    if (plugin_->spec.interface == Interface::umat)
      sum += p.volume0[i] * s.energy[0];  // SSE, per reference volume
    else
      sum += p.mass[i] * (s.energy[0] - s.energy[1]);  // internal - inelastic, per unit mass
  }
}

template <int Dim>
void UserMaterial<Dim>::add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& sum) const {
  const auto& state = p.field(keys::user_point);
  for (Index i = 0; i < p.size(); ++i) {
    const UserPointState& s = state[static_cast<std::size_t>(i)];
    if (plugin_->spec.interface == Interface::umat)
      sum += p.volume0[i] * (s.energy[1] + s.energy[2]);  // SPD + SCD
    else
      sum += p.mass[i] * s.energy[1];
  }
}

template <int Dim>
bool UserMaterial<Dim>::append_output(std::string_view field, const ParticleSet<Dim>& p,
                                      std::vector<double>& out) const {
  const auto& names = plugin_->spec.state_names;
  const auto it = std::find(names.begin(), names.end(), field);
  if (it == names.end() && field == "plastic_work") {
    // the energy the law dissipated, per reference volume (what the failure wrapper subtracts from the stress work,
    // eq. 16.4), unless a state variable has the name
    const auto& state = p.field(keys::user_point);
    for (Index i = 0; i < p.size(); ++i) {
      const UserPointState& s = state[static_cast<std::size_t>(i)];
      out.push_back(plugin_->spec.interface == Interface::umat ? s.energy[1] + s.energy[2]
                                                               : p.mass[i] / p.volume0[i] * s.energy[1]);
    }
    return true;
  }
  if (it == names.end()) return false;
  const auto& values = p.template field<Real>(state_fields_[static_cast<std::size_t>(it - names.begin())]);
  out.insert(out.end(), values.begin(), values.end());
  return true;
}

template <int Dim>
void UserMaterial<Dim>::fail(const ParticleSet<Dim>& p, Index i, const std::string& what) const {
  const auto& s = plugin_->spec;
  Real x[3] = {0, 0, 0};
  for (int d = 0; d < Dim; ++d) x[d] = p.x[i][d];
  throw UserMaterialError(fmt::format(
      "material '{}' (model user, interface {}, symbol '{}' of library '{}'): {} at particle {} (x = ({:.6g}, "
      "{:.6g}, {:.6g}) m, t = {:.6g} s)",
      s.material, interface_name(s.interface), s.symbol, s.library, what, p.id[i], x[0], x[1], x[2],
      p.field(keys::user_point)[static_cast<std::size_t>(i)].time));
}

template <int Dim>
PointKinematics UserMaterial<Dim>::kinematics_of(const ParticleSet<Dim>& p, Index i, const MatU<Dim>& L,
                                                 Real hoop_stretch, Real hoop_rate, Real temperature) const {
  PointKinematics pt;
  const UserPointState& st = p.field(keys::user_point)[static_cast<std::size_t>(i)];
  pt.F_old = row_major(st.F_old);
  pt.F_new = embed<Dim>(Mat<Dim>(p.F[i]), hoop_stretch);
  const Mat3 Lf = embed<Dim>(Mat<Dim>(L), hoop_rate);
  pt.D = symmetric_part(Lf);
  pt.W = 0.5 * (Lf - Lf.transpose());
  pt.J = p.F[i].determinant() * hoop_stretch;
  std::copy(st.q, st.q + 4, pt.q);
  if constexpr (Dim == 3) {
    pt.R_old = rotation_of(st.q);
    pt.R_new = polar_rotation_3d(pt.F_new, pt.q);
  } else if constexpr (Dim == 2) {
    pt.R_old = polar_rotation_2d(pt.F_old);
    pt.R_new = polar_rotation_2d(pt.F_new);
  } else {
    pt.R_old = pt.R_new = Mat3::Identity();
  }
  pt.stress_old = p.stress[i].full();
  pt.temperature = temperature;
  pt.density = params_.density / pt.J;
  pt.length = std::pow(std::abs(p.volume0[i] * pt.J), Real(1) / Dim);
  for (int d = 0; d < Dim; ++d) pt.x[d] = p.x[i][d];
  return pt;
}

template <int Dim>
WaveSpeedBound<Dim> UserMaterial<Dim>::update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L,
                                                     Real dt) {
  thread_local Scratch scratch;  // a block's arrays, reused by the thread's next blocks
  for (Index first = begin; first < end; first += max_block)
    update_chunk(p, first, std::min(end, first + max_block), L + (first - begin), dt, scratch);
  const Real* hoop = axisym::hoop_stretch_of(p);
  WaveSpeedBound<Dim> bound;
  for (Index i = begin; i != end; ++i) {
    const Real c = wave_speed(axisym::volume_ratio(p, i, hoop));
    bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
  }
  return bound;
}

template <int Dim>
void UserMaterial<Dim>::update_chunk(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt,
                                     Scratch& s) const {
  const UserMaterialSpec& spec = plugin_->spec;
  const int n = static_cast<int>(end - begin);
  const int nstatev = static_cast<int>(state_fields_.size());
  const int nprops = static_cast<int>(spec.properties.size());
  UserPointState* state = p.field(keys::user_point).data();
  s.sdv.resize(static_cast<std::size_t>(nstatev));
  for (int k = 0; k < nstatev; ++k)
    s.sdv[k] = p.template field<Real>(state_fields_[static_cast<std::size_t>(k)]).data();
  const Real* temperature = p.has_field(mpm::keys::temperature) ? p.field(mpm::keys::temperature).data() : nullptr;
  [[maybe_unused]] axisym::HoopFields hoop;
  if constexpr (Dim == 2) hoop = axisym::hoop_fields(p);

  // 1. The kinematics of every point: F, R of F = R U old and new, D and W, the stress in the global frame.
  s.points.resize(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) {
    const Index i = begin + b;
    Real hoop_stretch = 1, hoop_rate = 0;
    if constexpr (Dim == 2)
      if (hoop) {
        hoop_stretch = hoop.stretch[i];
        hoop_rate = hoop.rate[i];
      }
    s.points[static_cast<std::size_t>(b)] =
        kinematics_of(p, i, L[b], hoop_stretch, hoop_rate, temperature ? temperature[i] : 0);
  }

  // 2. The call, through the interface's arrays; 3. the results checked and stored.
  if (spec.interface == Interface::umat) {
    for (int b = 0; b < n; ++b) {
      const Index i = begin + b;
      UserPointState& st = state[i];
      UmatCall u(Dim, s.points[static_cast<std::size_t>(b)], st, p.id[i], dt);
      u.statev.resize(static_cast<std::size_t>(nstatev));
      for (int k = 0; k < nstatev; ++k) u.statev[static_cast<std::size_t>(k)] = s.sdv[k][i];
      u.call(*plugin_);
      if (!all_finite(u.stress, static_cast<std::size_t>(u.ntens)))
        fail(p, i,
             fmt::format("the subroutine returned a stress that is not finite, STRESS = ({})",
                         fmt::join(u.stress, u.stress + u.ntens, ", ")));
      if (!all_finite(u.statev.data(), u.statev.size()))
        fail(p, i, "the subroutine returned state variables (STATEV) that are not finite");
      p.stress[i] = SymTensor<Dim>::from(symmetric_from(umat_pairs, u.ntens, [&](int k) { return u.stress[k]; }));
      for (int k = 0; k < nstatev; ++k) s.sdv[k][i] = u.statev[static_cast<std::size_t>(k)];
      const Mat3 eps_new = u.strain_rotated + u.strain_increment;
      for (int k = 0; k < 6; ++k) st.strain[k] = (k < 3 ? 1 : 2) * eps_new(umat_pairs[k][0], umat_pairs[k][1]);
      st.energy[0] = u.sse;
      st.energy[1] = u.spd;
      st.energy[2] = u.scd;
    }
  } else {
    // VUMAT (column-major, nblock x ncomp) and C (point-major) share the arrays; `at(b, c, m)` is the place of
    // component c of point b in an array of m components.
    const bool fortran = spec.interface == Interface::vumat;
    const int ndir = 3, nshr = Dim == 3 ? 3 : 1, ncomp = ndir + nshr, ndef = ndir + 2 * nshr;
    const int csym = fortran ? ncomp : 6, cdef = fortran ? ndef : 9, cspin = fortran ? nshr : 3;
    auto at = [&](int b, int c, int m) { return static_cast<std::size_t>(fortran ? b + c * n : b * m + c); };
    auto size = [&](int m) { return static_cast<std::size_t>(std::max(n * m, 1)); };
    s.coord.resize(size(3));
    s.length.resize(size(1));
    s.density.resize(size(1));
    s.temp.resize(size(1));
    s.strain_inc.resize(size(csym));
    s.spin_inc.resize(size(cspin));
    s.stretch_old.resize(size(csym));
    s.stretch_new.resize(size(csym));
    s.defgrad_old.resize(size(cdef));
    s.defgrad_new.resize(size(cdef));
    s.rotation_new.resize(size(9));
    s.stress_old.resize(size(csym));
    s.stress_new.resize(size(csym));
    s.state_old.resize(size(nstatev));
    s.state_new.resize(size(nstatev));
    s.field.assign(size(1), 0.0);
    for (int e = 0; e < 2; ++e) {
      s.energy_old[e].resize(size(1));
      s.energy_new[e].resize(size(1));
    }
    for (int b = 0; b < n; ++b) {
      const Index i = begin + b;
      const auto& pt = s.points[static_cast<std::size_t>(b)];
      const UserPointState& st = state[i];
      const Mat3 U_old = symmetric_part(pt.R_old.transpose() * pt.F_old);
      const Mat3 U_new = symmetric_part(pt.R_new.transpose() * pt.F_new);
      const Mat3 d_eps = pt.R_new.transpose() * pt.D * pt.R_new * dt;
      const Mat3 S_old = pt.R_old.transpose() * pt.stress_old * pt.R_old;
      // relative spin: W dt less the spin of R over the step (the axial vector of Delta R), in the corotational frame
      const Mat3 dR = pt.R_new * pt.R_old.transpose();
      const Vec<3> w_dt(pt.W(2, 1) * dt, pt.W(0, 2) * dt, pt.W(1, 0) * dt);
      const Vec<3> omega(0.5 * (dR(2, 1) - dR(1, 2)), 0.5 * (dR(0, 2) - dR(2, 0)), 0.5 * (dR(1, 0) - dR(0, 1)));
      const Vec<3> spin = pt.R_new.transpose() * (w_dt - omega);
      for (int c = 0; c < 3; ++c) s.coord[at(b, c, 3)] = pt.x[c];
      s.length[at(b, 0, 1)] = pt.length;
      s.density[at(b, 0, 1)] = pt.density;
      s.temp[at(b, 0, 1)] = pt.temperature;
      for (int c = 0; c < csym; ++c) {
        const int r = vumat_pairs[c][0], k = vumat_pairs[c][1];
        s.strain_inc[at(b, c, csym)] = d_eps(r, k);
        s.stretch_old[at(b, c, csym)] = U_old(r, k);
        s.stretch_new[at(b, c, csym)] = U_new(r, k);
        s.stress_old[at(b, c, csym)] = s.stress_new[at(b, c, csym)] = S_old(r, k);
      }
      if (fortran && nshr == 1) {
        s.spin_inc[at(b, 0, 1)] = spin[2];
      } else {
        for (int c = 0; c < 3; ++c) s.spin_inc[at(b, c, 3)] = spin[c];
      }
      for (int c = 0; c < cdef; ++c) {
        int r = c / 3, k = c % 3;  // C: row-major 3x3
        if (fortran) {
          r = Dim == 3 ? defgrad_pairs_3d[c][0] : defgrad_pairs_2d[c][0];
          k = Dim == 3 ? defgrad_pairs_3d[c][1] : defgrad_pairs_2d[c][1];
        }
        s.defgrad_old[at(b, c, cdef)] = pt.F_old(r, k);
        s.defgrad_new[at(b, c, cdef)] = pt.F_new(r, k);
      }
      if (!fortran) store_row_major(pt.R_new, &s.rotation_new[at(b, 0, 9)]);
      for (int k = 0; k < nstatev; ++k) s.state_old[at(b, k, nstatev)] = s.state_new[at(b, k, nstatev)] = s.sdv[k][i];
      for (int e = 0; e < 2; ++e) s.energy_old[e][at(b, 0, 1)] = s.energy_new[e][at(b, 0, 1)] = st.energy[e];
    }
    const double time = state[begin].time + dt;  // the end of the increment (every point of a body shares it)
    const double* props = nprops ? spec.properties.data() : s.field.data();
    if (fortran) {
      const int nfieldv = 0, lanneal = 0;
      reinterpret_cast<VumatFunction>(plugin_->entry)(
          &n, &ndir, &nshr, &nstatev, &nfieldv, &nprops, &lanneal, &time, &time, &dt, plugin_->cmname.data(),
          s.coord.data(), s.length.data(), props, s.density.data(), s.strain_inc.data(), s.spin_inc.data(),
          s.temp.data(), s.stretch_old.data(), s.defgrad_old.data(), s.field.data(), s.stress_old.data(),
          s.state_old.data(), s.energy_old[0].data(), s.energy_old[1].data(), s.temp.data(), s.stretch_new.data(),
          s.defgrad_new.data(), s.field.data(), s.stress_new.data(), s.state_new.data(), s.energy_new[0].data(),
          s.energy_new[1].data(), cmname_length);
    } else {
      mpm_user_material_block block{};
      block.abi_version = MPM_USER_MATERIAL_ABI_VERSION;
      block.n = n;
      block.dimension = Dim;
      if constexpr (Dim == 2) block.axisymmetric = hoop ? 1 : 0;
      block.nprops = nprops;
      block.nstatev = nstatev;
      block.name = plugin_->c_name.c_str();
      block.dt = dt;
      block.time = time;
      block.props = props;
      block.density = s.density.data();
      block.coordinates = s.coord.data();
      block.char_length = s.length.data();
      block.temperature = s.temp.data();
      block.F_old = s.defgrad_old.data();
      block.F_new = s.defgrad_new.data();
      block.stretch_old = s.stretch_old.data();
      block.stretch_new = s.stretch_new.data();
      block.rotation_new = s.rotation_new.data();
      block.strain_increment = s.strain_inc.data();
      block.stress_old = s.stress_old.data();
      block.stress_new = s.stress_new.data();
      block.state_old = s.state_old.data();
      block.state_new = s.state_new.data();
      block.energy_internal_old = s.energy_old[0].data();
      block.energy_internal_new = s.energy_new[0].data();
      block.energy_inelastic_old = s.energy_old[1].data();
      block.energy_inelastic_new = s.energy_new[1].data();
      block.failed_point = -1;
      const int code = reinterpret_cast<CUpdateFunction>(plugin_->entry)(&block);
      if (code != MPM_USER_MATERIAL_OK) {
        block.message[MPM_USER_MATERIAL_MESSAGE_SIZE - 1] = 0;
        const int b = block.failed_point >= 0 && block.failed_point < n ? block.failed_point : 0;
        fail(p, begin + b,
             fmt::format("the update returned error code {}{}{}", code, block.message[0] ? ": " : "",
                         block.message[0] ? block.message : "") +
                 (block.failed_point >= 0 && block.failed_point < n ? "" : " (for the block that starts)"));
      }
    }
    for (int b = 0; b < n; ++b) {
      const Index i = begin + b;
      const auto& pt = s.points[static_cast<std::size_t>(b)];
      UserPointState& st = state[i];
      double out[6];
      for (int c = 0; c < csym; ++c) out[c] = s.stress_new[at(b, c, csym)];
      const int ngiven = fortran ? ncomp : 6;
      if (!all_finite(out, static_cast<std::size_t>(ngiven)))
        fail(p, i,
             fmt::format("the subroutine returned a stress that is not finite, stressNew = ({})",
                         fmt::join(out, out + ngiven, ", ")));
      for (int k = 0; k < nstatev; ++k)
        if (!std::isfinite(s.state_new[at(b, k, nstatev)]))
          fail(p, i,
               fmt::format("the subroutine returned state variable {} ({}) = {}", k + 1, spec.state_names[k],
                           s.state_new[at(b, k, nstatev)]));
      const Mat3 S_new = symmetric_from(vumat_pairs, Dim == 3 || !fortran ? 6 : 4, [&](int c) { return out[c]; });
      p.stress[i] = SymTensor<Dim>::from(pt.R_new * S_new * pt.R_new.transpose());
      for (int k = 0; k < nstatev; ++k) s.sdv[k][i] = s.state_new[at(b, k, nstatev)];
      for (int e = 0; e < 2; ++e) st.energy[e] = s.energy_new[e][at(b, 0, 1)];
    }
  }

  // 4. What the next step starts from.
  for (int b = 0; b < n; ++b) {
    const Index i = begin + b;
    const auto& pt = s.points[static_cast<std::size_t>(b)];
    UserPointState& st = state[i];
    store_row_major(pt.F_new, st.F_old);
    std::copy(pt.q, pt.q + 4, st.q);
    st.time += dt;
    st.increments += 1;
  }
}

template class UserMaterial<1>;
template class UserMaterial<2>;
template class UserMaterial<3>;

}  // namespace mpm::user_material
