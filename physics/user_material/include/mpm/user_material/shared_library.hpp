#pragma once
/// \file shared_library.hpp
/// A shared library opened with dlopen(RTLD_NOW | RTLD_LOCAL) and closed when the last owner lets it go.

#include <memory>
#include <stdexcept>
#include <string>

namespace mpm::user_material {

/// A library that cannot be opened or lacks a symbol; what() says which and dlerror()'s reason.
class LibraryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SharedLibrary {
 public:
  /// Opens `path` (throws LibraryError with dlerror()'s text).
  static std::shared_ptr<SharedLibrary> open(const std::string& path);
  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  /// The address of `name`, or nullptr when the library does not define it.
  void* find(const std::string& name) const;
  /// The address of `name`; throws LibraryError naming the symbol and the library when it is missing.
  void* symbol(const std::string& name) const;
  const std::string& path() const { return path_; }

 private:
  SharedLibrary(void* handle, std::string path) : handle_(handle), path_(std::move(path)) {}
  void* handle_;
  std::string path_;
};

}  // namespace mpm::user_material
