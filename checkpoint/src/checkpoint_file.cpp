// A StateArchive as an HDF5 file (HDF5 1.10 C API): one dataset per entry, contiguous, uncompressed (the
// state is mostly doubles, which do not compress; a checkpoint is written at disk speed), each with its
// checksum as an attribute.
#include "mpm/checkpoint/checkpoint_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <utility>

#include "mpm/checkpoint/checksum.hpp"
#include "mpm/io/atomic_file.hpp"

namespace mpm::checkpoint {
namespace fs = std::filesystem;
namespace {

/// An HDF5 identifier closed by `close` when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// HDF5 prints its error stack to stderr by default; the messages here say what went wrong instead.
void silence_hdf5() {
  static const bool once = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)once;
}

hid_t native_type(ScalarType type) {
  switch (type) {
    case ScalarType::float64:
      return H5T_NATIVE_DOUBLE;
    case ScalarType::float32:
      return H5T_NATIVE_FLOAT;
    case ScalarType::int64:
      return H5T_NATIVE_INT64;
    case ScalarType::uint64:
      return H5T_NATIVE_UINT64;
    case ScalarType::int32:
      return H5T_NATIVE_INT32;
    case ScalarType::uint32:
      return H5T_NATIVE_UINT32;
    case ScalarType::int8:
      return H5T_NATIVE_INT8;
    case ScalarType::uint8:
    case ScalarType::opaque:
      break;
  }
  return H5T_NATIVE_UINT8;
}

/// The scalar type of a dataset's file type (uint8 for strings), or nothing for a type no archive writes.
std::optional<ScalarType> scalar_type(hid_t type) {
  const H5T_class_t c = H5Tget_class(type);
  const std::size_t size = H5Tget_size(type);
  if (c == H5T_STRING) return ScalarType::uint8;
  if (c == H5T_FLOAT) return size == 8 ? ScalarType::float64 : ScalarType::float32;
  if (c != H5T_INTEGER) return std::nullopt;
  const bool is_signed = H5Tget_sign(type) == H5T_SGN_2;
  switch (size) {
    case 8:
      return is_signed ? ScalarType::int64 : ScalarType::uint64;
    case 4:
      return is_signed ? ScalarType::int32 : ScalarType::uint32;
    case 1:
      return is_signed ? ScalarType::int8 : ScalarType::uint8;
    default:
      return std::nullopt;
  }
}

void write_entry(hid_t file, const std::string& name, const ArchivedArray& a, hid_t link_properties) {
  const std::string where = "'" + name + "'";
  std::optional<Handle> type;
  std::optional<Handle> space;
  if (a.text) {  // a fixed-length string (a null dataspace for the empty text)
    type.emplace(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type->get(), std::max<std::size_t>(a.bytes.size(), 1));
    H5Tset_strpad(type->get(), H5T_STR_NULLPAD);
    space.emplace(H5Screate(a.bytes.empty() ? H5S_NULL : H5S_SCALAR), H5Sclose);
  } else {
    std::vector<hsize_t> dims(a.shape.begin(), a.shape.end());
    space.emplace(
        dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
        H5Sclose);
  }
  const hid_t memory_type = a.text ? type->get() : native_type(a.type);
  const Handle set(H5Dcreate2(file, name.c_str(), memory_type, space->get(), link_properties, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  if (!set.valid()) throw std::runtime_error("cannot create the dataset " + where);
  if (!a.bytes.empty() && H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) < 0)
    throw std::runtime_error("cannot write the dataset " + where);
  const std::uint64_t sum = checksum(a.bytes);
  const Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle attribute(H5Acreate2(set.get(), "checksum", H5T_NATIVE_UINT64, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_UINT64, &sum) < 0)
    throw std::runtime_error("cannot write the checksum of " + where);
}

void write_file(const fs::path& path, const StateArchive& archive, const std::function<void()>& halfway) {
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw std::runtime_error("cannot create the file");
  const Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links.get(), 1);
  std::size_t written = 0;
  for (const auto& [name, array] : archive.entries()) {
    write_entry(file.get(), name, array, links.get());
    if (halfway && ++written == archive.entries().size() / 2) {  // a test kills the process here
      H5Fflush(file.get(), H5F_SCOPE_GLOBAL);
      halfway();
    }
  }
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error("cannot flush the file");
}

/// fsync of a file or a directory (what a rename needs to survive a crash of the machine).
void sync_to_disk(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

struct Visit {
  StateArchive* archive;
  std::string error;
};

/// Reads one dataset into the archive (H5Lvisit callback); stops the visit with an error message.
herr_t read_entry(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto& visit = *static_cast<Visit*>(data);
  const Handle object(H5Oopen(group, name, H5P_DEFAULT), H5Oclose);
  if (!object.valid()) {
    visit.error = fmt::format("cannot open '{}'", name);
    return -1;
  }
  if (H5Iget_type(object.get()) != H5I_DATASET) return 0;  // a group
  const Handle type(H5Dget_type(object.get()), H5Tclose);
  const Handle space(H5Dget_space(object.get()), H5Sclose);
  const auto scalar = scalar_type(type.get());
  if (!scalar) {
    visit.error = fmt::format("dataset '{}' has a type no checkpoint holds", name);
    return -1;
  }
  ArchivedArray a;
  a.type = *scalar;
  a.text = H5Tget_class(type.get()) == H5T_STRING;
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (a.text) {
    if (H5Sget_simple_extent_type(space.get()) != H5S_NULL) a.bytes.resize(H5Tget_size(type.get()));
    a.shape = {a.bytes.size()};
  } else {
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    a.shape.assign(dims.begin(), dims.end());
    a.bytes.resize(a.count() * scalar_size(a.type));
  }
  const hid_t memory_type = a.text ? type.get() : native_type(a.type);
  if (!a.bytes.empty() && H5Dread(object.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) < 0) {
    visit.error = fmt::format("cannot read dataset '{}'", name);
    return -1;
  }
  std::uint64_t expected = 0;
  const Handle attribute(H5Aopen(object.get(), "checksum", H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Aread(attribute.get(), H5T_NATIVE_UINT64, &expected) < 0) {
    visit.error = fmt::format("dataset '{}' has no checksum", name);
    return -1;
  }
  if (checksum(a.bytes) != expected) {
    visit.error = fmt::format("dataset '{}' is corrupt: its checksum does not match its bytes", name);
    return -1;
  }
  if (a.text) {  // a string was padded with nulls to its fixed length: a text never holds one
    const auto end = std::find(a.bytes.begin(), a.bytes.end(), std::byte{0});
    a.bytes.erase(end, a.bytes.end());
    a.shape = {a.bytes.size()};
  }
  visit.archive->put(name, std::move(a));
  return 0;
}

}  // namespace

std::string checkpoint_name(long long step) { return fmt::format("checkpoint_{:09d}.h5", step); }

void write_checkpoint(const fs::path& path, const StateArchive& archive, const std::function<void()>& halfway) {
  silence_hdf5();
  try {
    io::write_atomically(path, [&](const fs::path& tmp) {
      write_file(tmp, archive, halfway);
      sync_to_disk(tmp);
    });
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("cannot write the checkpoint {}: {}", path.string(), e.what()));
  }
  sync_to_disk(path.has_parent_path() ? path.parent_path() : fs::path("."));
}

StateArchive read_checkpoint(const fs::path& path) {
  silence_hdf5();
  const std::string file = path.string();
  std::error_code error;
  if (!fs::exists(path, error)) throw CheckpointError(file + ": no such checkpoint file");
  if (fs::is_directory(path, error)) throw CheckpointError(file + ": is a directory, not a checkpoint file");
  if (fs::file_size(path, error) == 0) throw CheckpointError(file + ": the file is empty, not a checkpoint");
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw CheckpointError(file + ": not an HDF5 file (or its header is damaged), not a checkpoint");
  const Handle h5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid())
    throw CheckpointError(file + ": cannot open it as HDF5 (truncated or damaged: was its writing interrupted?)");
  StateArchive archive;
  Visit visit{&archive, {}};
  if (H5Lvisit(h5.get(), H5_INDEX_NAME, H5_ITER_INC, read_entry, &visit) < 0)
    throw CheckpointError(file + ": " +
                          (visit.error.empty() ? "cannot read its contents (truncated or damaged)" : visit.error));
  return archive;
}

std::vector<fs::path> checkpoint_files(const fs::path& directory) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == checkpoint_name(0).size() && name.starts_with("checkpoint_") && name.ends_with(".h5") &&
        std::all_of(name.begin() + 11, name.end() - 3, [](char c) { return c >= '0' && c <= '9'; }))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename() > b.filename(); });
  return files;
}

}  // namespace mpm::checkpoint
