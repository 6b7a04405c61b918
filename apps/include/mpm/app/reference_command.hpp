#pragma once
/// \file reference_command.hpp
/// `mpm reference --materials [FILE]`: the material parameter tables generated from the registered specs
/// (material_reference.hpp). Without FILE it prints every model's table; with FILE (docs/scene-reference.md) it
/// rewrites the generated blocks in place (`cmake --build build --target scene_reference` does that).

#include <filesystem>
#include <iosfwd>
#include <optional>

namespace mpm::app {

/// Registers the modules, then prints or rewrites; returns the exit status (0; 1 when FILE cannot be read or
/// written; 2 for a malformed generated block), as run_scene.hpp's ExitStatus.
int reference_command(const std::optional<std::filesystem::path>& file, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
