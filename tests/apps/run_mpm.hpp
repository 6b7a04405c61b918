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

}  // namespace cli
