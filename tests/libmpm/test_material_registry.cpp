/// Tests of the one material registration (material_registry.hpp), of the reference tables generated from it
/// (material_reference.hpp, scene_reference.hpp) and of the option enums (solver_options.hpp).

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "mpm/app/modules.hpp"
#include "mpm/material_reference.hpp"
#include "mpm/material_registry.hpp"
#include "mpm/scene_loader.hpp"
#include "mpm/scene_reference.hpp"

namespace {

using mpm::ParameterSpec;
using mpm::io::Range;

/// A model with one parameter of each kind, registered only in this test's process.
const char* const test_model = "registry_test_model";
void register_test_model() {
  mpm::MaterialModel model;
  model.key = test_model;
  model.description = "a model of the registry tests";
  model.parameters = {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference density rho0"),
      ParameterSpec::with_default("stiffness", "Pa", 2.5e9, Range::at_least(0), "a modulus | with a bar"),
      ParameterSpec::optional("switch", "-", Range::above_up_to(0, 1), "absent: off", "turns something on"),
      ParameterSpec::with_default("switch_gain", "-", 4, Range::any(), "belongs to switch").only_with("switch"),
  };
  model.check = [](const std::map<std::string, double>& values) -> std::optional<mpm::ParameterError> {
    if (values.count("switch_gain") && !values.count("switch"))
      return mpm::ParameterError{"switch_gain",
                                 "switch_gain needs switch; stiffness is " + std::to_string(values.at("stiffness"))};
    return std::nullopt;
  };
  mpm::register_material_model(model);
}

std::string scene_with(const std::string& material) {
  return "dimension: 1\ngrid: {extent: [1], cell_size: 0.1}\nmaterials:\n  m: {model: " + std::string(test_model) +
         material +
         "}\nbodies: [{material: m, shape: {type: box, min: [0], max: [1]}}]\nsolver: {cfl: 0.5, end_time: 1}\n";
}

TEST(MaterialRegistry, CoreModelsAreRegisteredWithTheirMakers) {
  for (const char* key : {"linear_elastic", "neo_hookean"}) {
    const mpm::MaterialModel* model = mpm::find_material_model(key);
    ASSERT_NE(model, nullptr) << key;
    EXPECT_EQ(model->parameters.size(), 3u);
    EXPECT_TRUE(model->make_1d && model->make_2d && model->make_3d) << key;
    mpm::MaterialDescription d{"m", key, {{"density", 1000}, {"youngs_modulus", 1e6}, {"poisson_ratio", 0.3}}, {}};
    EXPECT_EQ(mpm::make_material<2>(d)->model(), key);
    EXPECT_EQ(mpm::make_material<3>(d)->density(), 1000);
  }
  EXPECT_THROW(mpm::make_material<2>(mpm::MaterialDescription{"m", "no_such_model", {}, {}}), std::invalid_argument);
}

TEST(MaterialRegistry, LoaderFillsDefaultsFromTheSpecAndLeavesOptionalsOut) {
  register_test_model();
  const auto scene = mpm::parse_scene(scene_with(", density: 3"), "inline.yaml");
  const auto& p = scene.materials.at("m").parameters;
  EXPECT_EQ(p.at("density"), 3);
  EXPECT_EQ(p.at("stiffness"), 2.5e9);    // the spec's default
  EXPECT_EQ(p.count("switch"), 0u);       // optional, not given: absent
  EXPECT_EQ(p.count("switch_gain"), 0u);  // a parameter of a feature: absent unless given
  const auto given = mpm::parse_scene(scene_with(", density: 3, stiffness: 1, switch: 0.5"), "inline.yaml");
  const auto& material = given.materials.at("m");
  EXPECT_EQ(material.parameters.at("switch"), 0.5);
  EXPECT_EQ(material.parameters.count("switch_gain"), 0u);
  EXPECT_EQ(mpm::material_parameter(material, "switch_gain"), 4);  // the spec's default
  EXPECT_EQ(mpm::material_parameter(material, "stiffness"), 1);
  EXPECT_THROW(mpm::material_parameter(material, "no_such_parameter"), std::out_of_range);
}

TEST(MaterialRegistry, CheckSeesTheParametersOfAFeatureOnlyWhenGiven) {
  register_test_model();
  EXPECT_NO_THROW(mpm::parse_scene(scene_with(", density: 3"), "inline.yaml"));
  try {
    mpm::parse_scene(scene_with(", density: 3, switch_gain: 2"), "inline.yaml");
    FAIL() << "accepted";
  } catch (const mpm::SceneError& e) {
    EXPECT_EQ(e.key, "materials.m.switch_gain");
    EXPECT_EQ(e.message, "switch_gain needs switch; stiffness is 2500000000.000000");  // the default, filled in
  }
}

TEST(MaterialRegistry, RangeOfTheSpecIsTheReaderRange) {
  register_test_model();
  try {
    mpm::parse_scene(scene_with(", density: 3, switch: 0"), "inline.yaml");
    FAIL() << "accepted";
  } catch (const mpm::SceneError& e) {
    EXPECT_EQ(e.message, "out of range: must be in (0, 1], got 0");
  }
}

TEST(MaterialReference, WritesTheSpecAsATable) {
  register_test_model();
  const std::string table = mpm::material_reference_block(std::string("parameters of ") + test_model);
  EXPECT_EQ(table,
            "| Parameter | Unit | Default | Allowed values | Description |\n"
            "|---|---|---|---|---|\n"
            "| `density` | kg/m^3 | required | > 0 | reference density rho0 |\n"
            "| `stiffness` | Pa | 2500000000 | >= 0 | a modulus \\| with a bar |\n"
            "| `switch` | - | absent: off | in (0, 1] | turns something on |\n"
            "| `switch_gain` | - | 4 (with `switch`) | any | belongs to switch |\n");
}

TEST(MaterialReference, SharedAndSpecificParametersOfTwoModels) {
  register_test_model();
  // The two core models declare the same parameters: all shared, none specific.
  const std::string shared = mpm::material_reference_block(std::string("parameters of linear_elastic, neo_hookean"));
  EXPECT_NE(shared.find("| `youngs_modulus` | Pa | required | > 0 | Young's modulus E |"), std::string::npos);
  const std::string specific =
      mpm::material_reference_block(std::string("parameters specific to linear_elastic, neo_hookean"));
  EXPECT_EQ(specific,
            "| Model | Parameter | Unit | Default | Allowed values | Description |\n|---|---|---|---|---|---|\n");
}

TEST(MaterialReference, LeavesBlocksOfUnknownModelsAndRejectsBrokenOnes) {
  const std::string begin = "<!-- generated by `mpm reference`: parameters of no_such_model -->\n";
  const std::string document = "text\n" + begin + "| old |\n<!-- end of generated text -->\nafter\n";
  const auto update = mpm::update_scene_reference(document);
  EXPECT_EQ(update.text, document);
  EXPECT_EQ(update.blocks, 0);
  ASSERT_EQ(update.skipped.size(), 1u);
  EXPECT_EQ(update.skipped[0], "parameters of no_such_model");
  EXPECT_THROW(mpm::update_scene_reference("x\n" + begin + "| old |\n"), std::invalid_argument);
  EXPECT_THROW(mpm::update_scene_reference("<!-- generated by `mpm reference`: tables -->\n<!-- end of generated "
                                           "text -->\n"),
               std::invalid_argument);
}

// The traits the modules ask instead of model keys: how thermal expansion enters (heat conduction) and whether the
// model gives the implicit scheme its algorithmic stress.
TEST(MaterialRegistry, TraitsTheModulesAsk) {
  mpm::app::register_modules();
  const auto model = [](const char* key) { return *mpm::find_material_model(key); };
  EXPECT_EQ(model("linear_elastic").thermal_expansion, mpm::ThermalExpansion::by_heat_conduction);
  EXPECT_EQ(model("neo_hookean").thermal_expansion, mpm::ThermalExpansion::unsupported);
  EXPECT_FALSE(model("linear_elastic").implicit_stress);
#ifdef MPM_WITH_PLASTICITY
  EXPECT_EQ(model("johnson_cook").thermal_expansion, mpm::ThermalExpansion::in_update);
  EXPECT_EQ(model("j2_plasticity").thermal_expansion, mpm::ThermalExpansion::in_update);
  EXPECT_TRUE(model("hencky_j2").implicit_stress);
  EXPECT_EQ(mpm::material_model_names_where([](const mpm::MaterialModel& m) { return m.implicit_stress; }),
            "hencky_j2");
  EXPECT_EQ(mpm::material_model_names_where(
                [](const mpm::MaterialModel& m) { return m.thermal_expansion != mpm::ThermalExpansion::unsupported; }),
            "j2_plasticity, johnson_cook and linear_elastic");
#endif
}

TEST(SolverOptions, NamesAreWrittenOnce) {
  EXPECT_EQ(mpm::enum_names<mpm::VelocityTransfer>(), (std::vector<std::string>{"flip", "apic", "polypic"}));
  EXPECT_EQ(mpm::enum_names<mpm::CpdiDomainUpdate>(), (std::vector<std::string>{"deformation_gradient", "corners"}));
}

TEST(Range, DescribesItsBounds) {
  EXPECT_EQ(Range::above(0).describe("Pa"), "> 0 Pa");
  EXPECT_EQ(Range::at_least(1).describe("-"), ">= 1");
  EXPECT_EQ(Range::open(-1, 0.5).describe(""), "in (-1, 0.5)");
  EXPECT_EQ(Range::closed(0, 1).describe(""), "in [0, 1]");
  EXPECT_EQ(Range::any().describe("m"), "any");
  EXPECT_TRUE(Range::above_up_to(0, 1).contains(1));
  EXPECT_FALSE(Range::above_up_to(0, 1).contains(0));
}

}  // namespace
