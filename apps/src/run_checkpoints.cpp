#include "mpm/app/run_checkpoints.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <csignal>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "mpm/checkpoint/checkpoint_file.hpp"
#include "mpm/checkpoint/checksum.hpp"
#include "mpm/core/due_time.hpp"
#include "mpm/io/atomic_file.hpp"
#include "mpm/scene/scene_error.hpp"

namespace mpm::app {
namespace fs = std::filesystem;
namespace {

/// Version of the layout of a checkpoint's entries; a checkpoint of another one is refused.
constexpr int checkpoint_format = 1;

long long step_of(const fs::path& file) { return std::stoll(file.filename().string().substr(11, 9)); }

/// The first line of a message (for a checkpoint that is skipped).
std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

void check_writable(const fs::path& directory, const CheckpointDescription& settings) {
  std::error_code error;
  fs::create_directories(directory, error);
  const fs::path probe = directory / ".mpm_write_test";
  std::ofstream out(probe);
  out << "test\n";
  out.close();
  const bool ok = !error && out;
  fs::remove(probe, error);
  if (!ok)
    throw SceneError(settings.where, "output.checkpoint",
                     "cannot write checkpoints to the directory '" + directory.string() +
                         "' (it cannot be created or is not writable)");
}

}  // namespace

std::string read_scene_text(const SceneDescription& scene) {
  std::ifstream in(scene.file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path checkpoint_directory(const SceneDescription& scene, const fs::path& output_directory) {
  const std::string& directory = scene.output.checkpoint.directory;
  return directory.empty() ? output_directory / "checkpoints" : fs::path(directory);
}

RunCheckpoints::RunCheckpoints(const SceneDescription& scene, std::string scene_text, fs::path directory,
                               bool writes_files)
    : settings_(scene.output.checkpoint),
      scene_file_(scene.file),
      scene_text_(std::move(scene_text)),
      gravity_(scene.solver.gravity.begin(), scene.solver.gravity.begin() + scene.dimension),
      directory_(std::move(directory)),
      last_wall_(Clock::now()),
      writes_files_(writes_files) {
  if (settings_.enabled && writes_files_) check_writable(directory_, settings_);
  if (settings_.interval) next_time_ = *settings_.interval;
}

bool RunCheckpoints::due(double time) const {
  if (settings_.interval && time >= next_time_ * (1 - 1e-12)) return true;
  return settings_.wall_interval &&
         std::chrono::duration<double>(Clock::now() - last_wall_).count() >= *settings_.wall_interval;
}

fs::path RunCheckpoints::write(StateArchive& archive, Index step, double time) {
  if (settings_.interval) next_time_ = next_due_time(next_time_, *settings_.interval, time * (1 + 1e-12));
  last_wall_ = Clock::now();
  archive.put_integer("run/format", checkpoint_format);
  archive.put_text("run/program_version", MPM_VERSION);
  archive.put_text("run/scene_file", scene_file_);
  archive.put_values<double>("run/gravity", gravity_);
  archive.put_text("run/scene_text", scene_text_);
  archive.put_text("run/scene_hash", checkpoint::checksum_hex(scene_text_));
  archive.put_number("run/checkpoint_next_time", next_time_);
  if (!writes_files_) return {};
  fs::create_directories(directory_);
  const fs::path file = directory_ / checkpoint::checkpoint_name(step);
  const bool kill = ++written_ == kill_in_checkpoint_;
  checkpoint::write_checkpoint(file, archive, kill ? [] { std::raise(SIGKILL); } : std::function<void()>());
  // Keep the newest `keep` of those up to this one (later ones were removed by restore()).
  int kept = 0;
  for (const auto& older : checkpoint::checkpoint_files(directory_))
    if (step_of(older) <= step && ++kept > settings_.keep) fs::remove(older);
  return file;
}

int RunCheckpoints::restore(const StateArchive& archive) {
  if (settings_.interval && archive.contains("run/checkpoint_next_time")) {
    next_time_ = archive.number("run/checkpoint_next_time");
    const double time = archive.number("simulation/time");
    if (next_time_ <= time) next_time_ = time + *settings_.interval;  // a fork that set an interval
  } else if (settings_.interval) {
    next_time_ = archive.number("simulation/time") + *settings_.interval;
  }
  if (!writes_files_) return 0;
  const long long step = archive.integer("simulation/step");
  int removed = 0;
  for (const auto& later : checkpoint::checkpoint_files(directory_))
    if (step_of(later) > step) {
      fs::remove(later);
      ++removed;
    }
  // Checkpoints that a killed run left half-written under their temporary names.
  std::vector<fs::path> temporaries;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(".checkpoint_") && name.find(".h5.tmp-") != std::string::npos)
      temporaries.push_back(entry.path());
  }
  for (const auto& file : temporaries) fs::remove(file, error);
  return removed;
}

RestartPoint find_restart_point(const fs::path& file_or_directory, const SceneDescription& scene,
                                const std::string& scene_text, std::ostream& log) {
  RestartPoint point;
  std::error_code error;
  if (fs::is_directory(file_or_directory, error)) {
    auto files = checkpoint::checkpoint_files(file_or_directory);
    if (files.empty()) files = checkpoint::checkpoint_files(file_or_directory / "checkpoints");  // an output dir
    std::string skipped;
    for (const auto& file : files) {
      try {
        point.archive = checkpoint::read_checkpoint(file);
        point.file = file;
        break;
      } catch (const checkpoint::CheckpointError& e) {
        fmt::print(log, "warning: skipping {}\n", first_line(e.what()));
        skipped += fmt::format("\n  {}", first_line(e.what()));
      }
    }
    if (point.file.empty())
      throw RestartError(fmt::format("{}: no valid checkpoint in this directory (checkpoint_*.h5){}",
                                     file_or_directory.string(), skipped));
  } else {
    point.archive = checkpoint::read_checkpoint(file_or_directory);
    point.file = file_or_directory;
  }
  const std::string where = point.file.string();
  if (!point.archive.contains("run/program_version") || !point.archive.contains("run/format"))
    throw RestartError(where + ": not a checkpoint of mpm (it has no run/program_version)");
  const std::string version = point.archive.text("run/program_version");
  if (version != MPM_VERSION || point.archive.integer("run/format") != checkpoint_format)
    throw RestartError(fmt::format(
        "{}: written by mpm {} (checkpoint format {}); this is mpm {} (format {}): a checkpoint is continued by the "
        "version that wrote it",
        where, version, point.archive.integer("run/format"), MPM_VERSION, checkpoint_format));
  const std::string saved_scene = point.archive.text("run/scene_text");
  std::string refused;
  for (auto& d : scene_differences(saved_scene, scene_text, scene.file)) {
    if (d.run_control) {
      point.changes.push_back(std::move(d));
      continue;
    }
    refused += fmt::format("\n  {}:{}: {}: {} in the checkpoint, {} now: {}", d.where.file, d.where.line, d.key, d.was,
                           d.now, d.refusal);
  }
  if (!refused.empty())
    throw RestartError(fmt::format(
        "{}: the scene differs from the checkpoint's (scene {}) in keys a fork may not change (a fork may change "
        "what keeps the state's meaning: output, end time and time step, boundary conditions, material parameters, "
        "loads, gravity; docs/scene-reference.md, \"Restart and fork\"):{}",
        where, point.archive.text("run/scene_file"), refused));
  return point;
}

void write_fork_changes(const fs::path& directory, const RestartPoint& point) {
  if (point.changes.empty()) return;
  std::string text = fmt::format("# a fork of {} (step {}, t = {:.9g} s, scene {}): the keys it changed\n",
                                 point.file.string(), point.archive.integer("simulation/step"),
                                 point.archive.number("simulation/time"), point.archive.text("run/scene_file"));
  for (const auto& d : point.changes)
    text += fmt::format("{}: {} in the checkpoint, {} now  # {}:{}\n", d.key, d.was, d.now, d.where.file, d.where.line);
  io::write_atomically(directory / fork_changes_file, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + (directory / fork_changes_file).string());
  });
}

