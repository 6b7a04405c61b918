#pragma once
/// \file output_fields.hpp
/// The one table of particle fields that a run can write to its .vtu files (the scene's `output.fields`).
/// An entry holds the field's name, components, unit and description, how to append its values from a
/// body, and optionally what to allocate on a body before the run when a scene asks for it and what makes it
/// meaningless (no body carries the particle field it reads). The core registers its own fields (velocity,
/// stress, ...); a module registers its fields when it registers (plasticity: plastic_strain, ...; thermal:
/// heat_flux, ...), so the core names no module's field. The scene loader's list of valid fields, the
/// builder's checks and the writer all read this table; adding a field is one register_output_field call.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "mpm/particles/body.hpp"
#include "mpm/particles/field_key.hpp"

namespace mpm {

/// Appends body.particles.size() * components values (particle after particle) to `out`.
template <int Dim>
using OutputAppend = std::function<void(const Body<Dim>& body, std::vector<double>& out)>;
/// Allocates what the field reads on a freshly filled body (before the first snapshot).
template <int Dim>
using OutputPrepare = std::function<void(Body<Dim>& body)>;

/// One writable particle field. Values per particle are called once per body per frame (never per particle).
struct OutputField {
  std::string name;         ///< the scene's key and the .vtu array name
  int components = 1;       ///< 1; 3 (a vector, padded to 3D); 6 (symmetric: XX YY ZZ XY YZ XZ); 9 (3x3, rows)
  std::string unit;         ///< SI unit, "-" for a number
  std::string description;  ///< one line for the scene reference
  bool selectable = true;   ///< false: always written, not a scene choice (`id`)
  /// A particle field that at least one body must carry when the scene asks for this one (empty: none),
  /// why it would be missing ("no body tracks temperature") and how to get it, one clause per module.
  std::string carrier;
  std::string absent;
  std::vector<std::string> remedies;
  /// Written by the body's material (Material::append_output; plasticity: plastic_strain): a body whose
  /// material does not write it has no such field (a history on that body is refused).
  bool material_output = false;
  OutputAppend<1> append_1d;
  OutputAppend<2> append_2d;
  OutputAppend<3> append_3d;
  OutputPrepare<1> prepare_1d;
  OutputPrepare<2> prepare_2d;
  OutputPrepare<3> prepare_3d;

  /// Sets the appender of every dimension from one generic callable `f(const Body<Dim>&, out)`.
  template <class F>
  OutputField& append_with(F f) {
    append_1d = f;
    append_2d = f;
    append_3d = f;
    return *this;
  }
  /// Sets the preparer of every dimension from one generic callable `f(Body<Dim>&)`.
  template <class F>
  OutputField& prepare_with(F f) {
    prepare_1d = f;
    prepare_2d = f;
    prepare_3d = f;
    return *this;
  }
  template <int Dim>
  const OutputAppend<Dim>& append() const {
    if constexpr (Dim == 1) return append_1d;
    if constexpr (Dim == 2) return append_2d;
    if constexpr (Dim == 3) return append_3d;
  }
  template <int Dim>
  const OutputPrepare<Dim>& prepare() const {
    if constexpr (Dim == 1) return prepare_1d;
    if constexpr (Dim == 2) return prepare_2d;
    if constexpr (Dim == 3) return prepare_3d;
  }
};

/// Adds a field to the table (after the core's, in registration order). A field registered again (two
/// modules can write one shared particle field, e.g. temperature) must have the same components and unit;
/// its remedies are added to the first registration's (which keeps its appender). Throws std::logic_error
/// otherwise. Called by a module's register_module().
void register_output_field(OutputField field);
/// The field with this name, or nullptr. The pointer stays valid.
const OutputField* find_output_field(std::string_view name);
/// Names of the fields a scene can ask for (the selectable ones), in table order.
std::vector<std::string> output_field_names();

/// Appends the values of the named field for every particle of `body`; throws std::invalid_argument for a
/// name that is not in the table.
template <int Dim>
void append_output_field(std::string_view name, const Body<Dim>& body, std::vector<double>& out);
/// Runs the preparers of the requested fields on a filled body.
template <int Dim>
void prepare_output_fields(const std::vector<std::string>& requested, Body<Dim>& body);
/// The first requested field (in table order) whose carrier no body has, as "name: absent; remedy, ...,
/// or remove name from the fields", or nothing when every requested field can be written.
template <int Dim>
std::optional<std::string> unavailable_output_field(const std::vector<std::string>& requested,
                                                    const std::vector<Body<Dim>>& bodies);

/// Why `field` means nothing on `body` (its material does not write it, or the body does not carry the
/// particle field it reads), or nothing when it is defined there. For histories that name a body.
template <int Dim>
std::optional<std::string> output_field_undefined_on(const OutputField& field, const Body<Dim>& body);

/// The dimension of a Body type (for the generic callables of OutputField).
template <class B>
inline constexpr int body_dimension = std::remove_cvref_t<B>::dimension;

/// Appends v padded with zeros to three components.
template <int Dim>
void append_padded(std::vector<double>& out, const VecU<Dim>& v) {
  for (int d = 0; d < 3; ++d) out.push_back(d < Dim ? v[d] : 0.0);
}
/// Appends an on-demand scalar field, or zeros for a particle set without it.
template <int Dim>
void append_scalar_field(const ParticleSet<Dim>& p, FieldKey<Real> key, std::vector<double>& out) {
  if (!p.has_field(key)) {
    out.insert(out.end(), static_cast<std::size_t>(p.size()), 0.0);
    return;
  }
  const auto& values = p.field(key);
  out.insert(out.end(), values.begin(), values.end());
}
/// Appends an on-demand vector field padded to three components, or zeros for a particle set without it.
template <int Dim>
void append_vector_field(const ParticleSet<Dim>& p, FieldKey<VecU<Dim>> key, std::vector<double>& out) {
  if (!p.has_field(key)) {
    out.insert(out.end(), 3 * static_cast<std::size_t>(p.size()), 0.0);
    return;
  }
  for (const VecU<Dim>& v : p.field(key)) append_padded<Dim>(out, v);
}
/// An entry whose values `append(body, out)` (a generic callable, see OutputField::append_with) writes.
template <class Append>
OutputField output_field(std::string name, int components, std::string unit, std::string description, Append append) {
  OutputField f;
  f.name = std::move(name);
  f.components = components;
  f.unit = std::move(unit);
  f.description = std::move(description);
  f.append_with(append);
  return f;
}
/// An entry for an on-demand scalar field of the particles: its values, 0 in bodies without it.
inline OutputField scalar_particle_output(FieldKey<Real> key, std::string unit, std::string description) {
  return output_field(
      std::string(key.name), 1, std::move(unit), std::move(description),
      [key](const auto& body, std::vector<double>& out) { append_scalar_field(body.particles, key, out); });
}
/// The same for a field that at least one body must carry when the scene asks for it: `absent` says why it
/// would be missing, `remedy` how this registration's module provides it (see OutputField::carrier).
inline OutputField carried_scalar_output(FieldKey<Real> key, std::string unit, std::string description,
                                         std::string absent, std::string remedy) {
  OutputField f = scalar_particle_output(key, std::move(unit), std::move(description));
  f.carrier = std::string(key.name);
  f.absent = std::move(absent);
  f.remedies = {std::move(remedy)};
  return f;
}

}  // namespace mpm
