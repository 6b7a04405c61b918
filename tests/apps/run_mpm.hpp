#pragma once
// Running the `mpm` program from a test: its exit status and what it printed, in a scratch directory.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cli {

namespace fs = std::filesystem;

struct Result {
  int status = -1;  ///< the exit status (-1 when the program did not exit normally)
  std::string out, err;
};

/// The test data folder (bad-scene fixtures, good scenes, meshes).
inline const fs::path data = fs::path(MPM_SOURCE_DIR) / "tests" / "data";

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// An empty directory in the temporary folder, named after `name` and this process.
inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Runs `mpm ARGS` with stdin from /dev/null; stdout and stderr go through files in `dir`. `environment`
/// ("NAME=value ...") is set for the program only.
inline Result mpm(const std::string& args, const fs::path& dir, const std::string& environment = "") {
  const std::string cmd = (environment.empty() ? "" : "env " + environment + " ") + std::string(MPM_EXECUTABLE) + " " +
                          args + " > " + (dir / "stdout").string() + " 2> " + (dir / "stderr").string() +
                          " < /dev/null";
  const int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "stdout");
  r.err = slurp(dir / "stderr");
  return r;
}

/// A 2D elastic block, 0.3 m square in a unit box of 0.05 m cells, moving at `velocity` (e.g. "[20, 0]": it leaves the
/// grid through +x within 0.02 s, the stability guard's case), with the solver keys `solver`.
inline std::string block_scene(const std::string& solver, const std::string& velocity) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{name: block, material: m, shape: {type: box, min: [0.3, 0.3], max: [0.6, 0.6]}, velocity: " +
         velocity +
         "}]\n"
         "solver: {" +
         solver +
         "}\n"
         "output: {interval: 0.05, fields: [velocity, stress, displacement, von_mises_stress]}\n";
}

}  // namespace cli
