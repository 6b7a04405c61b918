// The output-field table (output_fields.hpp): the core's fields and the modules' are in it, a new field is
// one registration (the scene loader accepts it and the writer writes it), and the builder's message for a
// field no body can give is assembled from the registrations.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "mpm/output/output_fields.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/scene/scene_error.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

std::string block_scene(const std::string& fields) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.25}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {type: box, min: [0.25, 0.25], max: [0.75, 0.75]}}]\n"
         "solver: {scheme: musl, cfl: 0.5, end_time: 1}\n"
         "output: {fields: [" +
         fields + "]}\n";
}

// The core's fields in the order of docs/scene-reference.md, `id` always written and not a choice; with the
// modules registered their fields follow.
TEST(OutputFields, CoreFieldsFirstThenTheModules) {
  app::register_modules();
  const auto names = output_field_names();
  const std::vector<std::string> core = {
      "velocity", "displacement",      "stress",   "deformation_gradient", "mass",        "volume", "density",
      "body",     "velocity_gradient", "pressure", "von_mises_stress",     "domain_size", "domains"};
  ASSERT_GE(names.size(), core.size());
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + core.size()), core);
  EXPECT_EQ(std::count(names.begin(), names.end(), "id"), 0);
  ASSERT_NE(find_output_field("id"), nullptr);
  EXPECT_EQ(find_output_field("stress")->components, 6);
  EXPECT_EQ(find_output_field("deformation_gradient")->components, 9);
  EXPECT_EQ(find_output_field("velocity")->unit, "m/s");
#ifdef MPM_WITH_PLASTICITY
  EXPECT_EQ(find_output_field("plastic_strain_rate")->unit, "1/s");
#endif
#ifdef MPM_WITH_THERMAL
  EXPECT_EQ(find_output_field("heat_flux")->components, 3);
  EXPECT_EQ(find_output_field("heat_flux")->unit, "W/m^2");
#endif
#if defined(MPM_WITH_THERMAL) || defined(MPM_WITH_PLASTICITY)
  EXPECT_EQ(std::count(names.begin(), names.end(), "temperature"), 1);  // registered by both, listed once
  EXPECT_EQ(find_output_field("temperature")->unit, "K");
#endif
}

// Adding a field is one registration: the scene loader accepts its name, the writer writes its values.
TEST(OutputFields, ANewFieldIsOneRegistration) {
  OutputField twice;
  twice.name = "test_twice_the_mass";
  twice.unit = "kg";
  twice.description = "2 m_p (a test field)";
  twice.append_with([](const auto& body, std::vector<double>& out) {
    for (const Real m : body.particles.mass) out.push_back(2 * m);
  });
  register_output_field(twice);
  auto sim = test::simulation_from_yaml<2>(block_scene("test_twice_the_mass, mass"));
  OutputWriter<2> writer(std::filesystem::temp_directory_path() / "mpm_output_fields_test", "p",
                         {"test_twice_the_mass", "mass"}, false, 0);
  const io::PointCloud cloud = writer.particle_cloud(*sim);
  std::filesystem::remove_all(writer.directory());
  ASSERT_EQ(cloud.fields.size(), 3u);  // and `id`
  EXPECT_EQ(cloud.fields[2].name, "id");
  ASSERT_EQ(cloud.fields[0].values.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(cloud.fields[0].values[i], 2 * cloud.fields[1].values[i]);
  // 0.5 x 0.5 m of 1000 kg/m^3 in 2 x 2 cells of 2 x 2 particles: 15.625 kg/m per particle
  EXPECT_EQ(cloud.size(), 16u);
  EXPECT_DOUBLE_EQ(cloud.fields[1].values[0], 1000 * 0.25 * 0.25 / 4);
}

// A field that reads a particle field no body carries: the message joins the registrations' remedies.
TEST(OutputFields, MissingCarrierMessageJoinsTheRemedies) {
  OutputField f = scalar_particle_output(FieldKey<Real>{"test_carried"}, "K", "a test field");
  f.carrier = "test_carried";
  f.absent = "no body carries it";
  f.remedies = {"give the first remedy"};
  register_output_field(f);
  auto sim = test::simulation_from_yaml<2>(block_scene("velocity"));
  const std::vector<std::string> asked = {"velocity", "test_carried"};
  EXPECT_EQ(*unavailable_output_field<2>(asked, sim->bodies()),
            "test_carried: no body carries it; give the first remedy or remove test_carried from the fields");
  f.remedies = {"the second"};  // a second module writing the same particle field
  register_output_field(f);
  EXPECT_EQ(*unavailable_output_field<2>(asked, sim->bodies()),
            "test_carried: no body carries it; give the first remedy, the second, or remove test_carried from the "
            "fields");
  EXPECT_FALSE(unavailable_output_field<2>({"velocity"}, sim->bodies()));
  // Registered again with other components: refused.
  f.components = 3;
  EXPECT_THROW(register_output_field(f), std::logic_error);
}

// The builder refuses the scene with that message (file, line, key), and the writer refuses a name that is
// not in the table.
TEST(OutputFields, UnknownNameIsRefused) {
  app::register_modules();
  auto sim = test::simulation_from_yaml<2>(block_scene("velocity"));
  std::vector<double> out;
  try {
    append_output_field<2>("strain", sim->bodies()[0], out);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown output field 'strain'");
  }
  EXPECT_THROW(test::simulation_from_yaml<2>(block_scene("strain")), SceneError);
}

}  // namespace
}  // namespace mpm
