#pragma once
/// \file checkpoint_command.hpp
/// `mpm checkpoint FILE`: what a checkpoint holds (program version, scene and its hash, time, step, bodies with
/// their particle counts and fields, modules) after checking every dataset against its checksum.

#include <filesystem>
#include <iosfwd>

namespace mpm::app {

/// Prints the summary to `out`; an unreadable or corrupt file is reported to `err`. Returns the exit status:
/// 0, or 2 for a file that is no valid checkpoint (run_scene.hpp's ExitStatus).
int checkpoint_command(const std::filesystem::path& file, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
