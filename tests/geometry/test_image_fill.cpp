// Images to particles (geometry/image_region.hpp): PNG, PGM and VTK .vti files written here, so the
// selected pixels are known exactly; areas against pi r^2, labels, orientation (y up) and every error.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/image_region.hpp"
#include "mpm/geometry/register.hpp"
#include "mpm/geometry/shape_filler.hpp"

namespace fs = std::filesystem;
using namespace mpm;
using namespace mpm::geometry;

namespace {

fs::path image_scratch() {
  const fs::path dir = fs::temp_directory_path() / ("mpm_geometry_image_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

/// A picture of nx x ny pixels with `components` channels; value(i, row) with row 0 at the TOP as the
/// picture is displayed (the order of the rows in the file).
std::vector<unsigned char> picture(int nx, int ny, int components,
                                   const std::function<unsigned char(int, int)>& value_at_column_row) {
  std::vector<unsigned char> pixels;
  for (int row = 0; row < ny; ++row)
    for (int i = 0; i < nx; ++i)
      for (int c = 0; c < components; ++c) pixels.push_back(value_at_column_row(i, row));
  return pixels;
}

/// Writes a PNG through VTK (VTK's row 0 is the bottom row of the picture).
void write_png(const fs::path& file, int nx, int ny, int components, const std::vector<unsigned char>& top_down) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int row = 0; row < ny; ++row)
    for (int i = 0; i < nx * components; ++i)
      data[(ny - 1 - row) * nx * components + i] = top_down[row * nx * components + i];
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(file.c_str());
  writer->SetInputData(image);
  writer->Write();
}

/// Binary PGM (P5), rows top-down as in the file.
void write_pgm(const fs::path& file, int nx, int ny, const std::vector<unsigned char>& top_down) {
  std::ofstream out(file, std::ios::binary);
  out << "P5\n" << nx << ' ' << ny << "\n255\n";
  out.write(reinterpret_cast<const char*>(top_down.data()), static_cast<std::streamsize>(top_down.size()));
}

ShapeDescription image_shape(const fs::path& file, double pixel, std::optional<double> threshold,
                             std::optional<double> label = std::nullopt) {
  mpm::geometry::register_module();  // the image kind
  ImageShape image;
  image.file = file.string();
  image.pixel_size = {pixel, pixel, pixel};
  image.threshold = threshold;
  image.label = label;
  return make_shape("image", image);
}

/// A disk of radius r (pixels) centred in an n x n picture: 255 inside, 0 outside.
unsigned char disk(int i, int row, int n, double r) {
  const double dx = i + 0.5 - n / 2.0, dy = row + 0.5 - n / 2.0;
  return dx * dx + dy * dy <= r * r ? 255 : 0;
}

double total(const ParticleSeeds<2>& s) { return s.volume * static_cast<double>(s.positions.size()); }

}  // namespace

// A disk of radius 150 pixels of 1 mm: area pi 0.15^2 m^2 within 1% (pixelisation error ~1e-4), from the
// PNG and from the same picture as PGM, on the grid lattice and one particle per pixel.
TEST(ImageFill, DiskAreaFromPngAndPgm) {
  const fs::path dir = image_scratch();
  const int n = 400;
  const auto pixels = picture(n, n, 1, [&](int i, int row) { return disk(i, row, n, 150); });
  write_png(dir / "disk.png", n, n, 1, pixels);
  write_pgm(dir / "disk.pgm", n, n, pixels);
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.01), {40, 40});
  const double exact = M_PI * 0.15 * 0.15;
  for (const char* name : {"disk.png", "disk.pgm"}) {
    const auto shape = image_shape(dir / name, 1e-3, 128);
    const auto seeds = fill_shape<2>(shape, g, {4, 4, 1}, nullptr);
    EXPECT_NEAR(total(seeds) / exact, 1, 0.01) << name;
    EXPECT_NEAR(seeds.sub_cell_volume * static_cast<double>(seeds.positions.size()) / exact, 1, 0.01) << name;
    auto pixel_shape = shape;
    pixel_shape.as<ImageShape>().pixel_particles = true;
    const auto pixels_seeds = fill_shape<2>(pixel_shape, g, {4, 4, 1}, nullptr);
    EXPECT_NEAR(total(pixels_seeds) / exact, 1, 0.01) << name;
    EXPECT_DOUBLE_EQ(pixels_seeds.volume, 1e-6);
    EXPECT_NEAR(total(pixels_seeds), total(seeds), 1e-15) << "both sum to the selected pixel area";
  }
  fs::remove_all(dir);
}

// Row 0 of the file is the top of the picture: a block in the top-left corner gives particles at small x
// and large y. The origin shifts the image. Colour pictures use the mean of R, G and B.
TEST(ImageFill, YPointsUpAndOriginShifts) {
  const fs::path dir = image_scratch();
  const auto pixels = picture(20, 10, 3, [](int i, int row) { return i < 5 && row < 2 ? 200 : 10; });
  write_png(dir / "corner.png", 20, 10, 3, pixels);
  auto shape = image_shape(dir / "corner.png", 0.1, 100);
  shape.as<ImageShape>().origin = std::array<double, 3>{1, 2, 0};
  shape.as<ImageShape>().pixel_particles = true;
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {40, 40});
  const auto seeds = fill_shape<2>(shape, g, {1, 1, 1}, nullptr);
  ASSERT_EQ(seeds.positions.size(), 10u);
  for (const auto& x : seeds.positions) {
    EXPECT_GT(x[0], 1.0);
    EXPECT_LT(x[0], 1.5);
    EXPECT_GT(x[1], 2.8);  // top two rows of ten: y in [2.8, 3.0]
    EXPECT_LT(x[1], 3.0);
  }
}

