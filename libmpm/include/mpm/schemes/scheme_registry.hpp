#pragma once
/// \file scheme_registry.hpp
/// The one registry of time-integration schemes (`solver.scheme`). A scheme is declared once by a SchemeSpec: its
/// name and description, the parser of the keys of `solver:` it owns (declared with their specs by
/// register_scheme_solver_keys, scene/scene_extension.hpp) and a check of the whole scene, its makers
/// per dimension, and its traits (scheme_traits.hpp). The core registers USL, MUSL, USF and TLMPM
/// (src/schemes/core_schemes.cpp); an optional module registers its own from its register_module() (physics/implicit:
/// `implicit`). The loader's list of valid schemes, its checks of what combines with what, the builder, contact, heat
/// conduction, the memory estimate, `mpm check --ranks` and the energy hints all read this table.

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/scene/scene.hpp"
#include "mpm/schemes/scheme.hpp"
#include "mpm/schemes/scheme_traits.hpp"

namespace mpm {

namespace io {
class YamlReader;
class YamlMap;
}  // namespace io

/// Builds the scheme of a validated scene (its shape function, coordinates and SolverDescription::scheme_options).
template <int Dim>
using SchemeMaker = std::unique_ptr<Scheme<Dim>> (*)(const SceneDescription& scene);

struct SchemeSpec {
  std::string name{};         ///< the value of `solver.scheme`
  std::string description{};  ///< one line for the scene reference
  /// Reads the scheme's keys of `solver:` (`solver` holds what the core read so far: shape function, velocity
  /// transfer) and refuses what the scheme does not support, through the reader (file:line:column: key). Called
  /// before the time step is read. The result is stored in SolverDescription::scheme_options. Null: no keys.
  std::any (*parse)(const io::YamlReader& reader, const io::YamlMap& solver_map, const SolverDescription& solver,
                    const SceneDescription& scene) = nullptr;
  /// After every section (modules' included) is read: refuses sections the scheme does not support. Optional.
  void (*check)(const io::YamlReader& reader, const io::YamlMap& top, const SceneDescription& scene) = nullptr;
  SchemeMaker<1> make_1d = nullptr;
  SchemeMaker<2> make_2d = nullptr;
  SchemeMaker<3> make_3d = nullptr;
  SchemeTraits traits{};

  template <int Dim>
  SchemeMaker<Dim> maker() const {
    if constexpr (Dim == 1) return make_1d;
    if constexpr (Dim == 2) return make_2d;
    if constexpr (Dim == 3) return make_3d;
  }
};

/// Adds (or replaces) the scheme with this name. The core's schemes are registered when the table is first read;
/// a module calls this from its register_module().
void register_scheme(SchemeSpec spec);
/// The scheme with this name, or nullptr. The pointer stays valid.
const SchemeSpec* find_scheme(std::string_view name);
/// The scheme a validated solver section names; throws std::invalid_argument when it is not registered.
const SchemeSpec& scheme_of(const SolverDescription& solver);
/// The registered names, in registration order (the core's first).
std::vector<std::string> scheme_names();
/// The names of the registered schemes whose traits satisfy `accept`, as "a, b or c" (for refusals that say
/// what would work).
std::string scheme_names_where(const std::function<bool(const SchemeTraits&)>& accept);

/// The scheme of a validated scene, made by the maker of the scheme it names; throws std::invalid_argument when
/// that scheme is not registered or has no maker in this dimension.
template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scene_scheme(const SceneDescription& scene);

}  // namespace mpm
