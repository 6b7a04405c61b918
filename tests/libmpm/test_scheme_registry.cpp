// The scheme registry (scheme_registry.hpp): the core's four schemes with their traits, the traits against the
// schemes they make, the lists the refusals quote, and a scheme registered from outside the core (a copy of USL
// under another name) accepted by the loader and built by the builder with the same bits as USL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/schemes/scheme_registry.hpp"
#include "scene_fixture.hpp"
#include "two_disks_scene.hpp"

namespace mpm {
namespace {

const SchemeTraits& registered_traits(const char* name) {
  const SchemeSpec* spec = find_scheme(name);
  if (!spec) throw std::logic_error(std::string("not registered: ") + name);
  return spec->traits;
}

TEST(SchemeRegistry, CoreSchemesComeFirstWithTheirTraits) {
  const std::vector<std::string> names = scheme_names();
  ASSERT_GE(names.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 4),
            (std::vector<std::string>{"musl", "tlmpm", "usf", "usl"}));
  for (const char* name : {"musl", "tlmpm", "usf", "usl"}) {
    EXPECT_EQ(make_scheme<2>(name, "linear")->name(), name);
    EXPECT_TRUE(registered_traits(name).runs_distributed) << name;
    EXPECT_FALSE(registered_traits(name).unconditionally_stable) << name;
    EXPECT_FALSE(find_scheme(name)->description.empty()) << name;
  }
  // USL: one scatter per step, its stress from the un-mapped grid velocity, no release of separating contact nodes
  EXPECT_EQ(registered_traits("usl").scatters_per_step, 1);
  EXPECT_TRUE(registered_traits("usl").stress_update_without_remap);
  EXPECT_FALSE(registered_traits("usl").contact_releases_separating_nodes);
  for (const char* name : {"musl", "usf"}) {
    EXPECT_EQ(registered_traits(name).scatters_per_step, 2) << name;
    EXPECT_FALSE(registered_traits(name).stress_update_without_remap) << name;
    EXPECT_TRUE(registered_traits(name).contact_releases_separating_nodes) << name;
  }
  for (const char* name : {"musl", "usf", "usl"}) {
    EXPECT_FALSE(registered_traits(name).total_lagrangian) << name;
    EXPECT_TRUE(registered_traits(name).affine_transfers) << name;
    EXPECT_TRUE(registered_traits(name).contact) << name;
    EXPECT_EQ(registered_traits(name).bytes_per_particle, nullptr) << name;
  }
  const SchemeTraits& tl = registered_traits("tlmpm");
  EXPECT_TRUE(tl.total_lagrangian);
  EXPECT_FALSE(tl.affine_transfers);
  EXPECT_NE(tl.affine_transfers.why_not.find("Remark 35"), std::string::npos);
  EXPECT_FALSE(tl.contact);
  EXPECT_NE(tl.contact.why_not.find("reference configuration"), std::string::npos);
  // the factored stencil of tlmpm.hpp: 104 B per particle with hats in 3D (3 axes x 2 nodes x weight and
  // derivative x 8 B, and the base node), 152 B with the quadratic B-spline (support 3) in 3D
  ASSERT_NE(tl.bytes_per_particle, nullptr);
  EXPECT_EQ(tl.bytes_per_particle(3, 2), 104u);
  EXPECT_EQ(tl.bytes_per_particle(3, 3), 152u);
  EXPECT_EQ(tl.bytes_per_particle(1, 2), 40u);
  // the defaults (a hand-made HintContext) are MUSL's in every trait the energy hints ask
  const SchemeTraits defaults;
  EXPECT_EQ(defaults.total_lagrangian, registered_traits("musl").total_lagrangian);
  EXPECT_EQ(defaults.stress_update_without_remap, registered_traits("musl").stress_update_without_remap);
  EXPECT_EQ(defaults.unconditionally_stable, registered_traits("musl").unconditionally_stable);
}

// What a scheme declares agrees with what the scheme it makes does: every registered scheme that needs no keys of
// its own (the core's; a module's with `solver:` keys is checked by its module's tests).
TEST(SchemeRegistry, TraitsAgreeWithTheSchemesMade) {
  for (const std::string& name : scheme_names()) {
    const SchemeSpec& spec = *find_scheme(name);
    if (spec.parse) continue;
    const SchemeTraits& t = spec.traits;
    for (const char* shape : {"linear", "cubic_bspline", "gimp"}) {
      const auto check = [&](const auto& scheme) {
        EXPECT_EQ(scheme->shape_function(), shape);
        EXPECT_EQ(scheme->runs_distributed(), t.runs_distributed) << name;
        EXPECT_EQ(scheme->reorders_particles(), !t.total_lagrangian) << name;
        EXPECT_EQ(scheme->positions_must_stay_in_grid(), !t.total_lagrangian) << name;
      };
      check(make_scheme<1>(name, shape));
      check(make_scheme<2>(name, shape));
      check(make_scheme<3>(name, shape));
    }
    EXPECT_EQ(make_scheme<2>(name, "linear", Coordinates::axisymmetric)->shape_function(), "linear");
  }
}

TEST(SchemeRegistry, RefusalsListWhatWouldWork) {
  EXPECT_EQ(scheme_names_where([](const SchemeTraits& t) { return t.total_lagrangian; }), "tlmpm");
  // implicit, where it is compiled in, supports no contact either; the thermal module's heat analysis does (a pair's
  // finite conductance)
  EXPECT_EQ(scheme_names_where([](const SchemeTraits& t) { return t.contact.yes; }),
            find_scheme("heat") ? "musl, usf, usl or heat" : "musl, usf or usl");
  try {
    (void)make_scheme<2>("flip", "linear");
    FAIL() << "an unknown scheme was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown scheme 'flip' (valid: musl, tlmpm, usf"), std::string::npos)
        << e.what();
  }
  try {
    (void)make_scheme<2>("usf", "lagrange_quadratic");
    FAIL() << "lagrange_quadratic was made with usf";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "shape function 'lagrange_quadratic' is only valid with scheme tlmpm, not 'usf'");
  }
}

