// The grid density m_I / V_I of the grid output (mpm/grid/node_volume.hpp): V_I = ∫ φ_I dV sums to the grid's
// volume, and a body at rest maps its density onto the nodes it covers, half of it on a free face.
#include "mpm/grid/node_volume.hpp"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <filesystem>
#include <numbers>

#include "mpm/output/output_writer.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

template <int Dim>
Real total_node_volume(const GridGeometry<Dim>& g) {
  Real sum = 0;
  for (Index n = 0; n < g.node_count(); ++n) sum += node_volume(g, n);
  return sum;
}

// Σ_I φ_I = 1, so Σ_I ∫ φ_I dV is the grid's volume: Cartesian 1D, 2D, 3D and the revolved cylinder π R² H.
TEST(NodeVolume, SumsToTheGridVolume) {
  const GridGeometry<1> g1(Vec<1>(-0.3), Vec<1>(0.1), {7});
  EXPECT_NEAR(total_node_volume(g1), 0.7, 1e-15);
  const GridGeometry<2> g2(Vec<2>(0, 1), Vec<2>(0.1, 0.25), {5, 4});
  EXPECT_NEAR(total_node_volume(g2), 0.5 * 1.0, 1e-15);
  const GridGeometry<3> g3(Vec<3>(0, 0, 0), Vec<3>(0.1, 0.2, 0.05), {3, 2, 4});
  EXPECT_NEAR(total_node_volume(g3), 0.3 * 0.4 * 0.2, 1e-15);
  const GridGeometry<2> axisymmetric(Vec<2>(0, 0), Vec<2>(0.1, 0.2), {6, 3}, Coordinates::axisymmetric);
  const Real R = 0.6, H = 0.6;
  EXPECT_NEAR(total_node_volume(axisymmetric), std::numbers::pi * R * R * H, 1e-14);
}

/// The grid density of the first frame after one step of a block at rest (no load: the particles stay put).
std::vector<double> grid_density(const std::string& yaml, const std::string& name, std::array<int, 3>& dims) {
  auto sim = test::simulation_from_yaml<2>(yaml);
  sim->advance(1e-6);
  const auto dir = std::filesystem::path(MPM_BINARY_DIR) / ("test_node_volume_" + name);
  std::filesystem::remove_all(dir);
  OutputWriter<2> writer(dir, "p", {"velocity"}, true, 0);
  writer.write(*sim);
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName((dir / "p_grid_000000.vti").c_str());
  reader->Update();
  reader->GetOutput()->GetDimensions(dims.data());
  vtkDataArray* density = reader->GetOutput()->GetPointData()->GetArray("density");
  EXPECT_NE(density, nullptr);
  std::vector<double> values;
  if (density)
    for (vtkIdType i = 0; i < density->GetNumberOfTuples(); ++i) values.push_back(density->GetTuple1(i));
  std::filesystem::remove_all(dir);
  return values;
}

const std::string resting_block = R"(
dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1@COORDINATES@}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies: [{material: m, shape: {type: box, min: [@X0@, 0.2], max: [0.6, 0.5]}}]
solver: {scheme: musl, dt: 1.0e-6, end_time: 1}
)";

// Hats, 2 particles per cell per axis: ρ inside, ρ/2 on a free face, ρ/4 at a corner, 0 outside, to round-off:
// the contour ρ/2 is the body's outline.
TEST(NodeVolume, GridDensityOfABlockAtRest) {
  std::array<int, 3> dims{};
  const auto rho = grid_density(test::fill(resting_block, {{"COORDINATES", ""}, {"X0", "0.2"}}), "cartesian", dims);
  ASSERT_EQ(rho.size(), 121u);
  const auto at = [&](int i, int j) { return rho[static_cast<std::size_t>(i + dims[0] * j)]; };
  EXPECT_NEAR(at(4, 3), 1000, 1e-9);  // inside
  EXPECT_NEAR(at(2, 3), 500, 1e-9);   // on the face x = 0.2
  EXPECT_NEAR(at(4, 5), 500, 1e-9);   // on the face y = 0.5
  EXPECT_NEAR(at(6, 2), 250, 1e-9);   // a corner
  EXPECT_EQ(at(8, 8), 0);             // outside
}

// Axisymmetric (x = r, the block reaching the axis): ρ inside to round-off, the revolved volume 2π ∫ φ r dr; on the
// axis the particles' midpoint quadrature of φ r (concave there: no opposite half to cancel its error) gives 9/8 ρ.
TEST(NodeVolume, GridDensityOfARevolvedBlockAtRest) {
  std::array<int, 3> dims{};
  const auto rho = grid_density(
      test::fill(resting_block, {{"COORDINATES", ", coordinates: axisymmetric"}, {"X0", "0"}}), "axisymmetric", dims);
  ASSERT_EQ(rho.size(), 121u);
  const auto at = [&](int i, int j) { return rho[static_cast<std::size_t>(i + dims[0] * j)]; };
  EXPECT_NEAR(at(3, 3), 1000, 1e-9);  // inside
  EXPECT_NEAR(at(0, 3), 1125, 1e-9);  // on the axis
  EXPECT_NEAR(at(3, 5), 500, 1e-9);   // on the face z = 0.5
  // on the face r = 0.6: the particles' midpoint rule gives ∫ φ r dr over the inner half less h²/48, so
  // ρ (r h/2 - h²/6 - h²/48) / (r h) = 468.75 instead of 500 (a surface 0.03 cells further in)
  EXPECT_NEAR(at(6, 3), 1000 * (0.06 / 2 - 0.01 / 6 - 0.01 / 48) / 0.06, 1e-9);
}

}  // namespace
}  // namespace mpm
