/// Tests of numbers with units (core/units.hpp) and of the reader that converts them to each key's SI unit
/// (scene/yaml_reader.hpp): `youngs_modulus: 210 GPa` is 210e9 exactly, a unit of another dimension or an unknown one
/// is refused naming the key, and every unit a key spec declares is one the parser reads.

#include <gtest/gtest.h>

#include <functional>
#include <numbers>
#include <string>

#include "mpm/app/modules.hpp"
#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/core/units.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "scene_fixture.hpp"

namespace {

namespace units = mpm::units;

/// `text` ("210 GPa") converted to `key_unit`.
double value(const std::string& text, const std::string& key_unit) {
  const auto x = units::split_number(text);
  EXPECT_TRUE(x) << text;
  return units::to_key_unit(*x, key_unit);
}

/// The UnitError message of converting `text` to `key_unit`, or "" when it converts.
std::string refusal(const std::string& text, const std::string& key_unit) {
  try {
    value(text, key_unit);
  } catch (const units::UnitError& e) {
    return e.what();
  }
  return "";
}

TEST(Units, SiPrefixesConvertToTheCorrectlyRoundedValueOfWhatIsWritten) {
  // The decimal exponent moves in the text: the same double as the SI number written out.
  EXPECT_EQ(value("210 GPa", "Pa"), 210e9);
  EXPECT_EQ(value("7.85 g/cm^3", "kg/m^3"), 7850.0);
  EXPECT_EQ(value("7.85e-9 t/mm^3", "kg/m^3"), 7850.0);  // the mm-t-s system's density
  EXPECT_EQ(value("25 us", "s"), 25e-6);
  EXPECT_EQ(value("25 \u00b5s", "s"), 25e-6);  // µ, the micro sign
  EXPECT_EQ(value("25 \u03bcs", "s"), 25e-6);  // μ, the Greek mu
  EXPECT_EQ(value("5 mm", "m"), 5e-3);
  EXPECT_EQ(value("5mm", "m"), 5e-3);
  EXPECT_EQ(value("-800 m/s", "m/s"), -800.0);
  EXPECT_EQ(value("1.5 km/s", "m/s"), 1500.0);
  EXPECT_EQ(value("792 MPa", "Pa"), 792e6);
  EXPECT_EQ(value("200 N/mm^2", "Pa"), 200e6);
  EXPECT_EQ(value("3 bar", "Pa"), 3e5);
  EXPECT_EQ(value("1 kg/L", "kg/m^3"), 1000.0);
  EXPECT_EQ(value("9.81 m/s^2", "m/s^2"), 9.81);
  EXPECT_EQ(value("1e3 kg m^-3", "kg/m^3"), 1000.0);
  EXPECT_EQ(value("1e3 kg.m^-3", "kg/m^3"), 1000.0);
  EXPECT_EQ(value("1e3 kg*m^-3", "kg/m^3"), 1000.0);
  EXPECT_EQ(value("1e3 kg/m\u00b3", "kg/m^3"), 1000.0);  // kg/m³
  EXPECT_EQ(value("460 J/(kg K)", "J/(kg K)"), 460.0);
  EXPECT_EQ(value("0.46 kJ/(kg K)", "J/(kg K)"), 460.0);
  EXPECT_EQ(value("10 kW/(m^2 K)", "W/(m^2 K)"), 1e4);
  EXPECT_EQ(value("1 mPa s", "Pa s"), 1e-3);
  EXPECT_EQ(value("12 1/ms", "1/s"), 12e3);
  EXPECT_EQ(value("+5 mm", "m"), 5e-3);
  EXPECT_EQ(value("2 min", "s"), 120.0);
  EXPECT_EQ(value("1 h", "s"), 3600.0);
  EXPECT_EQ(value("1 ms", "s"), 1e-3);  // milli-second, not metre-second
  // A key in degrees takes degrees: 90 deg is 90; radians convert.
  EXPECT_EQ(value("90 deg", "degrees"), 90.0);
  EXPECT_NEAR(value("1 rad", "degrees"), 180 / std::numbers::pi, 1e-13);
  // No unit: the number as written, in the key's unit.
  EXPECT_EQ(value("2.0e11", "Pa"), 2.0e11);
  EXPECT_EQ(value("0.3", "-"), 0.3);
}

TEST(Units, AnotherDimensionIsRefusedNamingBoth) {
  EXPECT_EQ(refusal("210 GPa", "m"), "expected a length (m), got a pressure (GPa)");
  EXPECT_EQ(refusal("7.85 g/cm^3", "Pa"), "expected a pressure (Pa), got a density (g/cm^3)");
  EXPECT_EQ(refusal("5 mm", "-"), "expected a dimensionless number, got a length (mm)");
  EXPECT_EQ(refusal("5 mm", ""), "expected a dimensionless number, got a length (mm)");
  EXPECT_EQ(refusal("25 us", "m/s"), "expected a velocity (m/s), got a time (us)");
  EXPECT_EQ(refusal("90 deg", "-"), "expected a dimensionless number, got an angle (deg)");
  EXPECT_EQ(refusal("3 kg m", "Pa"), "expected a pressure (Pa), got a quantity in kg m (kg m)");
}

TEST(Units, AnUnknownOrMalformedUnitIsRefusedWithWhatWouldDo) {
  EXPECT_NE(refusal("210 Gpa", "Pa").find("unknown unit 'Gpa' (did you mean 'GPa'?)"), std::string::npos);
  EXPECT_NE(refusal("210 mpa", "Pa").find("(did you mean 'mPa' or 'MPa'?)"), std::string::npos);
  EXPECT_NE(refusal("3 psi", "Pa").find("unknown unit 'psi'"), std::string::npos);
  EXPECT_NE(refusal("3 psi", "Pa").find("m g s K N Pa J W"), std::string::npos);     // the units that would do
  EXPECT_NE(refusal("3 kmin", "s").find("unknown unit 'kmin'"), std::string::npos);  // min takes no prefix
  EXPECT_NE(refusal("7.85 g/cc", "kg/m^3").find("unknown unit 'cc' (did you mean 'cm^3'?)"), std::string::npos);
  EXPECT_NE(refusal("3 psi", "Pa").find("(imperial units are not read: write SI)"), std::string::npos);
  EXPECT_NE(refusal("20 C", "K").find("(temperatures are absolute: K)"), std::string::npos);
  EXPECT_NE(refusal("460 J/kg/K", "J/(kg K)").find("only one factor may follow '/' (write J/(kg K)"),
            std::string::npos);
  EXPECT_NE(refusal("460 J/kg K", "J/(kg K)").find("only one factor may follow '/'"), std::string::npos);
  EXPECT_NE(refusal("1 kg/(m^3", "kg/m^3").find("a '(' without its ')'"), std::string::npos);
  EXPECT_NE(refusal("1 kg/m^", "kg/m^3").find("expected an integer power after '^'"), std::string::npos);
  EXPECT_NE(refusal("1 m/", "m").find("a unit symbol is missing at the end"), std::string::npos);
}

TEST(Units, SplitNumberKeepsTheNumbersTextAndTrimsTheUnit) {
  const auto x = units::split_number("  -7.85e-9   t/mm^3 ");
  ASSERT_TRUE(x);
  EXPECT_EQ(x->number, -7.85e-9);
  EXPECT_EQ(x->number_text, "-7.85e-9");
  EXPECT_EQ(x->unit, "t/mm^3");
  EXPECT_FALSE(units::split_number("soft"));
  EXPECT_FALSE(units::split_number("inf"));
  EXPECT_FALSE(units::split_number(""));
}

/// Calls `visit` on every key spec below `keys`.
void each_key(const std::vector<mpm::io::KeySpec>& keys, const std::function<void(const mpm::io::KeySpec&)>& visit) {
  for (const auto& key : keys) {
    visit(key);
    each_key(key.keys, visit);
  }
}

TEST(Units, EveryUnitAKeyOrAParameterDeclaresIsOneTheParserReads) {
  mpm::app::register_modules();
  int units_read = 0;
  const auto parses = [&](const std::string& where, const std::string& unit) {
    EXPECT_NO_THROW(units::parse_unit(unit)) << where << ": '" << unit << "'";
    ++units_read;
  };
  each_key(mpm::scene_keys(), [&](const mpm::io::KeySpec& k) { parses(k.name, k.unit); });
  for (const auto& name : mpm::shape_kind_names())
    each_key(mpm::find_shape_kind(name)->keys, [&](const mpm::io::KeySpec& k) { parses(name + "." + k.name, k.unit); });
  for (const auto& model : mpm::material_model_names())
    for (const auto& p : mpm::material_parameters(*mpm::find_material_model(model)))
      parses(model + "." + p.name, p.unit);
  EXPECT_GT(units_read, 100);
}

mpm::SceneDescription load(const std::string& yaml) { return mpm::parse_scene(yaml, "units.yaml"); }

std::string disk_scene(const std::string& density, const std::string& modulus, const std::string& radius,
                       const std::string& velocity, const std::string& end_time) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1 m, 100 cm], cell_size: 50 mm}\n"
         "materials: {steel: {model: linear_elastic, density: " +
         density + ", youngs_modulus: " + modulus +
         ", poisson_ratio: 0.3}}\n"
         "bodies: [{name: disk, material: steel, shape: {type: disk, center: [0.5, 0.5], radius: " +
         radius + "}, velocity: [0, " + velocity +
         "]}]\n"
         "solver: {cfl: 0.5, end_time: " +
         end_time + ", gravity: [0, -9.81 m/s^2]}\n";
}

