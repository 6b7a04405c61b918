#include "mpm/app/checkpoint_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <ostream>

#include "mpm/app/run_scene.hpp"
#include "mpm/checkpoint/checkpoint_file.hpp"
#include "mpm/checkpoint/checksum.hpp"

namespace mpm::app {

int checkpoint_command(const std::filesystem::path& file, std::ostream& out, std::ostream& err) {
  StateArchive a;
  try {
    a = checkpoint::read_checkpoint(file);
  } catch (const checkpoint::CheckpointError& e) {
    fmt::print(err, "error: {}\n", e.what());
    return exit_bad_input;
  }
  try {
    const std::string scene_text = a.text("run/scene_text");
    const bool hash_ok = checkpoint::checksum_hex(scene_text) == a.text("run/scene_hash");
    fmt::print(out, "{}: checkpoint of mpm {} (format {}), {} datasets, {} bytes of state; every checksum matches\n",
               file.string(), a.text("run/program_version"), a.integer("run/format"), a.entries().size(), a.bytes());
    fmt::print(out, "scene: {} (hash {}{})\n", a.text("run/scene_file"), a.text("run/scene_hash"),
               hash_ok ? "" : ", which does NOT match the stored scene text");
    fmt::print(out, "time: {:.17g} s, step {}, {}D, next time step bounded by wave speed ({})\n",
               a.number("simulation/time"), a.integer("simulation/step"), a.integer("simulation/dimension"),
               fmt::join(a.values<double>("simulation/wave_speed"), ", "));
    for (const auto& body : a.children("bodies/")) {
      const std::string prefix = "bodies/" + body + "/";
      const auto n = a.at(prefix + "storage_order").count();
      std::vector<std::string> fields;
      for (const auto& f : a.children(prefix))
        if (f != "storage_order") {
          const auto& array = a.at(prefix + f);
          fields.push_back(fmt::format("{} ({}{})", f, scalar_type_name(array.type),
                                       array.shape.size() > 1 ? fmt::format(" x {}", array.shape[1]) : ""));
        }
      fmt::print(out, "body {}: {} particles; fields: {}\n", body, n, fmt::join(fields, ", "));
    }
    for (const auto& module : a.children("modules/")) fmt::print(out, "module {}\n", module);
    fmt::print(out, "output: {} frames written, next at t = {:.9g} s\n", a.integer("output/frame"),
               a.number("output/next_time"));
    if (!hash_ok) return exit_bad_input;
  } catch (const ArchiveError& e) {
    fmt::print(err, "error: {}: not a checkpoint of mpm: {}\n", file.string(), e.what());
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace mpm::app
