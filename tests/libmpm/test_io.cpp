// Output layer: .vtu/.vti writers, .pvd collection, CSV log, atomic replacement of files.
#include "mpm/io/atomic_file.hpp"
#include "mpm/io/csv_log.hpp"
#include "mpm/io/pvd_collection.hpp"
#include "mpm/io/vtk_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// A fresh directory per test, removed afterwards.
class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("mpm_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Names of the files in the test directory.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

mpm::io::PointCloud three_points() {
  mpm::io::PointCloud cloud;
  cloud.points = {0.0, 0.0, 0.0, 1.5, -2.25, 0.0, 1e-300, 0.1, 3.0};
  cloud.fields.push_back({"mass", 1, {1.0, 2.5, 0.1}});
  cloud.fields.push_back({"velocity", 3, {1, 2, 3, 4, 5, 6, 7, 8, -0.3}});
  std::vector<double> stress(18);
  for (std::size_t i = 0; i < stress.size(); ++i) stress[i] = 1.0 / (1.0 + static_cast<double>(i));
  cloud.fields.push_back({"stress", 6, stress});
  return cloud;
}

void expect_array(vtkDataArray* a, const mpm::io::FieldArray& f) {
  ASSERT_NE(a, nullptr) << f.name;
  ASSERT_EQ(a->GetNumberOfComponents(), f.components) << f.name;
  ASSERT_EQ(static_cast<std::size_t>(a->GetNumberOfValues()), f.values.size()) << f.name;
  EXPECT_EQ(a->GetDataType(), VTK_DOUBLE) << f.name;
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    const auto c = static_cast<int>(i % static_cast<std::size_t>(f.components));
    const auto t = static_cast<vtkIdType>(i / static_cast<std::size_t>(f.components));
    EXPECT_EQ(a->GetComponent(t, c), f.values[i]) << f.name << " value " << i;
  }
}

}  // namespace

TEST_F(IoTest, VtuRoundTripIsExact) {
  const auto cloud = three_points();
  const auto file = dir_ / "particles.vtu";
  mpm::io::write_vtu(file, cloud);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 3);
  ASSERT_EQ(grid->GetNumberOfCells(), 3);
  for (vtkIdType i = 0; i < 3; ++i) {
    EXPECT_EQ(grid->GetCellType(i), VTK_VERTEX);
    double x[3];
    grid->GetPoint(i, x);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(x[d], cloud.points[static_cast<std::size_t>(3 * i + d)]);
  }
  for (const auto& f : cloud.fields) expect_array(grid->GetPointData()->GetArray(f.name.c_str()), f);

  auto* stress = grid->GetPointData()->GetArray("stress");
  ASSERT_NE(stress, nullptr);
  const char* names[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  for (int c = 0; c < 6; ++c) {
    ASSERT_NE(stress->GetComponentName(c), nullptr);
    EXPECT_STREQ(stress->GetComponentName(c), names[c]);
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"particles.vtu"});  // no temporary left over
}

TEST_F(IoTest, VtuIsBinaryAppendedAndCompressed) {
  const auto file = dir_ / "particles.vtu";
  mpm::io::write_vtu(file, three_points());
  const auto text = read_text(file);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("format=\"appended\""), std::string::npos);
  EXPECT_NE(text.find("encoding=\"raw\""), std::string::npos);
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
}

