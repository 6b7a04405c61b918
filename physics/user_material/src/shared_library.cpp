#include "mpm/user_material/shared_library.hpp"

#include <dlfcn.h>

#include <mutex>

namespace mpm::user_material {
namespace {
/// dlerror() is per thread but not reentrant with itself on every libc: one caller at a time.
std::mutex& dl_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

std::shared_ptr<SharedLibrary> SharedLibrary::open(const std::string& path) {
  std::lock_guard lock(dl_mutex());
  dlerror();
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw LibraryError("cannot load the library '" + path + "': " + (why ? why : "unknown reason"));
  }
  return std::shared_ptr<SharedLibrary>(new SharedLibrary(handle, path));
}

SharedLibrary::~SharedLibrary() {
  std::lock_guard lock(dl_mutex());
  dlclose(handle_);
}

void* SharedLibrary::find(const std::string& name) const {
  std::lock_guard lock(dl_mutex());
  dlerror();
  return dlsym(handle_, name.c_str());
}

void* SharedLibrary::symbol(const std::string& name) const {
  if (void* address = find(name)) return address;
  throw LibraryError("the library '" + path_ + "' has no symbol '" + name + "'");
}

}  // namespace mpm::user_material