TEST(Units, ASceneWithUnitsReadsAsTheSameSceneInSi) {
  mpm::app::register_modules();
  const auto with_units = load(disk_scene("7.85 g/cm^3", "210 GPa", "200 mm", "-800 m/s", "25 us"));
  const auto si = load(disk_scene("7850", "210e9", "0.2", "-800", "25e-6"));
  const auto& a = with_units.materials.at("steel").parameters;
  const auto& b = si.materials.at("steel").parameters;
  EXPECT_EQ(a.at("density"), b.at("density"));
  EXPECT_EQ(a.at("youngs_modulus"), b.at("youngs_modulus"));
  EXPECT_EQ(with_units.solver.end_time, si.solver.end_time);
  EXPECT_EQ(with_units.bodies[0].velocity, si.bodies[0].velocity);
  EXPECT_EQ(with_units.grid.extent, si.grid.extent);
  EXPECT_EQ(with_units.grid.cell_size, si.grid.cell_size);
  EXPECT_EQ(with_units.solver.gravity, si.solver.gravity);
}

/// The message of loading `yaml`, or "" when it loads.
std::string load_error(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const mpm::SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Units, TheReaderNamesTheKeyOfAUnitItRefuses) {
  mpm::app::register_modules();

  EXPECT_NE(load_error(disk_scene("7850", "210e9", "210 GPa", "0", "1"))
                .find("bodies[0].shape.radius: expected a length (m), got a pressure (GPa)"),
            std::string::npos);
  EXPECT_NE(load_error(disk_scene("7850", "210e9", "0.2", "-800 m/ss", "1")).find("bodies[0].velocity[1]: "),
            std::string::npos);
  EXPECT_NE(load_error(disk_scene("7850", "210e9", "0.2", "-800 m/ss", "1")).find("unknown unit 'ss'"),
            std::string::npos);
  // A range is checked in SI, and says what was written.
  EXPECT_NE(load_error(disk_scene("7850", "-210 GPa", "0.2", "0", "1"))
                .find("materials.steel.youngs_modulus: out of range: must be > 0 Pa, got -210000000000 Pa (-210 GPa)"),
            std::string::npos);
  // An expression is still muparser's; a velocity of the wrong dimension is refused.
  EXPECT_EQ(load_error(disk_scene("7850", "210e9", "0.2", "\"-800*x\"", "1")), "");
  EXPECT_NE(
      load_error(disk_scene("7850", "210e9", "0.2", "-800 kg", "1")).find("expected a velocity (m/s), got a mass (kg)"),
      std::string::npos);
}

