// CAD bodies (geometry/cad_region.hpp, `cad: FILE`): STEP, IGES and BREP files written here with OpenCASCADE
// (cad_fixtures.hpp) are read, their units honoured, their solids chosen by name or index, filled, and certified
// (mass_properties.hpp) against closed forms; bad files are refused with the file, the solid and the problem.
#ifdef MPM_WITH_OCCT
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "../apps/run_mpm.hpp"
#include "cad_fixtures.hpp"
#include "mpm/geometry/cad_region.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/mass_properties.hpp"
#include "mpm/geometry/register.hpp"
#include "mpm/geometry/shape_filler.hpp"

namespace fs = std::filesystem;
using namespace mpm;
using namespace mpm::geometry;

namespace {

fs::path cad_scratch() {
  const fs::path dir = fs::temp_directory_path() / ("mpm_geometry_cad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

CadShape cad_shape_of(const fs::path& file) {
  mpm::geometry::register_module();
  CadShape cad;
  cad.file = file.string();
  return cad;
}

GridGeometry<3> cad_grid(double lo, double hi, double h) {
  const int n = static_cast<int>(std::lround((hi - lo) / h));
  return GridGeometry<3>(Vec<3>::Constant(lo), Vec<3>::Constant(h), {n, n, n});
}

/// The box's volume, centroid and inertia (a x b x c at lower corner lo).
MassProperties box_properties(const Vec<3>& lo, double a, double b, double c) {
  MassProperties p;
  p.volume = a * b * c;
  p.centroid = lo + Vec<3>(a, b, c) / 2;
  p.inertia.diagonal() << p.volume * (b * b + c * c) / 12, p.volume * (a * a + c * c) / 12,
      p.volume * (a * a + b * b) / 12;
  return p;
}

/// The tube's (radii R > r, height h, axis z through (cx, cy), base z0).
MassProperties tube_properties(double cx, double cy, double z0, double R, double r, double h) {
  MassProperties p;
  p.volume = std::numbers::pi * (R * R - r * r) * h;
  p.centroid = Vec<3>(cx, cy, z0 + h / 2);
  const double side = p.volume * ((R * R + r * r) / 4 + h * h / 12);
  p.inertia.diagonal() << side, side, p.volume * (R * R + r * r) / 2;
  return p;
}

void expect_close_cad(const MassProperties& a, const MassProperties& b, double relative) {
  EXPECT_NEAR(a.volume, b.volume, relative * b.volume);
  const double length = std::cbrt(b.volume);
  EXPECT_LT((a.centroid - b.centroid).norm(), relative * length) << a.centroid.transpose();
  EXPECT_LT((a.inertia - b.inertia).cwiseAbs().maxCoeff(), relative * b.inertia.cwiseAbs().maxCoeff())
      << a.inertia << "\nexpected\n"
      << b.inertia;
}

/// The lattice particles of the region with their sub-cell volumes (what the certificate compares).
MassProperties cad_lattice_properties(const CadShape& cad, const GridGeometry<3>& grid, int ppc) {
  const auto seeds = fill_shape<3>(make_shape("cad", cad), grid, {ppc, ppc, ppc}, nullptr, false);
  return particle_properties(seeds.positions, std::vector<Real>(seeds.positions.size(), seeds.sub_cell_volume));
}

std::string cad_error_of(const CadShape& cad) {
  try {
    make_cad_region(cad, nullptr);
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// A box in a STEP file in metres: OpenCASCADE's exact properties equal the closed form (1e-9), and the lattice
// particles of a box aligned with the lattice tile it: volume and centroid exact (1e-12), each diagonal inertia
// lower by the sub-cells' own, V s^2 / 6 (s the particle spacing), which the certificate reports.
TEST(CadFill, BoxStepCertificate) {
  const fs::path file = cad_scratch() / "box.step";
  test::write_step(file, test::cad_box(0.1, 0.1, 0.1, 0.4, 0.2, 0.1));
  const CadShape cad = cad_shape_of(file);
  const auto region = make_cad_region(cad, nullptr);
  const auto source = exact_properties(*region);
  ASSERT_TRUE(source);
  const MassProperties closed = box_properties(Vec<3>(0.1, 0.1, 0.1), 0.4, 0.2, 0.1);
  expect_close_cad(source->exact, closed, 1e-9);
  EXPECT_NE(source->source.find("BRepGProp"), std::string::npos);

  const double h = 0.05, s = h / 2;
  const MassProperties particles = cad_lattice_properties(cad, cad_grid(0, 1, h), 2);
  MassProperties points = closed;
  points.inertia.diagonal().array() -= closed.volume * s * s / 6;
  expect_close_cad(particles, points, 1e-12);
  const FidelityCertificate c = certify(source->exact, particles, source->source);
  EXPECT_NEAR(c.volume_error, 0, 1e-12);
  EXPECT_NEAR(c.centroid_error, 0, 1e-12);
  EXPECT_NEAR(c.inertia_error, s * s / 6 / ((0.4 * 0.4 + 0.2 * 0.2) / 12), 1e-9);
  EXPECT_NE(format_certificate(c).find("relative error"), std::string::npos);
}

// A part modelled in millimetres comes in metres: a 20 x 10 x 5 mm box at (30, 0, 0) mm has 1e-6 m^3.
TEST(CadFill, MillimetreStepInMetres) {
  const fs::path file = cad_scratch() / "part_mm.step";
  test::write_step(file, test::cad_box(30, 0, 0, 20, 10, 5), "MM");
  const auto region = make_cad_region(cad_shape_of(file), nullptr);
  const auto source = exact_properties(*region);
  ASSERT_TRUE(source);
  expect_close_cad(source->exact, box_properties(Vec<3>(0.03, 0, 0), 0.02, 0.01, 0.005), 1e-9);
  EXPECT_NEAR(region->bounds().hi[0], 0.05, 1e-9);
}

// A cylinder with a hole (R = 0.2, r = 0.1, h = 0.3) as BREP (metres) and as IGES solid (millimetres): the B-rep's
// properties equal the closed form (1e-7; OpenCASCADE integrates the cylindrical faces by Gauss quadrature), the
// tessellation (tolerance 1e-4 m) is closed, and the lattice particles (spacing 0.0125 m) carry the volume within 2%
// and the inertia within 3% (lattice error ~ surface area x spacing / volume).
TEST(CadFill, TubeBrepAndIges) {
  const MassProperties closed = tube_properties(0.5, 0.5, 0.1, 0.2, 0.1, 0.3);
  const TopoDS_Shape tube = test::cad_tube(0.5, 0.5, 0.1, 0.2, 0.1, 0.3);
  for (const std::string name : {"tube.brep", "tube.iges"}) {
    SCOPED_TRACE(name);
    const fs::path file = cad_scratch() / name;
    if (name.ends_with(".brep"))
      test::write_brep(file, tube);
    else
      test::write_iges(file, test::cad_tube(500, 500, 100, 200, 100, 300), true);
    CadShape cad = cad_shape_of(file);
    cad.tolerance = 1e-4;
    CadSummary summary;
    const auto region = make_cad_region(cad, nullptr, &summary);
    EXPECT_EQ(summary.solids.size(), 1u);
    EXPECT_GT(summary.triangles, 100u);
    const auto source = exact_properties(*region);
    ASSERT_TRUE(source);
    expect_close_cad(source->exact, closed, 1e-7);
    EXPECT_FALSE(region->contains(Vec<3>(0.5, 0.5, 0.25)));  // in the hole
    EXPECT_TRUE(region->contains(Vec<3>(0.65, 0.5, 0.25)));
    const FidelityCertificate c = certify(source->exact, cad_lattice_properties(cad, cad_grid(0, 1, 0.025), 2), "");
    EXPECT_LT(std::abs(c.volume_error), 0.02);
    EXPECT_LT(c.centroid_error, 0.01);
    EXPECT_LT(c.inertia_error, 0.03);
  }
}

// A rotated box: the products of inertia follow R I R^T (the sign convention of OpenCASCADE's matrix is the
// tensor's, int (|r|^2 I - r r^T) dV).
TEST(CadFill, RotatedBoxInertia) {
  const fs::path file = cad_scratch() / "box_rotated.brep";
  test::write_brep(file, test::cad_box(-0.2, -0.1, -0.05, 0.4, 0.2, 0.1));
  CadShape cad = cad_shape_of(file);
  cad.rotation = {0, 0, 30};
  cad.translation = {0.5, 0.5, 0.5};
  const auto source = exact_properties(*make_cad_region(cad, nullptr));
  ASSERT_TRUE(source);
  MassProperties closed = box_properties(Vec<3>(-0.2, -0.1, -0.05), 0.4, 0.2, 0.1);
  const Mat<3> R = Eigen::AngleAxisd(std::numbers::pi / 6, Vec<3>::UnitZ()).toRotationMatrix();
  closed.inertia = R * closed.inertia * R.transpose();
  closed.centroid = Vec<3>(0.5, 0.5, 0.5);
  expect_close_cad(source->exact, closed, 1e-9);
  EXPECT_LT(closed.inertia(0, 1), 0);
  // and the mesh's own integrals agree with the B-rep for a flat-faced solid
  const auto particles = cad_lattice_properties(cad, cad_grid(0, 1, 0.02), 2);
  EXPECT_LT(certify(source->exact, particles, "").inertia_error, 0.03);
}

// A two-part assembly: parts are found by their product names, placed by the assembly's locations, and chosen by
// name or by index; a name the file does not carry is refused, listing those it does.
TEST(CadFill, AssemblyPartsByName) {
  const fs::path file = cad_scratch() / "assembly.step";
  test::write_assembly_step(file, {{"plate", test::cad_box(0, 0, 0, 0.6, 0.6, 0.1), gp_Vec(0.2, 0.2, 0.1)},
                                   {"projectile", test::cad_tube(0, 0, 0, 0.05, 0.02, 0.2), gp_Vec(0.5, 0.5, 0.3)}});
  EXPECT_EQ(cad_part_names(file.string()), (std::vector<std::string>{"plate", "projectile"}));
  CadShape plate = cad_shape_of(file);
  plate.parts = {"plate"};
  const auto plate_props = exact_properties(*make_cad_region(plate, nullptr));
  ASSERT_TRUE(plate_props);
  expect_close_cad(plate_props->exact, box_properties(Vec<3>(0.2, 0.2, 0.1), 0.6, 0.6, 0.1), 1e-9);
  CadShape projectile = cad_shape_of(file);
  projectile.solids = {1};
  const auto projectile_props = exact_properties(*make_cad_region(projectile, nullptr));
  ASSERT_TRUE(projectile_props);
  expect_close_cad(projectile_props->exact, tube_properties(0.5, 0.5, 0.3, 0.05, 0.02, 0.2), 1e-7);
  // both: the union, whose properties combine the two
  const auto both = exact_properties(*make_cad_region(cad_shape_of(file), nullptr));
  ASSERT_TRUE(both);
  expect_close_cad(both->exact, combine(plate_props->exact, projectile_props->exact), 1e-12);

  CadShape bolt = cad_shape_of(file);
  bolt.parts = {"bolt"};
  const std::string message = cad_error_of(bolt);
  EXPECT_NE(message.find("assembly.step: no part named 'bolt' in the file; its parts: 'plate', 'projectile'"),
            std::string::npos)
      << message;
  CadShape past = cad_shape_of(file);
  past.solids = {2};
  EXPECT_NE(cad_error_of(past).find("no solid #2: the file has 2 solids"), std::string::npos) << cad_error_of(past);
}

// Bad files: each refused with the file, the solid and what is wrong.
TEST(CadFill, BadFilesRefused) {
  const fs::path dir = cad_scratch();
  // a truncated STEP
  const fs::path whole = dir / "whole.step", truncated = dir / "truncated.step";
  test::write_step(whole, test::cad_tube(0, 0, 0, 0.2, 0.1, 0.3));
  {
    std::ifstream in(whole);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(truncated) << text.substr(0, text.size() / 2);
  }
  EXPECT_NE(cad_error_of(cad_shape_of(truncated)).find("truncated.step: "), std::string::npos);
  EXPECT_NE(cad_error_of(cad_shape_of(truncated)).find("STEP"), std::string::npos)
      << cad_error_of(cad_shape_of(truncated));
  // an IGES of surfaces only
  const fs::path surfaces = dir / "surfaces.iges";
  test::write_iges(surfaces, test::cad_face(), false);
  EXPECT_NE(cad_error_of(cad_shape_of(surfaces)).find("surfaces.iges: the file has no solid"), std::string::npos)
      << cad_error_of(cad_shape_of(surfaces));
  // an open solid
  const fs::path open = dir / "open.brep";
  test::write_brep(open, test::cad_open_box());
  EXPECT_NE(cad_error_of(cad_shape_of(open)).find("open.brep: solid #0 is open: 4 edges bound a single face"),
            std::string::npos)
      << cad_error_of(cad_shape_of(open));
  // not a CAD file at all
  const fs::path text = dir / "text.step";
  std::ofstream(text) << "hello\n";
  EXPECT_NE(cad_error_of(cad_shape_of(text)).find("text.step: cannot read the STEP file"), std::string::npos)
      << cad_error_of(cad_shape_of(text));
}

// Through the program: a scene makes one body per part (`parts`), `mpm particles FILE` prints the certificate and
// the solids; a part name the file does not carry, a truncated STEP and an IGES of surfaces exit with 2, naming the
// scene line, and write nothing.
TEST(CadFill, ScenesThroughTheProgram) {
  const fs::path dir = cli::scratch("cad_scenes");
  test::write_assembly_step(dir / "assembly.step",
                            {{"plate", test::cad_box(0, 0, 0, 0.6, 0.6, 0.1), gp_Vec(0.2, 0.2, 0.1)},
                             {"projectile", test::cad_tube(0, 0, 0, 0.05, 0.02, 0.2), gp_Vec(0.5, 0.5, 0.3)}});
  const auto scene = [&](const std::string& name, const std::string& shape) {
    std::ofstream(dir / name) << "dimension: 3\n"
                                 "grid: {origin: [0, 0, 0], extent: [1, 1, 1], cell_size: 0.05}\n"
                                 "materials: {steel: {model: linear_elastic, density: 7800, youngs_modulus: 2.0e11, "
                                 "poisson_ratio: 0.3}}\n"
                                 "bodies:\n"
                                 "  - name: part\n"
                                 "    material: steel\n"
                                 "    shape: "
                              << shape << "\nsolver: {dt: 1.0e-6, end_time: 1.0e-5}\n";
    return (dir / name).string();
  };
  auto r = cli::mpm("particles --scene " + scene("parts.yaml", "{cad: assembly.step, parts: [plate, projectile]}") +
                        " -o " + (dir / "p.vtu").string(),
                    dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("in 2 bodies"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("body 'part_plate'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("body 'part_projectile'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  body 'part_plate':\n    fidelity against the B-rep (OpenCASCADE BRepGProp):"),
            std::string::npos)
      << r.out;

  r = cli::mpm("particles " + (dir / "assembly.step").string() + " --spacing 0.02 -o " + (dir / "q.vtu").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("fidelity against the B-rep (OpenCASCADE BRepGProp)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("solids of " + (dir / "assembly.step").string() + ": #0 'plate', #1 'projectile'"),
            std::string::npos)
      << r.out;

  r = cli::mpm("check " + scene("bolt.yaml", "{cad: assembly.step, part: bolt}"), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bolt.yaml:7:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no part named 'bolt' in the file; its parts: 'plate', 'projectile'"), std::string::npos)
      << r.err;

  test::write_iges(dir / "surfaces.iges", test::cad_face(), false);
  r = cli::mpm("check " + scene("surfaces.yaml", "{cad: surfaces.iges}"), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("surfaces.iges: the file has no solid"), std::string::npos) << r.err;

  {
    std::ifstream in(dir / "assembly.step");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "truncated.step") << text.substr(0, text.size() / 3);
  }
  r = cli::mpm(
      "particles --scene " + scene("truncated.yaml", "{cad: truncated.step}") + " -o " + (dir / "t.vtu").string(), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("truncated.step: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "t.vtu"));

  // The reader is a plugin loaded by the first `cad:` body (geometry/src/cad_plugin.cpp): one that is missing or is
  // not the CAD reader is refused at the key, naming the file looked at. MPM_CAD_PLUGIN is then the only place.
  const std::string parts = scene("parts.yaml", "{cad: assembly.step, parts: [plate, projectile]}");
  r = cli::mpm("check " + parts, dir, "MPM_CAD_PLUGIN=" + (dir / "missing.so").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("parts.yaml:7:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the CAD reader plugin (libmpm_cad_occt.so, OpenCASCADE) could not be loaded:\n  " +
                       (dir / "missing.so").string() + ": not there"),
            std::string::npos)
      << r.err;
  std::ofstream(dir / "junk.so") << "not a library\n";
  r = cli::mpm("check " + parts, dir, "MPM_CAD_PLUGIN=" + (dir / "junk.so").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find((dir / "junk.so").string() + ": " + (dir / "junk.so").string()), std::string::npos)
      << r.err;  // dlopen's own message names the file
  r = cli::mpm("check " + parts, dir, std::string("MPM_CAD_PLUGIN=") + MPM_CAD_PLUGIN_FOR_TESTS);
  EXPECT_EQ(r.status, 0) << r.err;
  fs::remove_all(dir);
}

#endif  // MPM_WITH_OCCT
