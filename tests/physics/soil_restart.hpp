#pragma once
// The exact-restart check of the soil models (test_soils.cpp, test_mu_i.cpp): a scene run to step 800 and saved,
// then on to 1600, against the same scene restored from the save and run to 1600; positions, stresses and the
// soil history (field `soil`) of every particle must be the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/soils/soil_batch.hpp"

namespace mpm::soils::test_support {

/// Runs the check on `yaml` (named `file` in messages, `label` in failures); returns the largest plastic strain at
/// the end, for the caller to assert that the saved state had flowed.
inline Real expect_exact_restart(const std::string& yaml, const std::string& file, const std::string& label) {
  auto reference = test::simulation_from_yaml<2>(yaml, file);
  reference->run({}, 800);
  StateArchive archive;
  reference->save_state(archive);
  reference->run({}, 1600);
  auto restarted = test::simulation_from_yaml<2>(yaml, file);
  restarted->restore_state(archive);
  EXPECT_EQ(restarted->step(), 800) << label;
  restarted->run({}, 1600);
  const auto& a = reference->bodies()[0].particles;
  const auto& b = restarted->bodies()[0].particles;
  EXPECT_EQ(a.size(), b.size()) << label;
  if (a.size() != b.size()) return 0;
  const auto& sa = a.field(keys::soil_state);
  const auto& sb = b.field(keys::soil_state);
  Real plastic = 0;
  for (Index i = 0; i < a.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(Vec<2>(a.x[i]), Vec<2>(b.x[i])) << label << " particle " << i;
    EXPECT_EQ(a.stress[i].full(), b.stress[i].full()) << label << " particle " << i;
    EXPECT_EQ(sa[k].plastic_strain, sb[k].plastic_strain) << label;
    EXPECT_EQ(sa[k].plastic_volumetric_strain, sb[k].plastic_volumetric_strain) << label;
    EXPECT_EQ(sa[k].plastic_work, sb[k].plastic_work) << label;
    plastic = std::max(plastic, sa[k].plastic_strain);
  }
  return plastic;
}

}  // namespace mpm::soils::test_support
