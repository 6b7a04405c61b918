#include "mpm/geometry/image_region.hpp"

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPNMReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry {

namespace {

std::string lower_extension(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// The image's values from VTK's image data (point scalars, or the first point array).
Image to_image(vtkImageData* data, const std::string& file, int dimension) {
  Image image;
  image.dimension = dimension;
  int dims[3];
  data->GetDimensions(dims);
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  if (!scalars && data->GetPointData()->GetNumberOfArrays() > 0) scalars = data->GetPointData()->GetArray(0);
  const long long count = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  if (!scalars || count <= 0 || scalars->GetNumberOfTuples() != count)
    throw GeometryError(file, "the image has no pixel");
  for (int d = 0; d < 3; ++d) image.size[d] = dims[d];
  const int components = scalars->GetNumberOfComponents();
  image.values.resize(static_cast<std::size_t>(count));
  for (long long n = 0; n < count; ++n) {
    if (components >= 3) {  // colour: mean of R, G, B (alpha ignored)
      image.values[n] = (scalars->GetComponent(n, 0) + scalars->GetComponent(n, 1) + scalars->GetComponent(n, 2)) / 3;
    } else {  // grey (and grey + alpha)
      image.values[n] = scalars->GetComponent(n, 0);
    }
  }
  return image;
}

/// Pixels selected by the shape's threshold or label: a mask with the image's layout.
std::vector<unsigned char> select(const Image& image, const ImageShape& shape, std::size_t& selected) {
  std::vector<unsigned char> mask(image.values.size(), 0);
  selected = 0;
  for (std::size_t n = 0; n < image.values.size(); ++n) {
    const double v = image.values[n];
    const bool in = shape.label ? v == *shape.label : v >= shape.threshold.value_or(0.5);
    mask[n] = in;
    selected += in;
  }
  if (selected == 0) {
    const auto [lo, hi] = std::minmax_element(image.values.begin(), image.values.end());
    const std::string what = shape.label
                                 ? fmt::format("no pixel has the label {}", *shape.label)
                                 : fmt::format("no pixel reaches the threshold {}", shape.threshold.value_or(0.5));
    throw GeometryError(shape.file, fmt::format("{} (the values in the image range from {} to {}): the body would be "
                                                "empty",
                                                what, *lo, *hi));
  }
  return mask;
}

/// Pixel size and lower corner: the shape's, else the .vti file's.
template <int Dim>
void placement(const Image& image, const ImageShape& shape, Vec<Dim>& origin, Vec<Dim>& h) {
  for (int d = 0; d < Dim; ++d) {
    h[d] = shape.pixel_size[d] > 0 ? shape.pixel_size[d] : image.spacing[d];
    origin[d] = shape.origin ? (*shape.origin)[d] : image.origin[d];
    if (!(h[d] > 0))
      throw GeometryError(shape.file, "the pixel size is not given (pixel_size) and the file does not define one");
  }
}

template <int Dim>
Image read_for(const ImageShape& shape) {
  Image image = read_image(shape.file);
  if (image.dimension != Dim)
    throw GeometryError(shape.file, fmt::format("a {}D image cannot make a body in a {}D scene", image.dimension, Dim));
  return image;
}

/// Selected pixels: inside when the pixel containing x is selected.
template <int Dim>
class ImageRegion : public Region<Dim> {
 public:
  explicit ImageRegion(const ImageShape& shape) {
    const Image image = read_for<Dim>(shape);
    placement<Dim>(image, shape, origin_, h_);
    for (int d = 0; d < 3; ++d) size_[d] = image.size[d];
    std::size_t selected = 0;
    mask_ = select(image, shape, selected);
    volume_ = static_cast<Real>(selected) * h_.prod();
    // Bounds of the selected pixels only.
    std::array<int, 3> lo{size_[0], size_[1], size_[2]}, hi{-1, -1, -1};
    for (int k = 0; k < size_[2]; ++k)
      for (int j = 0; j < size_[1]; ++j)
        for (int i = 0; i < size_[0]; ++i)
          if (mask_[index(i, j, k)]) {
            const int ijk[3] = {i, j, k};
            for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], ijk[d]), hi[d] = std::max(hi[d], ijk[d]);
          }
    for (int d = 0; d < Dim; ++d) {
      bounds_.lo[d] = origin_[d] + h_[d] * lo[d];
      bounds_.hi[d] = origin_[d] + h_[d] * (hi[d] + 1);
    }
  }
  bool contains(const Vec<Dim>& x) const override {
    int ijk[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) {
      const Real s = std::floor((x[d] - origin_[d]) / h_[d]);
      if (s < 0 || s >= size_[d]) return false;
      ijk[d] = static_cast<int>(s);
    }
    return mask_[index(ijk[0], ijk[1], ijk[2])];
  }
  Box<Dim> bounds() const override { return bounds_; }
  std::optional<Real> exact_volume() const override { return volume_; }

 private:
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(size_[0]) * (j + static_cast<std::size_t>(size_[1]) * k);
  }
  Vec<Dim> origin_, h_;
  std::array<int, 3> size_{};
  std::vector<unsigned char> mask_;
  Box<Dim> bounds_;
  Real volume_ = 0;
};

}  // namespace

