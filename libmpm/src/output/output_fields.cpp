#include "mpm/output/output_fields.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <stdexcept>

#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm {
namespace {

void push_mat3(std::vector<double>& out, const Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
}

/// Calls f(i) for every particle of the body.
template <class B, class F>
void each(const B& body, F f) {
  for (Index i = 0; i < body.particles.size(); ++i) f(i);
}

/// The fields of the core, in the order of the scene reference.
std::deque<OutputField> core_fields() {
  std::deque<OutputField> t;
  t.push_back(
      output_field("velocity", 3, "m/s", "particle velocity (m/s)", [](const auto& b, std::vector<double>& out) {
        constexpr int Dim = body_dimension<decltype(b)>;
        each(b, [&](Index i) { append_padded<Dim>(out, b.particles.v[i]); });
      }));
  t.push_back(output_field("displacement", 3, "m", "displacement from the initial position (m)",
                           [](const auto& b, std::vector<double>& out) {
                             constexpr int Dim = body_dimension<decltype(b)>;
                             const auto& p = b.particles;
                             const auto& x0 = p.field(keys::reference_position<Dim>);
                             each(b, [&](Index i) { append_padded<Dim>(out, VecU<Dim>(p.x[i] - x0[i])); });
                           }));
  t.back().prepare_with([](auto& body) {  // X_p = x_p at the start
    constexpr int Dim = body_dimension<decltype(body)>;
    auto& p = body.particles;
    auto& x0 = p.add_field(keys::reference_position<Dim>, VecU<Dim>::Zero());
    for (Index i = 0; i < p.size(); ++i) x0[i] = p.x[i];
  });
  t.push_back(output_field("stress", 6, "Pa", "Cauchy stress (Pa)", [](const auto& b, std::vector<double>& out) {
    each(b, [&](Index i) {  // ParaView order XX YY ZZ XY YZ XZ
      const Mat3 s = b.particles.stress[i].full();
      for (double v : {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)}) out.push_back(v);
    });
  }));
  t.push_back(output_field(
      "deformation_gradient", 9, "-", "deformation gradient F (-)", [](const auto& b, std::vector<double>& out) {
        const Real* hoop = axisym::hoop_stretch_of(b.particles);
        each(b, [&](Index i) { push_mat3(out, axisym::deformation_gradient_3x3(b.particles, i, hoop)); });
      }));
  t.push_back(output_field("mass", 1, "kg", "particle mass (kg)", [](const auto& b, std::vector<double>& out) {
    each(b, [&](Index i) { out.push_back(b.particles.mass[i]); });
  }));
  t.push_back(
      output_field("volume", 1, "m^3", "current particle volume (m^3)", [](const auto& b, std::vector<double>& out) {
        const auto& p = b.particles;
        const Real* hoop = axisym::hoop_stretch_of(p);
        each(b, [&](Index i) { out.push_back(p.volume0[i] * axisym::volume_ratio(p, i, hoop)); });
      }));
  t.push_back(
      output_field("density", 1, "kg/m^3", "current density (kg/m^3)", [](const auto& b, std::vector<double>& out) {
        const auto& p = b.particles;
        const Real* hoop = axisym::hoop_stretch_of(p);
        each(b, [&](Index i) { out.push_back(p.mass[i] / (p.volume0[i] * axisym::volume_ratio(p, i, hoop))); });
      }));
  t.push_back(
      output_field("body", 1, "-", "index of the particle's body in `bodies`",
                   [](const auto& b, std::vector<double>& out) { each(b, [&](Index) { out.push_back(b.index); }); }));
  t.push_back(output_field("velocity_gradient", 9, "1/s", "velocity gradient (1/s)",
                           [](const auto& b, std::vector<double>& out) {
                             constexpr int Dim = body_dimension<decltype(b)>;
                             const auto& L = b.particles.field(keys::velocity_gradient<Dim>);
                             const Real* hoop = nullptr;  // L_tt (axisymmetric bodies)
                             if constexpr (Dim == 2)
                               if (b.particles.has_field(keys::hoop_velocity_gradient))
                                 hoop = b.particles.field(keys::hoop_velocity_gradient).data();
                             each(b, [&](Index i) { push_mat3(out, embed<Dim>(Mat<Dim>(L[i]), hoop ? hoop[i] : 0)); });
                           }));
  t.back().prepare_with([](auto& body) {  // stored by the scheme only when this field exists
    constexpr int Dim = body_dimension<decltype(body)>;
    body.particles.add_field(keys::velocity_gradient<Dim>, MatU<Dim>::Zero());
  });
  t.push_back(
      output_field("pressure", 1, "Pa", "pressure, -tr(stress)/3 (Pa)", [](const auto& b, std::vector<double>& out) {
        each(b, [&](Index i) { out.push_back(-b.particles.stress[i].full().trace() / 3); });
      }));
  t.push_back(output_field("von_mises_stress", 1, "Pa", "von Mises equivalent stress (Pa)",
                           [](const auto& b, std::vector<double>& out) {
                             each(b, [&](Index i) {
                               const Mat3 s = b.particles.stress[i].full();
                               const Mat3 dev = s - s.trace() / 3 * Mat3::Identity();
                               out.push_back(std::sqrt(1.5 * dev.squaredNorm()));
                             });
                           }));
  // GIMP particle domain lengths per axis, l_p = 2 x half-length (cpGIMP: stretched by diag F, eq. 3.14); in
  // ParaView: Glyph filter, glyph type Box, scale array domain_size, scale by components.
  t.push_back(output_field("domain_size", 3, "m",
                           "GIMP particle domain lengths per axis (m), stretched by diag F with `cpgimp`; only with "
                           "`gimp`/`cpgimp`",
                           [](const auto& b, std::vector<double>& out) {
                             constexpr int Dim = body_dimension<decltype(b)>;
                             const auto& p = b.particles;
                             const auto& half0 = p.field(keys::domain_half_length0<Dim>);
                             const bool stretched = b.stretched_domain;
                             each(b, [&](Index i) {
                               VecU<Dim> l = 2 * half0[i];
                               if (stretched) l = l.cwiseProduct(VecU<Dim>(p.F[i].diagonal()));
                               append_padded<Dim>(out, l);
                             });
                           }));
  t.push_back(output_field("domains", 0, "m",
                           "the particle domains as cells, in their own files `PREFIX_domains_NNNNNN.vtu` / "
                           "`PREFIX_domains.pvd`; only with `gimp`, `cpgimp` and the `cpdi_*` functions",
                           nullptr));  // not a point field: OutputWriter writes the cells to files of their own
  // written by a material with `failure:` (FailingMaterial::append_output); 0 in any other body
  t.push_back(output_field("failed", 1, "-",
                           "1 for a particle that failed with action `fail` (it carries only compressive pressure, "
                           "eq. 16.2), else 0; 0 in bodies whose material has no `failure:`",
                           [](const auto& b, std::vector<double>& out) {
                             if (!b.material->append_output("failed", b.particles, out))
                               out.insert(out.end(), static_cast<std::size_t>(b.particles.size()), 0.0);
                           }));
  t.back().material_output = true;
  t.push_back(output_field("particle_sets", 1, "-",
                           "the particle's sets (`sets:`) as a bit mask: bit k (value 2^k) for the k-th set",
                           [](const auto& b, std::vector<double>& out) {
                             const auto& bits = b.particles.field(keys::particle_sets);
                             each(b, [&](Index i) { out.push_back(bits[static_cast<std::size_t>(i)]); });
                           }));
  t.back().carrier = std::string(keys::particle_sets.name);
  t.back().absent = "the scene has no `sets:`";
  t.push_back(output_field(
      "id", 1, "-", "index of the particle at creation (stable when particles are reordered)",
      [](const auto& b, std::vector<double>& out) { each(b, [&](Index i) { out.push_back(b.particles.id[i]); }); }));
  t.back().selectable = false;  // always written
  return t;
}