TEST(Units, AKeyWithoutAUnitRefusesOne) {
  const mpm::io::YamlReader reader("sample.yaml");
  const mpm::io::YamlValue value{YAML::Load("5 mm"), "image.threshold", YAML::Mark()};
  try {
    reader.number(value);
    FAIL() << "a unit on a key without one was accepted";
  } catch (const mpm::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("image.threshold: expected a plain number (this key has no unit), got '5 mm'"),
              std::string::npos)
        << e.what();
  }
}

/// `text` read as a bare number of `system` for a key in `key_unit`.
double in_system(const std::string& text, const std::string& key_unit, const std::string& system) {
  return units::to_key_unit(*units::split_number(text), key_unit, *units::find_unit_system(system));
}

// Each system's units are powers of ten of kg, m and s, so a bare number converts to the correctly rounded SI value
// of what it means: the same double as that value written in SI.
TEST(Units, AUnitSystemReadsBareNumbersInItsUnitsExactly) {
  EXPECT_EQ(in_system("7.85e-3", "kg/m^3", "mm-ms-g"), 7850.0);  // g/mm^3
  EXPECT_EQ(in_system("210000", "Pa", "mm-ms-g"), 210e9);        // MPa
  EXPECT_EQ(in_system("800", "m/s", "mm-ms-g"), 800.0);          // mm/ms
  EXPECT_EQ(in_system("0.025", "s", "mm-ms-g"), 25e-6);          // ms
  EXPECT_EQ(in_system("5", "m", "mm-ms-g"), 5e-3);               // mm
  EXPECT_EQ(in_system("10", "N", "mm-ms-g"), 10.0);              // g mm/ms^2 = N
  EXPECT_EQ(in_system("1", "J", "mm-ms-g"), 1e-3);               // N mm
  EXPECT_EQ(in_system("9.81e-3", "m/s^2", "mm-ms-g"), 9.81);     // mm/ms^2
  EXPECT_EQ(in_system("7.85e-9", "kg/m^3", "mm-s-tonne"), 7850.0);
  EXPECT_EQ(in_system("210000", "Pa", "mm-s-tonne"), 210e9);
  EXPECT_EQ(in_system("800000", "m/s", "mm-s-tonne"), 800.0);
  EXPECT_EQ(in_system("210", "Pa", "mm-ms-kg"), 210e9);  // GPa
  EXPECT_EQ(in_system("7.85", "kg/m^3", "cm-us-g"), 7850.0);
  EXPECT_EQ(in_system("2.1", "Pa", "cm-us-g"), 210e9);  // Mbar
  // Temperatures, angles and ratios are the same in every system; a number with its unit is that value in any.
  EXPECT_EQ(in_system("293.15", "K", "mm-ms-g"), 293.15);
  EXPECT_EQ(in_system("90", "degrees", "mm-ms-g"), 90.0);
  EXPECT_EQ(in_system("0.3", "-", "mm-ms-g"), 0.3);
  EXPECT_EQ(in_system("500", "J/(kg K)", "mm-ms-g"), 500.0);  // mm^2/(ms^2 K) = m^2/(s^2 K)
  EXPECT_EQ(in_system("210 GPa", "Pa", "mm-ms-g"), 210e9);
  EXPECT_EQ(in_system("25 us", "s", "mm-s-tonne"), 25e-6);
  EXPECT_EQ(in_system("210000", "Pa", "m-s-kg"), 210000.0);
  EXPECT_EQ(units::find_unit_system("mm-ms-gram"), nullptr);
}