// A scheme registered by name only (here USL's makers and traits under another name, as a module would register
// its own) is a valid `solver.scheme`, is built through its maker, and gives the same bits as USL.
TEST(SchemeRegistry, ARegisteredSchemeJoinsTheLoaderAndTheBuilder) {
  SchemeSpec copy = *find_scheme("usl");
  copy.name = "usl_registered_copy";
  register_scheme(copy);
  EXPECT_EQ(scheme_names().back(), "usl_registered_copy");
  const auto run = [](const std::string& scheme) {
    std::string yaml = test::two_disks_scene("");
    yaml = yaml.substr(0, yaml.find("output:"));
    yaml.replace(yaml.find("scheme: musl"), std::strlen("scheme: musl"), "scheme: " + scheme);
    auto sim = test::simulation_from_yaml<2>(yaml);
    EXPECT_EQ(sim->scheme().name(), "usl");
    sim->run({}, Index{30});
    std::vector<Real> state;
    for (const auto& body : sim->bodies())
      for (Index i = 0; i < body.particles.size(); ++i)
        for (int d = 0; d < 2; ++d) {
          state.push_back(body.particles.x[i][d]);
          state.push_back(body.particles.v[i][d]);
        }
    return state;
  };
  const std::vector<Real> usl = run("usl"), copied = run("usl_registered_copy");
  ASSERT_FALSE(usl.empty());
  EXPECT_EQ(usl, copied);  // bit for bit
  // its traits are USL's: the solver's checks read them, not the name
  const SceneDescription scene = parse_scene(
      "dimension: 1\ngrid: {origin: [0], extent: [1], cell_size: 0.1}\nmaterials: {m: {model: linear_elastic, "
      "density: 1, youngs_modulus: 1, poisson_ratio: 0.3}}\nbodies: [{name: a, material: m, shape: {type: box, "
      "min: [0.2], max: [0.8]}}]\nsolver: {scheme: usl_registered_copy, cfl: 0.5, end_time: 1}\n",
      "copy.yaml");
  EXPECT_EQ(scene.solver.scheme, "usl_registered_copy");
  EXPECT_EQ(scheme_of(scene.solver).traits.scatters_per_step, 1);
}

}  // namespace
}  // namespace mpm
