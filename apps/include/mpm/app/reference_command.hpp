#pragma once
/// \file reference_command.hpp
/// `mpm reference [--materials] [--keys] [--section PATH] [--output-fields] [--history-kinds] [--energy-hints]
/// [FILE]`: the reference tables generated from the registered specs (scene_reference.hpp). Without FILE it
/// prints the tables asked for (all of them when none is named); with FILE (docs/scene-reference.md) it rewrites
/// the file's generated blocks in place (`cmake --build build --target scene_reference` does that).

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace mpm::app {

/// What `mpm reference` prints.
struct ReferenceOptions {
  bool materials = false;      ///< every material model's parameter table
  bool keys = false;           ///< the keys of every section that declares them
  std::string section;         ///< the keys of one section ("output", "output.checkpoint", "contact.planes")
  bool output_fields = false;  ///< the writable particle fields
  bool history_kinds = false;  ///< the kinds of output.histories
  bool energy_hints = false;   ///< the energy sentinel's and the flight recorder's table of instabilities
  std::optional<std::filesystem::path> file;  ///< rewrite this document's generated blocks instead of printing
};

/// Registers the modules, then prints or rewrites; returns the exit status (0; 1 when FILE cannot be read or
/// written; 2 for a malformed generated block or an unknown section), as run_scene.hpp's ExitStatus.
int reference_command(const ReferenceOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