// A label image: three disks with grey values 50, 100 and 200; each label is its own body with the area
// of its pixels.
TEST(ImageFill, LabelsSelectOneBodyEach) {
  const fs::path dir = image_scratch();
  const int n = 300;
  const auto pixels = picture(n, n, 1, [&](int i, int row) -> unsigned char {
    const auto in = [&](double cx, double cy, double r) {
      return (i + 0.5 - cx) * (i + 0.5 - cx) + (row + 0.5 - cy) * (row + 0.5 - cy) <= r * r;
    };
    if (in(75, 75, 60)) return 50;
    if (in(225, 75, 50)) return 100;
    if (in(150, 220, 70)) return 200;
    return 0;
  });
  write_png(dir / "labels.png", n, n, 1, pixels);
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.02), {20, 20});
  const struct { double label, radius_px; } cases[] = {{50, 60}, {100, 50}, {200, 70}};
  for (const auto& c : cases) {
    const auto seeds =
        fill_shape<2>(image_shape(dir / "labels.png", 1e-3, std::nullopt, c.label), g, {4, 4, 1}, nullptr);
    const double exact = M_PI * std::pow(c.radius_px * 1e-3, 2);
    EXPECT_NEAR(total(seeds) / exact, 1, 0.01) << "label " << c.label;
  }
  fs::remove_all(dir);
}

// A 3D label stack as .vti: a ball of label 1 (radius 20 voxels of 1 mm) in a 64^3 image whose spacing
// and origin come from the file.
TEST(ImageFill, VtiStackGivesA3dBody) {
  const fs::path dir = image_scratch();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(64, 64, 64);
  image->SetSpacing(1e-3, 1e-3, 1e-3);
  image->SetOrigin(0.0005, 0.0005, 0.0005);  // voxel centres: the image's lower corner is at 0
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  std::size_t voxels = 0;
  for (int k = 0; k < 64; ++k)
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) {
        const double r2 = std::pow(i + 0.5 - 32, 2) + std::pow(j + 0.5 - 32, 2) + std::pow(k + 0.5 - 32, 2);
        const bool in = r2 <= 400;
        v[i + 64 * (j + 64 * k)] = in ? 1 : 0;
        voxels += in;
      }
  auto writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
  writer->SetFileName((dir / "ball.vti").c_str());
  writer->SetInputData(image);
  writer->Write();
  ShapeDescription s = image_shape(dir / "ball.vti", 0, std::nullopt, 1);
  const GridGeometry<3> g(Vec<3>::Zero(), Vec<3>::Constant(0.004), {16, 16, 16});
  const auto seeds = fill_shape<3>(s, g, {2, 2, 2}, nullptr);
  const double selected = static_cast<double>(voxels) * 1e-9;
  EXPECT_NEAR(seeds.volume * static_cast<double>(seeds.positions.size()), selected, 1e-12 * selected);
  EXPECT_NEAR(selected / (4.0 / 3 * M_PI * std::pow(0.02, 3)), 1, 0.01);
  // A lattice point lies in a selected voxel, whose centre is within 20 voxels of the ball's centre.
  for (const auto& x : seeds.positions)
    EXPECT_LE((x - Vec<3>::Constant(0.032)).norm(), 0.02 + std::sqrt(3.0) / 2 * 1e-3);
  fs::remove_all(dir);
}

// Bad images: errors name the file and the problem.
TEST(ImageFill, BadImagesAreRefused) {
  const fs::path dir = image_scratch();
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {10, 10});
  const auto error = [&](const ShapeDescription& s) -> std::string {
    try {
      fill_shape<2>(s, g, {1, 1, 1}, nullptr);
    } catch (const GeometryError& e) {
      return e.what();
    }
    return "";
  };
  const auto black = picture(10, 10, 1, [](int, int) { return 0; });
  write_png(dir / "black.png", 10, 10, 1, black);
  std::string m = error(image_shape(dir / "black.png", 0.01, 128));
  EXPECT_NE(m.find("black.png: no pixel reaches the threshold 128 (the values in the image range from 0 to 0)"),
            std::string::npos)
      << m;
  m = error(image_shape(dir / "black.png", 0.01, std::nullopt, 3));
  EXPECT_NE(m.find("black.png: no pixel has the label 3"), std::string::npos) << m;
  std::ofstream(dir / "empty.png");
  m = error(image_shape(dir / "empty.png", 0.01, 1));
  EXPECT_NE(m.find("empty.png: the image file is empty"), std::string::npos) << m;
  std::ofstream(dir / "text.png") << "not a picture";
  m = error(image_shape(dir / "text.png", 0.01, 1));
  EXPECT_NE(m.find("text.png: cannot read the file as a PNG image"), std::string::npos) << m;
  m = error(image_shape(dir / "missing.png", 0.01, 1));
  EXPECT_NE(m.find("missing.png: image file not found"), std::string::npos) << m;
  // 10 x 10 pixels of 0.2 m = 2 m, the grid is 1 m wide.
  const auto white = picture(10, 10, 1, [](int, int) { return 255; });
  write_png(dir / "white.png", 10, 10, 1, white);
  m = error(image_shape(dir / "white.png", 0.2, 128));
  EXPECT_NE(m.find("white.png: lies outside the grid: on axis x it spans [0, 2] m, the grid [0, 1] m"),
            std::string::npos)
      << m;
  fs::remove_all(dir);
}
