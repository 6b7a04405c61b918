#pragma once
/// \file output_writer.hpp
/// Writes a run for ParaView: one .vtu of all particles per frame (and a .vti of the grid, and a .vtu of
/// the particle domains as cells, when asked),
/// the .pvd collection of the series, and energy.csv (the conservation audit) with one row per frame.
/// Every file is written atomically and the writers refuse non-finite values. The particle fields and how
/// their values are made come from the table of output_fields.hpp.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mpm/io/csv_log.hpp"
#include "mpm/io/pvd_collection.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/output_fields.hpp"
#include "mpm/simulation.hpp"

namespace mpm {

template <int Dim>
class OutputWriter {
 public:
  /// Creates `directory` if needed. `interval` in s (0: first and last frames only). With `restart` (a
  /// checkpoint, entries "output/..." of save_state()), continues that run's series: the .pvd files and
  /// energy.csv hold its frames and rows up to the checkpoint and no later ones, frame files numbered from
  /// the checkpoint's next frame on are removed (the run writes them again), and the next frame is due
  /// when it would have been (throws std::runtime_error when energy.csv cannot be continued).
  OutputWriter(std::filesystem::path directory, std::string prefix, std::vector<std::string> fields, bool grid,
               Real interval, const StateArchive* restart = nullptr);
  /// The series so far (frame count, output schedule, .pvd frames, length of energy.csv) for a checkpoint.
  void save_state(StateArchive& archive) const;
  /// Writes a frame if the simulation time has reached the next output time (always for the first call).
  bool write_if_due(const Simulation<Dim>& sim);
  /// Writes a frame now (unless this time was just written).
  void write(const Simulation<Dim>& sim);
  /// The particles as a point cloud with the requested fields (also used by tests).
  io::PointCloud particle_cloud(const Simulation<Dim>& sim) const;
  /// What every file written from now on carries as field data besides `TIME` and `step` (the scene, the
  /// program version and commit, the thread count: see run_scene).
  void set_field_data(io::FieldData data) { field_data_ = std::move(data); }
  const std::filesystem::path& directory() const { return directory_; }
  int frames() const { return frame_; }

 private:
  void restore_state(const StateArchive& archive);
  std::filesystem::path directory_;
  std::string prefix_;
  std::vector<std::string> fields_;
  bool grid_;
  Real interval_;
  Real next_time_ = 0;
  Real last_written_ = -1;
  int frame_ = 0;
  io::PvdCollection particles_pvd_;
  std::unique_ptr<io::PvdCollection> grid_pvd_;
  std::unique_ptr<io::PvdCollection> domains_pvd_;  ///< GIMP/CPDI particle domains, when asked (`domains`)
  std::unique_ptr<io::CsvLog> energy_;
  io::FieldData field_data_;
};

}  // namespace mpm
