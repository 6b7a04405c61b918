#pragma once
/// \file atomic_file.hpp
/// Replace a file all at once: readers (ParaView, a plotting script, a killed run) see either the old
/// content or the new one, never a half-written file.

#include <filesystem>
#include <functional>

namespace mpm::io {

/// Calls `write(tmp)` with a temporary path in the same directory as `target`, then renames the
/// temporary onto `target` (atomic on POSIX, same file system). On any exception, from `write` or
/// from the rename, the temporary is removed and the exception rethrown: `target` is untouched.
/// Throws std::invalid_argument if `target` has no file name.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write);

}  // namespace mpm::io
