// OutputWriter::save_state / restore_state: the output series of a run in a checkpoint, so that a restart
// continues it (the .pvd frames, energy.csv through its FileMark, the output schedule) and a fork into
// another directory starts with the frames of the original run.
#include <fmt/format.h>

#include <cctype>
#include <sstream>
#include <stdexcept>

#include "mpm/output/output_writer.hpp"

namespace mpm {
namespace {

void save_frames(StateArchive& archive, const std::string& name, const io::PvdCollection& pvd) {
  std::vector<double> times;
  std::string files;
  for (const auto& [time, file] : pvd.frames()) {
    times.push_back(time);
    files += file.string() + '\n';
  }
  archive.put_values<double>(name + "/times", times);
  archive.put_text(name + "/files", files);
}

/// Adds the saved frames of `name` to `pvd` and rewrites it (nothing when the checkpoint has none).
void restore_frames(const StateArchive& archive, const std::string& name, io::PvdCollection& pvd) {
  if (!archive.contains(name + "/times")) return;
  const auto times = archive.values<double>(name + "/times");
  std::istringstream files(archive.text(name + "/files"));
  std::string file;
  for (const double t : times) {
    if (!std::getline(files, file)) throw ArchiveError(name + ": fewer files than times");
    pvd.add(t, file);
  }
  pvd.write();
}

/// N of a frame file PREFIX_NNNNNN.vtu, PREFIX_grid_NNNNNN.vti or PREFIX_domains_NNNNNN.vtu, or of a distributed
/// run's PREFIX_NNNNNN.pvtu and its folder of pieces PREFIX_NNNNNN (and the domains'); -1 otherwise.
int frame_number(const std::string& name, const std::string& prefix) {
  if (!name.starts_with(prefix + "_")) return -1;
  std::string rest = name.substr(prefix.size() + 1);
  for (const char* kind : {"grid_", "domains_"})
    if (rest.starts_with(kind) && rest.size() >= std::string(kind).size() + 6)
      rest = rest.substr(std::string(kind).size());
  if (rest.size() == 11 && rest.ends_with(".pvtu")) rest = rest.substr(0, 6) + ".vtu";
  if (rest.size() == 6) rest += ".vtu";  // a folder of pieces
  if (rest.size() != 10 || !(rest.ends_with(".vtu") || rest.ends_with(".vti"))) return -1;
  for (int k = 0; k < 6; ++k)
    if (!std::isdigit(static_cast<unsigned char>(rest[k]))) return -1;
  return std::stoi(rest.substr(0, 6));
}

}  // namespace

template <int Dim>
void OutputWriter<Dim>::save_state(StateArchive& archive) const {
  archive.put_integer("output/frame", frame_);
  archive.put_number("output/interval", interval_);
  archive.put_number("output/next_time", next_time_);
  archive.put_number("output/last_written", last_written_);
  if (!energy_) return;  // a distributed run's other ranks: rank 0 writes the checkpoint and its files' marks
  io::save_mark(archive, "output/energy", energy_->mark());
  save_frames(archive, "output/particles_pvd", particles_pvd_);
  if (grid_pvd_) save_frames(archive, "output/grid_pvd", *grid_pvd_);
  if (domains_pvd_) save_frames(archive, "output/domains_pvd", *domains_pvd_);
}

template <int Dim>
void OutputWriter<Dim>::restore_state(const StateArchive& archive) {
  frame_ = static_cast<int>(archive.integer("output/frame"));
  last_written_ = archive.number("output/last_written");
  next_time_ = archive.number("output/next_time");
  if (archive.number("output/interval") != interval_) {  // a fork with another interval: its own schedule
    next_time_ = 0;
    if (interval_ > 0)
      while (next_time_ <= last_written_ * (1 + 1e-12)) next_time_ += interval_;
  }
  if (!energy_) return;  // a distributed run's other ranks: the files are rank 0's
  restore_frames(archive, "output/particles_pvd", particles_pvd_);
  if (grid_pvd_) restore_frames(archive, "output/grid_pvd", *grid_pvd_);
  if (domains_pvd_) restore_frames(archive, "output/domains_pvd", *domains_pvd_);
  // Frames the interrupted run wrote after the checkpoint: the restarted run writes them again (or, after a
  // fork that changed the schedule, others), so none may be left over.
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(directory_))
    if (frame_number(entry.path().filename().string(), prefix_) >= frame_) stale.push_back(entry.path());
  for (const auto& file : stale) std::filesystem::remove_all(file);
}

template void OutputWriter<1>::save_state(StateArchive&) const;
template void OutputWriter<2>::save_state(StateArchive&) const;
template void OutputWriter<3>::save_state(StateArchive&) const;
template void OutputWriter<1>::restore_state(const StateArchive&);
template void OutputWriter<2>::restore_state(const StateArchive&);
template void OutputWriter<3>::restore_state(const StateArchive&);

}  // namespace mpm