Image read_image(const std::string& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw GeometryError(file, "image file not found");
  if (std::filesystem::is_directory(file, error)) throw GeometryError(file, "is a directory, not an image file");
  const std::string ext = lower_extension(file);
  if (std::filesystem::file_size(file, error) == 0) throw GeometryError(file, "the image file is empty");
  if (ext == ".png" || ext == ".pgm") {
    vtkSmartPointer<vtkImageReader2> reader;
    if (ext == ".png")
      reader = vtkSmartPointer<vtkPNGReader>::New();
    else
      reader = vtkSmartPointer<vtkPNMReader>::New();
    if (!reader->CanReadFile(file.c_str()))
      throw GeometryError(file, fmt::format("cannot read the file as a {} image (corrupt or another format)",
                                            ext == ".png" ? "PNG" : "binary PGM (P5)"));
    reader->SetFileName(file.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0) throw GeometryError(file, "cannot read the image (corrupt file)");
    int dims[3];
    reader->GetOutput()->GetDimensions(dims);
    if (dims[2] != 1) throw GeometryError(file, "expected a single 2D picture");
    return to_image(reader->GetOutput(), file, 2);
  }
  if (ext == ".vti") {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    if (!reader->CanReadFile(file.c_str())) throw GeometryError(file, "cannot read the file as a VTK XML image (.vti)");
    reader->SetFileName(file.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0) throw GeometryError(file, "cannot read the image (corrupt .vti file)");
    vtkImageData* data = reader->GetOutput();
    Image image = to_image(data, file, 3);
    double spacing[3], origin[3];
    data->GetSpacing(spacing);
    data->GetOrigin(origin);
    int extent[6];
    data->GetExtent(extent);
    for (int d = 0; d < 3; ++d) {
      image.spacing[d] = spacing[d];
      // VTK's points are voxel centres: the lower corner is half a voxel below the first one.
      image.origin[d] = origin[d] + (extent[2 * d] - 0.5) * spacing[d];
    }
    return image;
  }
  throw GeometryError(file,
                      fmt::format("unsupported image format '{}' (supported: .png and .pgm in 2D, .vti in 3D)", ext));
}

template <int Dim>
std::unique_ptr<Region<Dim>> make_image_region(const ImageShape& shape) {
  if constexpr (Dim == 1) {
    throw GeometryError(shape.file, "images make bodies in 2D and 3D only");
  } else {
    return std::make_unique<ImageRegion<Dim>>(shape);
  }
}

template <int Dim>
ParticleSeeds<Dim> fill_image_pixels(const ImageShape& shape) {
  ParticleSeeds<Dim> seeds;
  if constexpr (Dim == 1) {
    throw GeometryError(shape.file, "images make bodies in 2D and 3D only");
  } else {
    const Image image = read_for<Dim>(shape);
    Vec<Dim> origin, h;
    placement<Dim>(image, shape, origin, h);
    std::size_t selected = 0;
    const auto mask = select(image, shape, selected);
    seeds.positions.reserve(selected);
    std::size_t n = 0;
    for (int k = 0; k < image.size[2]; ++k)
      for (int j = 0; j < image.size[1]; ++j)
        for (int i = 0; i < image.size[0]; ++i, ++n)
          if (mask[n]) {
            const int ijk[3] = {i, j, k};
            Vec<Dim> x;
            for (int d = 0; d < Dim; ++d) x[d] = origin[d] + h[d] * (ijk[d] + 0.5);
            seeds.positions.push_back(x);
          }
    seeds.volume = seeds.sub_cell_volume = h.prod();
  }
  return seeds;
}

template std::unique_ptr<Region<1>> make_image_region<1>(const ImageShape&);
template std::unique_ptr<Region<2>> make_image_region<2>(const ImageShape&);
template std::unique_ptr<Region<3>> make_image_region<3>(const ImageShape&);
template ParticleSeeds<1> fill_image_pixels<1>(const ImageShape&);
template ParticleSeeds<2> fill_image_pixels<2>(const ImageShape&);
template ParticleSeeds<3> fill_image_pixels<3>(const ImageShape&);

}  // namespace mpm::geometry
