#include "mpm/io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <system_error>

namespace mpm::io {
namespace {

// Hidden name next to the target, unique per process and per call (threads may write concurrently).
std::filesystem::path temporary_for(const std::filesystem::path& target) {
  static std::atomic<unsigned long> counter{0};
  const auto n = counter.fetch_add(1, std::memory_order_relaxed);
  // Built with += : `"." + std::string` trips GCC 12's false -Wrestrict warning (GCC bug 105329).
  std::string name(1, '.');
  name += target.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(n);
  return target.parent_path() / name;
}

}  // namespace

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write) {
  if (!target.has_filename())
    throw std::invalid_argument("write_atomically: '" + target.string() + "' has no file name");
  const auto tmp = temporary_for(target);
  try {
    write(tmp);
    std::filesystem::rename(tmp, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace mpm::io
