// The note that names the optional modules a build lacks, appended to the messages about an unknown material
// model, top-level section or output field (by the program and the Python package). This build may have every
// module, so the list of missing modules is given explicitly.
#include <gtest/gtest.h>

#include "mpm/app/modules.hpp"

namespace {

using mpm::SceneError;
using mpm::app::missing_module_note;

TEST(MissingModuleNote, NamesTheModulesAndTheirOptionsForNamesAModuleCouldDefine) {
  const SceneError model({"s.yaml", 9, 12}, "materials.copper.model",
                         "unknown material model 'johnson_cook'; valid models: linear_elastic, neo_hookean");
  EXPECT_EQ(missing_module_note(model, {"plasticity"}),
            "; this build has no plasticity module (CMake option MPM_WITH_PLASTICITY=ON), whose models, sections "
            "and output fields are unknown to it");
  const SceneError section({"s.yaml", 20, 1}, "thermal", "unknown key 'thermal'; valid keys: dimension, grid");
  EXPECT_EQ(missing_module_note(section, {"thermal", "contact", "fluids"}),
            "; this build has no thermal, contact or fluids module (CMake options MPM_WITH_THERMAL=ON, "
            "MPM_WITH_CONTACT=ON, MPM_WITH_FLUIDS=ON), whose models, sections and output fields are unknown to it");
  const SceneError field({"s.yaml", 21, 22}, "output.fields[1]", "invalid value 'plastic_strain'; valid values: x");
  EXPECT_NE(missing_module_note(field, {"plasticity"}), "");
}

TEST(MissingModuleNote, StaysSilentForOtherErrorsAndCompleteBuilds) {
  const SceneError model({"s.yaml", 9, 12}, "materials.copper.model", "unknown material model 'rubberish'");
  EXPECT_EQ(missing_module_note(model, {}), "");
  const SceneError nested_key({"s.yaml", 5, 3}, "bodies[0].spin", "unknown key 'spin'; valid keys: name");
  EXPECT_EQ(missing_module_note(nested_key, {"plasticity"}), "");
  const SceneError range({"s.yaml", 5, 3}, "bodies[0].shape.radius", "out of range: must be > 0 m, got -1 m");
  EXPECT_EQ(missing_module_note(range, {"plasticity"}), "");
}

}  // namespace