TEST_F(IoTest, VtuWithNanThrowsAndLeavesNoFile) {
  auto cloud = three_points();
  cloud.fields[1].values[4] = std::numeric_limits<double>::quiet_NaN();  // velocity, point 1
  const auto file = dir_ / "particles.vtu";
  try {
    mpm::io::write_vtu(file, cloud);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("velocity"), std::string::npos) << what;
    EXPECT_NE(what.find("point 1"), std::string::npos) << what;
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(IoTest, VtuWithInfiniteCoordinateThrows) {
  auto cloud = three_points();
  cloud.points[7] = std::numeric_limits<double>::infinity();  // point 2, y
  try {
    mpm::io::write_vtu(dir_ / "particles.vtu", cloud);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("points"), std::string::npos) << what;
    EXPECT_NE(what.find("point 2"), std::string::npos) << what;
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(IoTest, VtuWithWrongFieldSizeThrows) {
  auto cloud = three_points();
  cloud.fields[0].values.pop_back();
  EXPECT_THROW(mpm::io::write_vtu(dir_ / "particles.vtu", cloud), std::runtime_error);
  cloud = three_points();
  cloud.fields[2].components = 9;
  EXPECT_THROW(mpm::io::write_vtu(dir_ / "particles.vtu", cloud), std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

TEST_F(IoTest, VtuWithNanKeepsPreviousFile) {
  const auto file = dir_ / "particles.vtu";
  write_text(file, "old");
  auto cloud = three_points();
  cloud.fields[0].values[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mpm::io::write_vtu(file, cloud), std::runtime_error);
  EXPECT_EQ(read_text(file), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"particles.vtu"});
}

TEST_F(IoTest, VtuIntoMissingDirectoryThrows) {
  EXPECT_THROW(mpm::io::write_vtu(dir_ / "missing" / "particles.vtu", three_points()), std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

TEST_F(IoTest, EmptyVtuIsReadable) {
  const auto file = dir_ / "empty.vtu";
  mpm::io::write_vtu(file, {});
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

TEST_F(IoTest, VtiRoundTripIsExact) {
  mpm::io::ImageGrid grid;
  grid.origin = {-1.0, 0.5, 0.0};
  grid.spacing = {0.25, 0.125, 1.0};
  grid.nodes = {3, 2, 1};
  std::vector<double> mass(6), momentum(18);
  for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = 0.1 * static_cast<double>(i);
  for (std::size_t i = 0; i < momentum.size(); ++i) momentum[i] = -1.0 / (3.0 + static_cast<double>(i));
  grid.fields.push_back({"mass", 1, mass});
  grid.fields.push_back({"momentum", 3, momentum});
  const auto file = dir_ / "grid.vti";
  mpm::io::write_vti(file, grid);

  const auto text = read_text(file);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("format=\"appended\""), std::string::npos);

  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 3);
  EXPECT_EQ(dims[1], 2);
  EXPECT_EQ(dims[2], 1);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(origin[d], grid.origin[static_cast<std::size_t>(d)]);
    EXPECT_EQ(spacing[d], grid.spacing[static_cast<std::size_t>(d)]);
  }
  // x fastest: node (i, j) is point i + 3 j.
  double x[3];
  image->GetPoint(4, x);
  EXPECT_EQ(x[0], -1.0 + 0.25);
  EXPECT_EQ(x[1], 0.5 + 0.125);
  for (const auto& f : grid.fields) expect_array(image->GetPointData()->GetArray(f.name.c_str()), f);
  EXPECT_EQ(entries(), std::vector<std::string>{"grid.vti"});
}

TEST_F(IoTest, VtiChecksSizesAndValues) {
  mpm::io::ImageGrid grid;
  grid.nodes = {2, 2, 1};
  grid.fields.push_back({"mass", 1, {1, 2, 3}});
  EXPECT_THROW(mpm::io::write_vti(dir_ / "grid.vti", grid), std::runtime_error);
  grid.fields[0].values = {1, 2, 3, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW(mpm::io::write_vti(dir_ / "grid.vti", grid), std::runtime_error);
  grid.fields[0].values = {1, 2, 3, 4};
  grid.nodes = {2, 2, 0};
  EXPECT_THROW(mpm::io::write_vti(dir_ / "grid.vti", grid), std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

TEST_F(IoTest, PvdListsTimestepsWithRelativePaths) {
  fs::create_directories(dir_ / "frames");
  mpm::io::PvdCollection pvd(dir_ / "particles.pvd");
  EXPECT_EQ(pvd.path(), dir_ / "particles.pvd");
  pvd.add(0.0, dir_ / "frames" / "particles_0000.vtu");
  pvd.write();
  pvd.add(0.1, dir_ / "frames" / "particles_0001.vtu");
  pvd.write();
  EXPECT_EQ(pvd.size(), 2u);

  const auto text = read_text(dir_ / "particles.pvd");
  EXPECT_EQ(text,
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/particles_0000.vtu\"/>\n"
            "    <DataSet timestep=\"0.10000000000000001\" group=\"\" part=\"0\" "
            "file=\"frames/particles_0001.vtu\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
  EXPECT_EQ(text.find(dir_.string()), std::string::npos);  // no absolute path
  auto names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frames", "particles.pvd"}));
  EXPECT_THROW(pvd.add(std::numeric_limits<double>::quiet_NaN(), dir_ / "x.vtu"), std::invalid_argument);
}

TEST_F(IoTest, CsvHeaderAndRows) {
  const auto file = dir_ / "energy.csv";
  mpm::io::CsvLog log(file, {"time", "kinetic", "strain"});
  EXPECT_EQ(log.path(), file);
  EXPECT_EQ(read_text(file), "time,kinetic,strain\n");
  log.append({0.0, 1.0, -2.5});
  log.append({0.1, 1e-20, 1.0 / 3.0});
  const std::string expected =
      "time,kinetic,strain\n"
      "0,1,-2.5\n"
      "0.10000000000000001,9.9999999999999995e-21,0.33333333333333331\n";
  EXPECT_EQ(read_text(file), expected);
  EXPECT_THROW(log.append({1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(log.append({1.0, 2.0, 3.0, 4.0}), std::invalid_argument);
  EXPECT_THROW(log.append({1.0, std::numeric_limits<double>::infinity(), 3.0}), std::invalid_argument);
  EXPECT_EQ(read_text(file), expected);  // unchanged by the rejected rows
  EXPECT_EQ(entries(), std::vector<std::string>{"energy.csv"});
}

TEST_F(IoTest, CsvNoDataIsAnEmptyCellAndAnyOtherNanIsRefused) {
  const auto file = dir_ / "probe.csv";
  mpm::io::CsvLog log(file, {"time", "value", "count"});
  log.append({0.0, mpm::io::no_data(), 0.0});
  log.append({0.5, mpm::io::no_data(), mpm::io::no_data()});
  EXPECT_THROW(log.append({1.0, std::numeric_limits<double>::quiet_NaN(), 0.0}), std::invalid_argument);
  EXPECT_EQ(read_text(file), "time,value,count\n0,,0\n0.5,,\n");
  EXPECT_TRUE(mpm::io::is_no_data(mpm::io::no_data()));
  EXPECT_FALSE(mpm::io::is_no_data(std::numeric_limits<double>::quiet_NaN()));
}

TEST_F(IoTest, AtomicWriteKeepsOldFileWhenWriterThrows) {
  const auto file = dir_ / "state.txt";
  write_text(file, "old content");
  EXPECT_THROW(mpm::io::write_atomically(file,
                                         [](const fs::path& tmp) {
                                           write_text(tmp, "half");
                                           throw std::runtime_error("disk full");
                                         }),
               std::runtime_error);
  EXPECT_EQ(read_text(file), "old content");
  EXPECT_EQ(entries(), std::vector<std::string>{"state.txt"});

  mpm::io::write_atomically(file, [&](const fs::path& tmp) {
    EXPECT_EQ(tmp.parent_path(), dir_);  // same directory, so the rename is atomic
    EXPECT_NE(tmp, file);
    write_text(tmp, "new content");
  });
  EXPECT_EQ(read_text(file), "new content");
  EXPECT_EQ(entries(), std::vector<std::string>{"state.txt"});
}
