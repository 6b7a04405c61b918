#pragma once
/// \file user_material.hpp
/// The material `model: user`: a law from a shared library, called once per block of at most 136 points
/// (README.md). The per-point history the interfaces need is one on-demand particle field (keys::user_point:
/// F and R of the last step, the UMAT's total strain, the energies, the point's time and increment count) and the
/// NSTATEV state variables are one Real field each ("sdv1", "sdv2", ...): all checkpointed and migrated by the
/// particle set's one byte mechanism, with no code here.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/materials/material.hpp"
#include "mpm/particles/field_key.hpp"
#include "mpm/user_material/shared_library.hpp"
#include "mpm/user_material/user_material_spec.hpp"

namespace mpm::user_material {

/// A user subroutine that failed: a non-finite result, an error code of the C interface. what() names the material,
/// the library and the point.
class UserMaterialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the program keeps per point for the interfaces (one field, read and written together; 29 doubles).
struct UserPointState {
  using scalar_type = Real;                     ///< a struct of Reals: checkpointed as an array of doubles
  Real F_old[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< F of the last step, 3x3 row-major
  Real q[4] = {1, 0, 0, 0};  ///< 3D: R of F_old as a unit quaternion (the start of the next polar iteration)
  Real strain[6] = {};       ///< UMAT: STRAN at the end of the last step (11, 22, 33, 12, 13, 23, engineering shear)
  /// VUMAT and C: internal and inelastic energy per unit mass (J/kg), unused; UMAT: SSE, SPD, SCD (J/m^3 of
  /// reference volume).
  Real energy[3] = {};
  Real time = 0;        ///< s, the time the point has been updated to
  Real increments = 0;  ///< steps done (the UMAT's KINC is increments + 1)
};

namespace keys {
inline constexpr FieldKey<UserPointState> user_point{"user_material"};
}  // namespace keys

/// The loaded library and what every call passes besides the points.
struct Plugin {
  UserMaterialSpec spec;
  std::shared_ptr<SharedLibrary> library;
  void* entry = nullptr;                      ///< VumatFunction, UmatFunction or the C update
  std::string cmname = std::string(80, ' ');  ///< CMNAME blank-padded to 80 characters (Fortran) ...
  std::string c_name;                         ///< ... and 0-terminated (C)

  /// Loads spec.library and looks up its entry point (the C interface: checks the version too). Throws
  /// LibraryError saying what is wrong.
  static std::shared_ptr<const Plugin> load(const UserMaterialSpec& spec);
};

/// The kinematics of one point over one step (what every interface's arguments are made of).
struct PointKinematics {
  Mat3 F_old, F_new, R_old, R_new, D, W, stress_old;  ///< stress_old: the Cauchy stress at t_n, global frame
  Real J = 1, q[4] = {1, 0, 0, 0}, temperature = 0, density = 0, length = 0;
  Real x[3] = {0, 0, 0};
};

/// The constants besides the library's: density and what the time step needs.
struct UserMaterialParams {
  Real density = 0;     ///< rho0, kg/m^3
  Real bulk = 0;        ///< K, Pa (0 with a declared wave speed)
  Real shear = 0;       ///< G, Pa (0 with a declared wave speed)
  Real wave_speed = 0;  ///< m/s, declared; 0: from K and G
};

template <int Dim>
class UserMaterial final : public Material<Dim> {
 public:
  UserMaterial(std::shared_ptr<const Plugin> plugin, const UserMaterialParams& params);
  std::string_view model() const override { return "user"; }
  Real density() const override { return params_.density; }
  const Plugin& plugin() const { return *plugin_; }

  void prepare_particles(ParticleSet<Dim>& p) const override;
  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override;
  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override;
  bool particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const override;
  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& sum) const override;
  void add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& sum) const override;
  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override;

  /// The dilatational wave speed at det F = J (the time step's): the declared one, or
  /// sqrt((K max(J, 1) + 4G/3) J / rho0) (K raised to the tangent K J in expansion, as the linear EOS of the
  /// plasticity module).
  Real wave_speed(Real J) const;
  /// F old and new, R of F = R U old and new, D and W of the step (L its velocity gradient) and the stress of its start
  /// (global frame) of particle i: what the interfaces' arguments are made of.
  PointKinematics kinematics_of(const ParticleSet<Dim>& p, Index i, const MatU<Dim>& L, Real hoop_stretch,
                                Real hoop_rate, Real temperature) const;

 private:
  struct Scratch;
  void update_chunk(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt, Scratch& s) const;
  [[noreturn]] void fail(const ParticleSet<Dim>& p, Index i, const std::string& what) const;

  std::shared_ptr<const Plugin> plugin_;
  UserMaterialParams params_;
  std::vector<std::string> state_fields_;  ///< sdv1, sdv2, ...
};

}  // namespace mpm::user_material