/// The disk scene of disk_scene() in `system` with its numbers `numbers` substituted.
std::string system_scene(const std::string& system, const std::string& numbers) {
  return "dimension: 2\nunits: " + system + "\n" + numbers;
}

// A scene written in mm-ms-g is the SI scene: every number of the description the same double, so its run is the
// same bits; an expression of x, y, z, t in the system's units gives the same values to rounding.
TEST(Units, ASceneInMmMsGIsTheSceneInSi) {
  mpm::app::register_modules();
  const std::string mm = R"yaml(grid: {origin: [0, 0], extent: [1000, 1000], cell_size: 50}
materials: {steel: {model: linear_elastic, density: 7.85e-3, youngs_modulus: 210000, poisson_ratio: 0.3}}
bodies: [{name: disk, material: steel, shape: {type: disk, center: [500, 500], radius: 200},
          velocity: ["-0.8 * (y - 500)", "0.8 * (x - 500)"]
}]
solver: {cfl: 0.5, end_time: 0.025, gravity: [0, -9.81e-3]}
output: {interval: 0.005}
)yaml";
  const std::string si = R"yaml(grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}
materials: {steel: {model: linear_elastic, density: 7850, youngs_modulus: 210e9, poisson_ratio: 0.3}}
bodies: [{name: disk, material: steel, shape: {type: disk, center: [0.5, 0.5], radius: 0.2},
          velocity: ["-800 * (y - 0.5)", "800 * (x - 0.5)"]
}]
solver: {cfl: 0.5, end_time: 25e-6, gravity: [0, -9.81]}
output: {interval: 5e-6}
)yaml";
  const auto a = load(system_scene("mm-ms-g", mm));
  const auto b = load(system_scene("m-s-kg", si));
  EXPECT_EQ(a.units, "mm-ms-g");
  EXPECT_EQ(a.grid.extent, b.grid.extent);
  EXPECT_EQ(a.grid.cell_size, b.grid.cell_size);
  EXPECT_EQ(a.materials.at("steel").parameters, b.materials.at("steel").parameters);
  EXPECT_EQ(a.solver.end_time, b.solver.end_time);
  EXPECT_EQ(a.solver.gravity, b.solver.gravity);
  EXPECT_EQ(a.output.interval, b.output.interval);
  auto sim_a = mpm::test::simulation_from_yaml<2>(system_scene("mm-ms-g", mm));
  auto sim_b = mpm::test::simulation_from_yaml<2>(system_scene("m-s-kg", si));
  const auto& pa = sim_a->bodies()[0].particles;
  const auto& pb = sim_b->bodies()[0].particles;
  ASSERT_EQ(pa.size(), pb.size());
  ASSERT_GT(pa.size(), 100);
  double largest = 0;
  for (mpm::Index i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(mpm::Vec<2>(pa.x[i]), mpm::Vec<2>(pb.x[i]));
    largest = std::max(largest, (mpm::Vec<2>(pa.v[i]) - mpm::Vec<2>(pb.v[i])).norm());
  }
  EXPECT_LT(largest, 1e-12 * 160);  // the spin's rim speed is 160 m/s
}

// The unit system is a choice of the named ones; a slip gets "did you mean".
TEST(Units, AnUnknownUnitSystemIsRefusedWithTheValidOnes) {
  const std::string error = load_error("dimension: 2\nunits: mm-ms-gram\n");
  EXPECT_NE(error.find("units: "), std::string::npos) << error;
  EXPECT_NE(error.find("mm-ms-g"), std::string::npos) << error;
}

}  // namespace
