// The model `user` (README.md): its parameters and keys, the reader of its keys (the library loaded and its entry
// point found while the scene is read, so that `mpm check` reports a bad library at its line), the output fields of
// its state variables, and its builders.
#include "mpm/user_material/register.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <set>

#include "mpm/materials/elastic_constants.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "mpm/user_material/user_material.hpp"

namespace mpm::user_material {
namespace {

namespace fs = std::filesystem;
using io::KeySpec;
using io::KeyType;
using io::Range;

std::vector<ParameterSpec> user_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference mass density rho0"),
      ParameterSpec::optional("youngs_modulus", "Pa", Range::above(0), "absent: wave_speed given",
                              "Young's modulus E: with poisson_ratio, the wave speed of the time step "
                              "sqrt((K + 4G/3)/rho); the library receives only `properties`"),
      ParameterSpec::optional("poisson_ratio", "-", Range::open(-1, 0.5), "absent: wave_speed given",
                              "Poisson's ratio nu (with youngs_modulus)"),
      ParameterSpec::optional("wave_speed", "m/s", Range::above(0), "absent: from youngs_modulus, poisson_ratio",
                              "the dilatational wave speed the time step is bounded by (instead of E and nu)"),
  };
}

std::vector<KeySpec> user_keys() {
  return {
      {.name = "library",
       .type = KeyType::name,
       .required = true,
       .description = "the shared library (.so) with the material law, relative to the scene file; loaded with "
                      "dlopen(RTLD_NOW | RTLD_LOCAL) when the scene is read",
       .allowed_text = "a file"},
      {.name = "interface",
       .type = KeyType::choice,
       .choices = {"vumat", "umat", "c"},
       .default_value = std::string("vumat"),
       .description = "the calling convention: Abaqus/Explicit VUMAT (blocks, corotational frame), Abaqus/Standard "
                      "UMAT (one point per call) or this program's C interface (mpm_user_material.h); "
                      "physics/user_material/README.md"},
      {.name = "symbol",
       .type = KeyType::name,
       .absent = "`vumat_`, `umat_` or `mpm_user_material_update` (by interface)",
       .description = "the entry point's name in the library (gfortran appends `_` to a subroutine's name)"},
      {.name = "properties",
       .type = KeyType::list,
       .absent = "none (NPROPS = 0)",
       .description = "the numbers passed as PROPS (props), in this order, as given (no unit conversion)",
       .type_text = "list of numbers",
       .allowed_text = "finite numbers"},
      {.name = "state_variables",
       .type = KeyType::list,
       .absent = "none (NSTATEV = 0)",
       .description = "the solution-dependent state variables (NSTATEV): their number (each starts at 0, output "
                      "fields sdv1, sdv2, ...), or a list with one entry each: an initial value (output sdvK), a name "
                      "(the output field's, starting at 0) or `NAME: VALUE`; checkpointed and migrated with the "
                      "particles",
       .type_text = "integer or list",
       .allowed_text = "a count >= 0, or a list of numbers, names or NAME: VALUE"},
      {.name = "name",
       .type = KeyType::name,
       .absent = "the material's name",
       .description = "the name passed as CMNAME (80 characters, blank-padded)"},
  };
}

std::optional<ParameterError> check(const std::map<std::string, double>& p) {
  const bool E = p.count("youngs_modulus") != 0, nu = p.count("poisson_ratio") != 0, c = p.count("wave_speed") != 0;
  if (c && (E || nu))
    return ParameterError{"wave_speed",
                          "give either youngs_modulus and poisson_ratio or wave_speed for the time step, not both"};
  if (E != nu)
    return ParameterError{E ? "youngs_modulus" : "poisson_ratio",
                          "youngs_modulus and poisson_ratio go together (the time step's wave speed needs both)"};
  if (!c && !E)
    return ParameterError{"youngs_modulus",
                          "the time step needs the material's wave speed: give youngs_modulus (Pa) and poisson_ratio, "
                          "or wave_speed (m/s)"};
  return std::nullopt;
}

/// The output names this module registered (so that a second scene, or a second material, may use them again).
std::set<std::string>& own_output_names() {
  static std::set<std::string> names;
  return names;
}
std::mutex& names_mutex() {
  static std::mutex m;
  return m;
}

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
}

/// Makes `name` an output field that the body's material writes: a field the module registered before, or one that
/// another module registered as written by the material (Material::append_output, e.g. plastic_strain, so that the
/// user's law writes it in its bodies), or a new one; fails at `value` for any other field of that name.
void register_state_output(const io::YamlReader& reader, const io::YamlValue& value, const std::string& name) {
  std::lock_guard lock(names_mutex());
  if (own_output_names().count(name)) return;
  if (const OutputField* existing = find_output_field(name)) {
    if (existing->material_output && existing->components == 1) return;
    reader.fail(value, fmt::format("state variable name '{}' is already an output field of this program that the "
                                   "material does not write; choose another name",
                                   name));
  }
  OutputField field = output_field(name, 1, "-", "a state variable of a `model: user` material (0 in the other bodies)",
                                   [name](const auto& body, std::vector<double>& out) {
                                     if (!body.material->append_output(name, body.particles, out))
                                       out.insert(out.end(), static_cast<std::size_t>(body.particles.size()), 0.0);
                                   });
  field.material_output = true;
  register_output_field(std::move(field));
  own_output_names().insert(name);
}