double rebase_gravity_potential(RestartPoint& point, const SceneDescription& scene) {
  StateArchive& archive = point.archive;
  if (!archive.contains("run/gravity")) return 0;
  const auto before = archive.values<double>("run/gravity");
  std::vector<double> change(before.size());
  bool changed = false;
  for (std::size_t d = 0; d < before.size(); ++d) {
    change[d] = scene.solver.gravity[d] - before[d];
    changed = changed || change[d] != 0;
  }
  if (!changed) return 0;
  double shift = 0;  // -(g_new - g_old) . sum m x over the saved particles
  for (const auto& body : archive.children("bodies/")) {
    const std::string prefix = "bodies/" + body + "/";
    if (!archive.contains(prefix + "mass") || !archive.contains(prefix + "position")) continue;
    const auto mass = archive.values<double>(prefix + "mass");
    const auto position = archive.values<double>(prefix + "position");
    for (std::size_t p = 0; p < mass.size(); ++p)
      for (std::size_t d = 0; d < change.size(); ++d) shift -= mass[p] * change[d] * position[p * change.size() + d];
  }
  std::vector<std::string> shifted;
  for (const auto& [name, array] : archive.entries())
    if (name == "run/initial_energy" || name.ends_with("/initial_gravity")) shifted.push_back(name);
  for (const auto& name : shifted) archive.put_number(name, archive.number(name) + shift);
  return shift;
}

}  // namespace mpm::app
