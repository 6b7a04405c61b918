// CPDI in a running simulation: tracked corners (eq. 3.38) move exactly with a rigid translation, the
// particle elements tile the body (their volumes add up to it), and the `domains` output writes one VTK
// cell per particle with the right cell type, whose areas/volumes add up to the body's.
#include <gtest/gtest.h>
#include <vtkCellType.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <Eigen/Geometry>

#include <filesystem>
#include <string>

#include "mpm/output/output_writer.hpp"
#include "mpm/shape/cpdi.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

using Vec2 = Vec<2>;

std::string box_scene(int dim, const std::string& shape, const std::string& extra_solver = "") {
  const std::string v = dim == 2 ? "[0.3, -0.2]" : "[0.3, -0.2, 0.1]";
  const std::string lo = dim == 2 ? "[0.3, 0.3]" : "[0.3, 0.3, 0.3]", hi = dim == 2 ? "[0.6, 0.5]" : "[0.6, 0.5, 0.5]";
  const std::string extent = dim == 2 ? "[1, 1]" : "[1, 1, 1]";
  return "dimension: " + std::to_string(dim) + "\ngrid: {extent: " + extent +
         ", cell_size: 0.1}\n"
         "materials:\n  m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}\n"
         "bodies:\n  - {material: m, shape: {type: box, min: " +
         lo + ", max: " + hi + "}, particles_per_cell: 2, velocity: " + v +
         "}\n"
         "solver: {scheme: musl, shape_function: " +
         shape + ", dt: 1.0e-3, end_time: 0.2" + extra_solver + "}\n";
}

TEST(CpdiSimulation, TrackedCornersFollowARigidTranslation) {
  auto sim = test::simulation_from_yaml<2>(box_scene(2, "cpdi_q4"));
  auto& p = sim->bodies()[0].particles;
  ASSERT_TRUE(p.has_field("cpdi_corners"));  // cpdi_q4 tracks its corners by default
  EXPECT_FALSE(p.has_field("cpdi_corner_offsets0"));
  // Corners by particle id: the particles are reordered by cell during the run.
  std::vector<CornerSet<2>> start(p.size());
  for (Index i = 0; i < p.size(); ++i) start[p.id[i]] = p.field<CornerSet<2>>("cpdi_corners")[i];
  sim->run();
  const Vec2 shift = Vec2(0.3, -0.2) * sim->time();
  const auto& corners = p.field<CornerSet<2>>("cpdi_corners");
  for (Index i = 0; i < p.size(); ++i)
    for (int c = 0; c < 4; ++c)
      ASSERT_LT((Vec2(corners[i][c]) - Vec2(start[p.id[i]][c]) - shift).norm(), 1e-12) << "particle " << i;
}

TEST(CpdiSimulation, DomainUpdateModes) {
  auto r4 = test::simulation_from_yaml<2>(box_scene(2, "cpdi_r4"));
  EXPECT_TRUE(r4->bodies()[0].particles.has_field("cpdi_corner_offsets0"));
  auto q4_with_F = test::simulation_from_yaml<2>(box_scene(2, "cpdi_q4", ", cpdi_domain_update: deformation_gradient"));
  EXPECT_FALSE(q4_with_F->bodies()[0].particles.has_field("cpdi_corners"));
  // Corner tracking is a module: only scenes that track corners construct it (every scene has the energy
  // sentinel, energy_sentinel.hpp, added last).
  ASSERT_EQ(r4->modules().size(), 1u);
  EXPECT_EQ(r4->modules()[0]->name(), "energy_sentinel");
  auto q4 = test::simulation_from_yaml<2>(box_scene(2, "cpdi_q4"));
  ASSERT_EQ(q4->modules().size(), 2u);
  EXPECT_EQ(q4->modules()[0]->name(), "cpdi_corner_tracking");
}

template <int Dim>
double cell_measure(vtkUnstructuredGrid* g, vtkIdType cell) {
  auto* ids = g->GetCell(cell)->GetPointIds();
  std::vector<Vec3> x(static_cast<std::size_t>(ids->GetNumberOfIds()));
  for (std::size_t k = 0; k < x.size(); ++k) g->GetPoint(ids->GetId(static_cast<vtkIdType>(k)), x[k].data());
  if (x.size() == 3) return 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
  if (Dim == 2) return 0.5 * ((x[1] - x[0]).cross(x[2] - x[0]).norm() + (x[2] - x[0]).cross(x[3] - x[0]).norm());
  return (x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0])) / 6;  // tetrahedron, right-handed
}

template <int Dim>
void check_domain_output(const std::string& shape, int vtk_type, double body_measure) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpm_cpdi_domains_" + shape);
  std::filesystem::remove_all(dir);
  auto sim = test::simulation_from_yaml<Dim>(box_scene(Dim, shape));
  OutputWriter<Dim> out(dir, "particles", {"velocity", "domains"}, false, 0);
  out.write(*sim);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "particles_domains_000000.vtu").c_str());
  reader->Update();
  auto* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfCells(), sim->bodies()[0].particles.size()) << shape;
  double total = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
    ASSERT_EQ(g->GetCellType(c), vtk_type) << shape;
    const double m = cell_measure<Dim>(g, c);
    ASSERT_GT(m, 0) << shape << " cell " << c << " is inverted";
    total += m;
  }
  EXPECT_NEAR(total, body_measure, 1e-12) << shape;
  EXPECT_TRUE(std::filesystem::exists(dir / "particles_domains.pvd"));
  std::filesystem::remove_all(dir);
}

TEST(CpdiSimulation, DomainsAreWrittenAsCellsThatTileTheBody) {
  check_domain_output<2>("cpdi_q4", VTK_QUAD, 0.3 * 0.2);
  check_domain_output<2>("cpdi_t3", VTK_TRIANGLE, 0.3 * 0.2);
  check_domain_output<2>("gimp", VTK_QUAD, 0.3 * 0.2);
  check_domain_output<3>("cpdi_tet4", VTK_TETRA, 0.3 * 0.2 * 0.2);
}

}  // namespace
}  // namespace mpm
