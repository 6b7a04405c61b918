// `grid.boundary.FACE: {type: absorbing, ...}` (docs/scene-reference.md, grid; docs/theory.md §19): Lysmer &
// Kuhlemeyer's viscous dashpots (eq. 19.1), and with `input_velocity` the compliant base of Joyner & Chen (eq. 19.3).
// The impedances come from the keys density, p_wave_speed and s_wave_speed, required: they are the material beyond
// the face (for a truncated body, its own), which the face's reader cannot know. The input is a list of expressions
// of t or a CSV time history (io/time_table.hpp), read here so that its errors stop the scene before a run.
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "kinds.hpp"
#include "mpm/boundary/absorbing_face.hpp"
#include "mpm/boundary/face.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/io/time_table.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::boundary {
namespace {
// Named in a namespace of this file's own, so that the folder's sources also compile as one translation unit
// (scripts/tidy.sh).
namespace absorbing {

constexpr const char* why_keys =
    " (the dashpots rho c_p and rho c_s of an absorbing face are those of the material beyond the face: for a body "
    "that continues there, its density, c_p = sqrt((lambda + 2 mu) / rho) and c_s = sqrt(mu / rho))";

template <int Dim>
std::unique_ptr<FaceCondition<Dim>> make(const std::any& spec, const GridGeometry<Dim>& g, int face) {
  return std::make_unique<AbsorbingFace<Dim>>(g, face, std::any_cast<const AbsorbingFaceSpec&>(spec));
}

/// `input_velocity: [e_x, e_y, ...]` (expressions of t, m/s) or `{file: F}` (a CSV with columns t, vx, vy, vz).
std::function<std::array<Real, 3>(Real)> read_input(const io::YamlReader& reader, const io::YamlValue& value,
                                                    int dimension) {
  if (value.node.IsMap()) {
    const io::YamlMap map = reader.map(value);
    map.allow({"file"});
    const io::YamlValue file = map.required("file", "key", " (a CSV time history with columns t, vx, ...)");
    const std::string name = reader.name(file);
    std::filesystem::path path(name);
    if (path.is_relative()) path = std::filesystem::path(reader.file()).parent_path() / path;
    std::error_code error;
    if (!std::filesystem::exists(path, error))
      reader.fail(file, fmt::format("ground motion file '{}' not found (looked for {})", name, path.string()));
    const std::vector<std::string> all{"vx", "vy", "vz"};
    std::shared_ptr<const io::TimeTable> table;
    try {
      table = std::make_shared<const io::TimeTable>(
          io::read_time_table(path.lexically_normal(), std::vector<std::string>(all.begin(), all.begin() + dimension)));
    } catch (const io::TimeTableError& e) {
      reader.fail(file, e.what());
    }
    return [table](Real t) { return table->at(t); };
  }
  const auto components = reader.list(value, static_cast<std::size_t>(dimension), "components");
  std::vector<std::shared_ptr<const Expression>> e;
  e.reserve(components.size());
  for (int d = 0; d < dimension; ++d)
    e.push_back(std::make_shared<const Expression>(
        reader.expression(components[static_cast<std::size_t>(d)], {"t"}, "m/s"), std::vector<std::string>{"t"}));
  return [e](Real t) {
    std::array<Real, 3> v{0, 0, 0};
    for (std::size_t d = 0; d < e.size(); ++d) v[d] = (*e[d])(0, 0, 0, t);
    return v;
  };
}

std::any parse(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face) {
  if (!value.node.IsMap())
    reader.fail(value, std::string("expected {type: absorbing, density: ..., p_wave_speed: ..., s_wave_speed: ...}") +
                           why_keys);
  const io::YamlMap map = reader.map(value);
  map.allow({"type", "density", "p_wave_speed", "s_wave_speed", "input_velocity"});
  AbsorbingFaceSpec spec;
  spec.density = reader.number(map.required("density", "key", why_keys), io::Range::above(0), "kg/m^3");
  spec.p_wave_speed = reader.number(map.required("p_wave_speed", "key", why_keys), io::Range::above(0), "m/s");
  // 1D has no tangential component: c_s is not needed there
  if (const auto s = face.dimension == 1 ? map.find("s_wave_speed")
                                         : std::optional(map.required("s_wave_speed", "key", why_keys))) {
    spec.s_wave_speed = reader.number(*s, io::Range::at_least(0), "m/s");
    if (!(spec.s_wave_speed < spec.p_wave_speed))
      reader.fail(*s, fmt::format("s_wave_speed {:g} m/s must be below p_wave_speed {:g} m/s (c_s / c_p = "
                                  "sqrt((1 - 2 nu) / (2 (1 - nu))) < 1 for an elastic solid)",
                                  spec.s_wave_speed, spec.p_wave_speed));
  }
  if (const auto input = map.find("input_velocity")) spec.input = read_input(reader, *input, face.dimension);
  return spec;
}

FaceTraits traits(const std::any&) {
  FaceTraits t;
  t.traction = t.does_work = true;
  t.not_implicit = "scheme: implicit does not support tractions yet (an absorbing face is a traction of the velocity)";
  t.not_contact =
      "an absorbing face's dashpot force depends on the nodal velocity, which contact splits into one field per body; "
      "not supported yet";
  return t;
}

}  // namespace absorbing
}  // namespace

FaceConditionKind absorbing_kind() {
  FaceConditionKind k;
  k.name = "absorbing";
  k.description =
      "viscous dashpots (Lysmer & Kuhlemeyer 1969): a traction -rho c_p v_n normal and -rho c_s v_t tangential on the "
      "face's nodes, which lets a wave out at normal incidence without reflection (docs/theory.md §19); with "
      "input_velocity the compliant base of a site response (Joyner & Chen 1975): rho c (2 v_in - v), which sends the "
      "incident wave v_in in and lets the reflected one out. Its work (energy absorbed or put in) enters the energy "
      "balance's W. Not with scheme implicit or contact";
  k.keys = {
      {"density", "kg/m^3", "required: the density of the material beyond the face (for a truncated body, its own)"},
      {"p_wave_speed", "m/s",
       "required: the P-wave speed of that material, c_p = sqrt((lambda + 2 mu) / rho) = sqrt(E (1 - nu) / (rho (1 + "
       "nu) (1 - 2 nu))); 1D: sqrt(E / rho) for a bar"},
      {"s_wave_speed", "m/s",
       "required in 2D and 3D (not read in 1D): the S-wave speed c_s = sqrt(mu / rho), below p_wave_speed; 0 for a "
       "fluid"},
      {"input_velocity", "m/s",
       "optional: the velocity of the incident (upgoing) wave, per component an expression of t (s), or {file: F}: a "
       "CSV relative to the scene's folder with a header t, vx, vy, vz (any of the scene's components; one missing "
       "is 0) and rows of increasing t, interpolated linearly and held at the first and last row's values outside "
       "them. The face's traction becomes rho c (2 v_in - v): a recorded outcrop motion is 2 v_in, so give half of "
       "it"},
  };
  k.bare = false;
  k.parse = absorbing::parse;
  k.traits = absorbing::traits;
  k.make_1d = absorbing::make<1>;
  k.make_2d = absorbing::make<2>;
  k.make_3d = absorbing::make<3>;
  return k;
}

}  // namespace mpm::boundary
