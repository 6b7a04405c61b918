#include "mpm/io/continued_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "mpm/core/state_archive.hpp"
#include "mpm/io/atomic_file.hpp"

namespace mpm::io {
namespace fs = std::filesystem;

FileMark mark_file(const fs::path& path) {
  std::error_code error;
  const auto size = fs::file_size(path, error);
  return {fs::absolute(path).lexically_normal(), error ? 0 : size};
}

void continue_file(const FileMark& mark, const fs::path& target) {
  std::error_code error;
  if (mark.bytes == 0) {
    fs::remove(target, error);
    return;
  }
  const auto size = fs::file_size(mark.path, error);
  if (error)
    throw std::runtime_error("cannot continue '" + mark.path.string() +
                             "': it is missing, and the checkpoint expects its first " + std::to_string(mark.bytes) +
                             " bytes");
  if (size < mark.bytes)
    throw std::runtime_error("cannot continue '" + mark.path.string() + "': it has " + std::to_string(size) +
                             " bytes, fewer than the " + std::to_string(mark.bytes) +
                             " it had at the checkpoint (was it replaced?)");
  const fs::path to = fs::absolute(target).lexically_normal();
  if (fs::equivalent(mark.path, to, error) && !error) {
    if (size > mark.bytes) fs::resize_file(to, mark.bytes);  // drop the rows written after the checkpoint
    return;
  }
  std::vector<char> head(mark.bytes);
  std::ifstream in(mark.path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (!in) throw std::runtime_error("cannot read '" + mark.path.string() + "'");
  if (to.has_parent_path()) fs::create_directories(to.parent_path());
  write_atomically(to, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + to.string() + "'");
  });
}

void save_mark(StateArchive& archive, const std::string& name, const FileMark& mark) {
  archive.put_text(name + "/path", mark.path.string());
  archive.put_integer(name + "/bytes", static_cast<std::int64_t>(mark.bytes));
}

FileMark load_mark(const StateArchive& archive, const std::string& name) {
  return {archive.text(name + "/path"), static_cast<std::uintmax_t>(archive.integer(name + "/bytes"))};
}

}  // namespace mpm::io
