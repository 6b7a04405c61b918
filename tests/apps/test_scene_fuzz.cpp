// The scene-parser fuzz test: mutations of the example scenes and the bad-scene fixtures (deleted,
// duplicated and swapped lines, extreme numbers, values of the wrong type, truncation, flipped bits;
// scene_fuzz.hpp), each run through `mpm check` and every fourth also through a 2-step `mpm run`, under a timeout.
// A mutated scene is valid or refused: the program must end within the timeout with exit 0 (valid) or 2 (refused,
// with a message), never with a signal, exit 1 (an internal error such as std::bad_alloc) or a hang. Exit 3 (the
// stability guard) is not accepted either: 2 steps of a scene that passed `mpm check` must not blow up unseen.
// A fixed seed and count in the suite (400 cases, 10-20 s); a long run: scripts/fuzz_scenes.sh N SEED
// (MPM_FUZZ_CASES, MPM_FUZZ_SEED, MPM_FUZZ_KEEP: a folder that receives every failing case).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "run_mpm.hpp"
#include "scene_fuzz.hpp"

namespace fs = std::filesystem;

namespace {

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

/// The address and undefined-behaviour sanitizers make the program about 10x slower (the fuzz test took 406 s
/// instead of ~40 s): the timeouts, which catch hangs, scale with it.
#ifdef MPM_SANITIZE
constexpr int timeout_scale = 10;
#else
constexpr int timeout_scale = 1;
#endif

/// Runs `mpm ARGS` under `timeout` (TERM after `seconds`, KILL 2 s later); the status as the shell saw it:
/// 124 or 137 for a hang, 128 + N for a signal.
int run_with_timeout(const std::string& args, const fs::path& dir, int seconds) {
  const std::string cmd = "timeout -k 2 " + std::to_string(seconds) + " " + std::string(MPM_EXECUTABLE) + " " + args +
                          " > " + (dir / "stdout").string() + " 2> " + (dir / "stderr").string() + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  if (WIFEXITED(raw)) return WEXITSTATUS(raw);
  return 128 + (WIFSIGNALED(raw) ? WTERMSIG(raw) : 0);
}

std::string describe(int status) {
  if (status == 124 || status == 137) return "a hang (killed by the timeout)";
  if (status > 128) return "signal " + std::to_string(status - 128);
  return "exit " + std::to_string(status);
}

TEST(SceneFuzz, EveryMutatedSceneIsValidOrRefused) {
  const std::uint64_t seed = env_number("MPM_FUZZ_SEED", 1);
  const std::uint64_t cases = env_number("MPM_FUZZ_CASES", 400);
  const char* keep = std::getenv("MPM_FUZZ_KEEP");
  const fs::path dir = cli::scratch("fuzz");
  // The scenes with the files they read (meshes, images, polygons, particle files), copied: a mutated scene is
  // written beside its original's copy, so that its relative paths still resolve.
  const fs::path source(MPM_SOURCE_DIR);
  fs::copy(source / "examples", dir / "examples", fs::copy_options::recursive);
  fs::copy(source / "tests" / "data", dir / "data", fs::copy_options::recursive);
  // Half the cases mutate a valid scene (examples/, data/good_scene_*), half a bad-scene fixture: most mutations of
  // a fixture are refused for its own error, so the valid scenes are where the mutations reach the builder and the run.
  std::vector<fs::path> valid, bad;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string name = fs::relative(entry.path(), dir).string();
    (name.rfind("examples/", 0) == 0 || name.find("good_scene") != std::string::npos ? valid : bad)
        .push_back(entry.path());
  }
  std::sort(valid.begin(), valid.end());
  std::sort(bad.begin(), bad.end());
  ASSERT_GE(valid.size(), 20u);
  ASSERT_GE(bad.size(), 200u);

  std::map<std::string, int> outcomes;  // "check exit 0", "run exit 2", ...
  std::vector<std::string> failures;
  for (std::uint64_t c = 0; c < cases; ++c) {
    fuzz::Draw draw(seed * 1000003 + c);  // one case reproducible alone
    const fs::path& original = draw.pick(c % 2 == 0 ? valid : bad);
    std::string text = cli::slurp(original), what;
    const std::size_t count = 1 + draw.below(3);
    for (std::size_t m = 0; m < count; ++m) {
      if (m > 0) what += ", ";
      text = fuzz::mutate(text, draw, what);
    }
    const fs::path scene = original.parent_path() / "fuzz_case.yaml";
    std::ofstream(scene, std::ios::binary) << text;
    const fs::path out = dir / "out";
    std::vector<std::pair<std::string, std::string>> commands{{"check", "check " + scene.string()}};
    if (c % 4 == 0) commands.emplace_back("run", "run " + scene.string() + " --steps 2 --threads 1 -o " + out.string());
    for (const auto& [name, args] : commands) {
      const int status = run_with_timeout(args, dir, timeout_scale * (name == "check" ? 10 : 20));
      ++outcomes[name + " " + describe(status)];
      if (status == 0 || status == 2) continue;
      const std::string id = "case " + std::to_string(c) + " (seed " + std::to_string(seed) + ")";
      failures.push_back(id + ": mpm " + name + " gave " + describe(status) + " on a mutation of " +
                         fs::relative(original, dir).string() + " (" + what + ")\n" + cli::slurp(dir / "stderr"));
      if (keep) {
        fs::create_directories(keep);
        std::ofstream(fs::path(keep) / ("case_" + std::to_string(c) + "_" + original.stem().string() + ".yaml"),
                      std::ios::binary)
            << "# " << failures.back().substr(0, failures.back().find('\n')) << "\n"
            << text;
      }
    }
    fs::remove(scene);
    fs::remove_all(out);
  }
  std::string summary = "fuzz: seed " + std::to_string(seed) + ", " + std::to_string(cases) + " cases:";
  for (const auto& [outcome, n] : outcomes) summary += " " + outcome + ": " + std::to_string(n) + ";";
  std::cout << summary << " failures: " << failures.size() << '\n';
  for (const auto& f : failures) ADD_FAILURE() << f;
  fs::remove_all(dir);
}

}  // namespace
