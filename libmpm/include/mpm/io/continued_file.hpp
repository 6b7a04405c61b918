#pragma once
/// \file continued_file.hpp
/// Files a run appends to as it goes (energy.csv, the contact forces, probe histories), continued by a
/// restart without duplicated or missing rows. A checkpoint records each such file's length (its FileMark,
/// saved with the writer's state); the restart cuts the file back to that length, which drops exactly the
/// rows written after the checkpoint, and the writer appends from there. Every CSV writer does this through
/// continue_file(), also when the stability guard rolls a run back to its last snapshot.

#include <cstdint>
#include <filesystem>
#include <string>

namespace mpm {
class StateArchive;
}

namespace mpm::io {

/// A file's length at a checkpoint.
struct FileMark {
  std::filesystem::path path;  ///< absolute, where the checkpointed run wrote it
  std::uintmax_t bytes = 0;    ///< its length then; 0 when nothing was written yet
};

/// The mark of `path` now: its length (0 when it does not exist). Flush the writer first.
FileMark mark_file(const std::filesystem::path& path);

/// Makes `target` hold exactly the first mark.bytes bytes of mark.path: cuts the file back when `target` is
/// mark.path (a restart, a roll-back), copies those bytes from mark.path when the run continues elsewhere (a
/// fork with `--output`; written atomically). With mark.bytes == 0, `target` is removed. Throws
/// std::runtime_error naming the file when mark.path is missing or shorter than the mark (it was cut or
/// replaced since the checkpoint): the rows before the checkpoint are gone.
void continue_file(const FileMark& mark, const std::filesystem::path& target);

/// A mark as two archive entries, NAME/path and NAME/bytes.
void save_mark(StateArchive& archive, const std::string& name, const FileMark& mark);
FileMark load_mark(const StateArchive& archive, const std::string& name);

}  // namespace mpm::io