void read_state_variables(const io::YamlReader& reader, const io::YamlValue& value, UserMaterialSpec& spec) {
  if (value.node.IsScalar()) {
    const int count = reader.integer(value, 0);
    spec.initial_state.assign(static_cast<std::size_t>(count), 0.0);
    for (int k = 0; k < count; ++k) spec.state_names.push_back(state_field_name(static_cast<std::size_t>(k)));
  } else {
    const auto entries = reader.list(value, std::nullopt, "state variables", "");
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const io::YamlValue& e = entries[k];
      std::string name = state_field_name(k);
      double initial = 0;
      if (e.node.IsMap()) {
        const io::YamlMap map = reader.map(e);
        if (map.entries().size() != 1) reader.fail(e, "a named state variable is one `NAME: INITIAL_VALUE` pair");
        name = map.entries()[0].key;
        initial = reader.number(map.entries()[0].value);
      } else if (io::parse_number(reader.string(e))) {
        initial = reader.number(e);
      } else {
        name = reader.name(e);
      }
      if (!is_identifier(name))
        reader.fail(
            e, fmt::format("state variable name '{}' must be letters, digits and '_' (an output field name)", name));
      if (std::find(spec.state_names.begin(), spec.state_names.end(), name) != spec.state_names.end())
        reader.fail(e, fmt::format("state variable name '{}' is given twice", name));
      spec.state_names.push_back(name);
      spec.initial_state.push_back(initial);
    }
  }
  for (std::size_t k = 0; k < spec.state_names.size(); ++k) register_state_output(reader, value, spec.state_names[k]);
}

std::any read_keys(const io::YamlReader& reader, const io::YamlMap& map, const MaterialDescription& material) {
  UserMaterialSpec spec;
  spec.material = material.name;
  spec.name = material.name;
  if (const auto v = map.find("name")) spec.name = reader.name(*v);
  spec.interface = Interface::vumat;
  if (const auto v = map.find("interface")) {
    const std::string word = reader.choice(*v, {"vumat", "umat", "c"});
    spec.interface = word == "umat" ? Interface::umat : word == "c" ? Interface::c : Interface::vumat;
  }
  spec.symbol = default_symbol(spec.interface);
  if (const auto v = map.find("symbol")) spec.symbol = reader.name(*v);
  if (const auto v = map.find("properties")) {
    // The subroutine receives SI stresses, strains, times and densities; its PROPS are passed as written, so a unit
    // system would hand it numbers in other units than the state it updates.
    if (!reader.unit_system().si())
      reader.fail(*v, fmt::format("a user material computes in SI (its stress, strain increments, times and "
                                  "density are SI), and its properties are passed as written: give them in SI "
                                  "and leave `units: {}` out of this scene",
                                  reader.unit_system().name));
    for (const auto& e : reader.list(*v, std::nullopt, "properties", "")) spec.properties.push_back(reader.number(e));
  }
  if (const auto v = map.find("state_variables")) read_state_variables(reader, *v, spec);
  const io::YamlValue library = map.required("library", "key", " of model user (the shared library, .so)");
  const std::string given = reader.name(library);
  fs::path path(given);
  if (path.is_relative()) path = fs::path(reader.file()).parent_path() / path;
  path = path.lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    reader.fail(library, fmt::format("library file '{}' not found{}", path.string(),
                                     given == path.string() ? "" : " (relative to the scene file)"));
  spec.library = fs::absolute(path, ec).string();
  try {
    return Plugin::load(spec);
  } catch (const LibraryError& e) {
    const bool symbol =
        map.find("symbol").has_value() && std::string(e.what()).find("has no symbol") != std::string::npos;
    reader.fail(symbol ? *map.find("symbol") : library, fmt::format("material '{}' (interface {}): {}", material.name,
                                                                    interface_name(spec.interface), e.what()));
  }
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_user(const MaterialDescription& d) {
  const auto& plugin = std::any_cast<const std::shared_ptr<const Plugin>&>(d.model_keys);
  const auto& p = d.parameters;
  UserMaterialParams params;
  params.density = p.at("density");
  if (p.count("wave_speed")) {
    params.wave_speed = p.at("wave_speed");
  } else {
    const ElasticConstants e = ElasticConstants::from_parameters(p);
    params.bulk = e.bulk;
    params.shear = e.mu;
  }
  return std::make_unique<UserMaterial<Dim>>(plugin, params);
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    MaterialModel model;
    model.key = "user";
    model.description =
        "a material law from a shared library: an Abaqus VUMAT or UMAT (Fortran) or a plugin of this program's C "
        "interface (mpm_user_material.h); frames, arguments and rules in physics/user_material/README.md";
    model.parameters = user_parameters();
    model.check = check;
    model.keys = user_keys();
    model.read_keys = read_keys;
    model.make_1d = make_user<1>;
    model.make_2d = make_user<2>;
    model.make_3d = make_user<3>;
    register_material_model(std::move(model));
  });
}

}  // namespace mpm::user_material
