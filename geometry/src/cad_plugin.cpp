// The CAD reader as a plugin (cad_backend.hpp): libmpm_cad_occt.so is opened on the first scene with a `cad:` body,
// so that the program, the tests and the Python package do not load OpenCASCADE's libraries for every other scene.
// Looked for beside the program (`<dir of the program or library>/../lib/mpm/`, an installed tree moved elsewhere
// or the build tree), then where the build put it, then where `cmake --install` puts it; the environment variable
// MPM_CAD_PLUGIN, when set, is the only place (a packager's layout, and the tests of the loader's refusals).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cad_backend.hpp"
#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::detail {

namespace {

struct Loaded {
  const CadBackend* backend = nullptr;
  std::string why_not;  ///< "" when loaded
};

#ifdef MPM_WITH_OCCT
/// The places to look, in order (duplicates are harmless: the first that loads wins).
std::vector<std::string> candidates() {
  if (const char* chosen = std::getenv("MPM_CAD_PLUGIN"); chosen != nullptr && *chosen != 0) return {chosen};
  std::vector<std::string> paths;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&candidates), &info) != 0 && info.dli_fname != nullptr) {
    std::error_code error;
    const auto self = std::filesystem::canonical(info.dli_fname, error);
    if (!error) paths.push_back((self.parent_path() / ".." / "lib" / "mpm" / MPM_CAD_PLUGIN_NAME).lexically_normal());
  }
  paths.emplace_back(MPM_CAD_PLUGIN_BUILT);
  paths.emplace_back(MPM_CAD_PLUGIN_INSTALLED);
  return paths;
}

Loaded load() {
  std::string tried;
  for (const std::string& path : candidates()) {
    if (!std::filesystem::exists(path)) {
      tried += "\n  " + path + ": not there";
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the process
    if (handle == nullptr) {
      const char* why = dlerror();
      tried += "\n  " + path + ": " + (why != nullptr ? why : "cannot be loaded");
      continue;
    }
    using Entry = const CadBackend* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, MPM_CAD_BACKEND_SYMBOL));
    const CadBackend* backend = entry != nullptr ? entry() : nullptr;
    if (backend == nullptr || backend->version != cad_backend_version) {
      tried += "\n  " + path + ": not the CAD reader of this version of mpm";
      continue;
    }
    return {backend, ""};
  }
  return {nullptr, "the CAD reader plugin (" MPM_CAD_PLUGIN_NAME ", OpenCASCADE) could not be loaded:" + tried};
}
#else
Loaded load() {
  return {nullptr,
          "STEP, IGES and BREP bodies need a build with OpenCASCADE: configure with -DMPM_WITH_OCCT=ON "
          "(Debian: libocct-data-exchange-dev, libocct-modeling-algorithms-dev, libocct-ocaf-dev)"};
}
#endif

const Loaded& loaded() {
  static const Loaded plugin = load();  // thread-safe: C++11 static initialisation
  return plugin;
}

const CadBackend& backend(const std::string& file) {
  const Loaded& plugin = loaded();
  if (plugin.backend == nullptr) throw GeometryError(file, plugin.why_not);
  return *plugin.backend;
}

}  // namespace

const std::string& cad_unavailable() { return loaded().why_not; }

std::vector<CadSolidInfo> cad_solids(const std::string& file) {
  CadFailure failure;
  auto solids = backend(file).solids(file, failure);
  if (!failure.problem.empty()) throw GeometryError(failure.file, failure.problem);
  return solids;
}

CadTessellation tessellate_cad_solid(const CadShape& shape, std::size_t index) {
  CadFailure failure;
  auto tessellation = backend(shape.file).tessellate(shape, index, failure);
  if (!failure.problem.empty()) throw GeometryError(failure.file, failure.problem);
  return tessellation;
}

}  // namespace mpm::geometry::detail