std::mutex& table_mutex() {
  static std::mutex m;
  return m;
}
/// A deque: entries never move, so find_output_field's pointers stay valid as modules register.
std::deque<OutputField>& field_table() {
  static std::deque<OutputField> t = core_fields();
  return t;
}
OutputField* find_locked(std::string_view name) {
  for (auto& f : field_table())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace

void register_output_field(OutputField field) {
  std::lock_guard lock(table_mutex());
  OutputField* existing = find_locked(field.name);
  if (!existing) {
    field_table().push_back(std::move(field));
    return;
  }
  if (existing->components != field.components || existing->unit != field.unit)
    throw std::logic_error(
        fmt::format("output field '{}' registered twice with different components or units", field.name));
  if (existing->description.empty()) existing->description = field.description;
  if (existing->carrier.empty()) {
    existing->carrier = field.carrier;
    existing->absent = field.absent;
  }
  for (auto& remedy : field.remedies)
    if (std::find(existing->remedies.begin(), existing->remedies.end(), remedy) == existing->remedies.end())
      existing->remedies.push_back(std::move(remedy));
}

const OutputField* find_output_field(std::string_view name) {
  std::lock_guard lock(table_mutex());
  return find_locked(name);
}

std::vector<std::string> output_field_names() {
  std::lock_guard lock(table_mutex());
  std::vector<std::string> names;
  for (const auto& f : field_table())
    if (f.selectable) names.push_back(f.name);
  return names;
}

template <int Dim>
void append_output_field(std::string_view name, const Body<Dim>& body, std::vector<double>& out) {
  const OutputField* f = find_output_field(name);
  if (!f || !f->template append<Dim>()) throw std::invalid_argument("unknown output field '" + std::string(name) + "'");
  f->template append<Dim>()(body, out);
}

template <int Dim>
std::optional<std::string> output_field_undefined_on(const OutputField& field, const Body<Dim>& body) {
  if (!field.carrier.empty() && !body.particles.has_field(field.carrier))
    return fmt::format("body '{}' does not carry {} ({}{}{})", body.name, field.name, field.absent,
                       field.remedies.empty() ? "" : "; ", fmt::join(field.remedies, ", or "));
  if (field.material_output) {
    std::vector<double> scratch;
    if (!body.material->append_output(field.name, body.particles, scratch))
      return fmt::format("the material of body '{}' (model {}) does not define {}", body.name, body.material->model(),
                         field.name);
  }
  return std::nullopt;
}

template <int Dim>
void prepare_output_fields(const std::vector<std::string>& requested, Body<Dim>& body) {
  for (const auto& name : requested)
    if (const OutputField* f = find_output_field(name); f && f->template prepare<Dim>())
      f->template prepare<Dim>()(body);
}

template <int Dim>
std::optional<std::string> unavailable_output_field(const std::vector<std::string>& requested,
                                                    const std::vector<Body<Dim>>& bodies) {
  std::vector<OutputField> fields;  // copied: the message is built without the lock
  {
    std::lock_guard lock(table_mutex());
    for (const auto& f : field_table())
      if (!f.carrier.empty() && std::find(requested.begin(), requested.end(), f.name) != requested.end())
        fields.push_back(f);
  }
  for (const auto& f : fields) {
    if (std::any_of(bodies.begin(), bodies.end(), [&](const Body<Dim>& b) { return b.particles.has_field(f.carrier); }))
      continue;
    std::string message = f.name + ": " + f.absent;
    for (std::size_t k = 0; k < f.remedies.size(); ++k) message += (k == 0 ? "; " : ", ") + f.remedies[k];
    message += fmt::format("{} remove {} from the fields", f.remedies.size() > 1 ? ", or" : " or", f.name);
    return message;
  }
  return std::nullopt;
}

template void append_output_field<1>(std::string_view, const Body<1>&, std::vector<double>&);
template void append_output_field<2>(std::string_view, const Body<2>&, std::vector<double>&);
template void append_output_field<3>(std::string_view, const Body<3>&, std::vector<double>&);
template void prepare_output_fields<1>(const std::vector<std::string>&, Body<1>&);
template void prepare_output_fields<2>(const std::vector<std::string>&, Body<2>&);
template void prepare_output_fields<3>(const std::vector<std::string>&, Body<3>&);
template std::optional<std::string> unavailable_output_field<1>(const std::vector<std::string>&,
                                                                const std::vector<Body<1>>&);
template std::optional<std::string> unavailable_output_field<2>(const std::vector<std::string>&,
                                                                const std::vector<Body<2>>&);
template std::optional<std::string> unavailable_output_field<3>(const std::vector<std::string>&,
                                                                const std::vector<Body<3>>&);

template std::optional<std::string> output_field_undefined_on<1>(const OutputField&, const Body<1>&);
template std::optional<std::string> output_field_undefined_on<2>(const OutputField&, const Body<2>&);
template std::optional<std::string> output_field_undefined_on<3>(const OutputField&, const Body<3>&);

}  // namespace mpm
