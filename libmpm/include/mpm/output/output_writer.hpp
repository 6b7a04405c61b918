#pragma once
/// \file output_writer.hpp
/// Writes a run for ParaView: one .vtu of all particles per frame (and a .vti of the grid, and a .vtu of
/// the particle domains as cells, when asked),
/// the .pvd collection of the series, and energy.csv (the conservation audit) with one row per frame.
/// Every file is written atomically and the writers refuse non-finite values. The particle fields and how
/// their values are made come from the table of output_fields.hpp.
/// A distributed run (a Communicator of N > 1 ranks) writes each frame as one piece per rank and a .pvtu
/// (docs/distributed.md, "Output of a distributed run").

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mpm/io/csv_log.hpp"
#include "mpm/io/pvd_collection.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

template <int Dim>
class OutputWriter {
 public:
  /// Creates `directory` if needed. `interval` in s (0: first and last frames only). With `restart` (a
  /// checkpoint, entries "output/..." of save_state()), continues that run's series: the .pvd files and
  /// energy.csv hold its frames and rows up to the checkpoint and no later ones, frame files numbered from
  /// the checkpoint's next frame on are removed (the run writes them again), and the next frame is due
  /// when it would have been (throws std::runtime_error when energy.csv cannot be continued).
  ///
  /// `comm` (not owned; null, or of one rank: the files of a one-process run, byte for byte): with N > 1 ranks,
  /// every rank's particles (`sim` holds only them) go to PREFIX_NNNNNN/PREFIX_NNNNNN_RANK.vtu and rank 0
  /// writes PREFIX_NNNNNN.pvtu, the .pvd files and energy.csv (sim.energy() is already global); the same for the
  /// domains (PREFIX_domains_NNNNNN.pvtu). The constructor and write() are then collective: every rank calls
  /// them at the same point, and when a file cannot be written on any rank every rank throws
  /// std::runtime_error, so no .pvd lists a frame with a missing piece. A grid output or a restart with N > 1
  /// ranks is refused (std::invalid_argument, on every rank alike).
  OutputWriter(std::filesystem::path directory, std::string prefix, std::vector<std::string> fields, bool grid,
               Real interval, const StateArchive* restart = nullptr, Communicator* comm = nullptr);
  /// The series so far (frame count, output schedule, .pvd frames, length of energy.csv) for a checkpoint.
  /// Throws std::logic_error in a distributed run (its checkpoints are not written yet).
  void save_state(StateArchive& archive) const;
  /// Writes a frame if the simulation time has reached the next output time (always for the first call).
  bool write_if_due(const Simulation<Dim>& sim);
  /// Writes a frame now (unless this time was just written). Collective in a distributed run (see the
  /// constructor): every rank calls it, also a rank without particles (its piece is then empty).
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
  bool distributed() const { return comm_ && comm_->size() > 1; }
  io::FieldData frame_field_data(const Simulation<Dim>& sim) const;
  void write_files(const Simulation<Dim>& sim, const io::FieldData& data);   ///< one process
  void write_pieces(const Simulation<Dim>& sim, const io::FieldData& data);  ///< N ranks
  io::ImageGrid grid_image(const Simulation<Dim>& sim, const io::FieldData& data) const;
  /// N ranks: the grid image of one process, complete on rank 0 (each node's values from the rank that owns it: its
  /// sums are the one-process ones, docs/distributed.md §5.2); a collective call.
  io::ImageGrid gathered_grid_image(const Simulation<Dim>& sim, const io::FieldData& data) const;
  std::vector<double> energy_row(const Simulation<Dim>& sim) const;
  /// Appends to energy.csv (rank 0), with the outflow faces' columns (the first frame sets the header).
  void append_energy_row(const Simulation<Dim>& sim, const std::vector<double>& row);
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
  Communicator* comm_ = nullptr;  ///< the ranks of a distributed run (not owned); null: one process
};

}  // namespace mpm
