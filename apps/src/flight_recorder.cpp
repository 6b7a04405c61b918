// The flight recorder (flight_recorder.hpp): failure/ beside the output after the guard stopped a run.
#include "mpm/app/flight_recorder.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "mpm/io/pvd_collection.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/output/output_fields.hpp"

namespace mpm::app {
namespace {

constexpr std::array<char, 3> axes{'x', 'y', 'z'};

/// The linear indices of the corners of the cell holding x (clamped to the grid).
template <int Dim>
std::vector<Index> cell_nodes(const GridGeometry<Dim>& g, const Vec<Dim>& x) {
  std::array<int, Dim> base{};
  for (int d = 0; d < Dim; ++d) {
    const Real s = std::isfinite(x[d]) ? std::floor((x[d] - g.origin[d]) * g.inv_h[d]) : 0;
    base[d] = static_cast<int>(std::clamp<Real>(s, 0, g.cells(d) - 1));
  }
  std::vector<Index> nodes;
  for (int corner = 0; corner < (1 << Dim); ++corner) {
    Index n = 0;
    for (int d = 0; d < Dim; ++d) n += static_cast<Index>(base[d] + ((corner >> d) & 1)) * g.stride[d];
    nodes.push_back(n);
  }
  return nodes;
}

/// The on-demand fields of a particle stored as doubles (the material's state: plastic strain, damage, ...).
std::vector<FieldLayout> state_fields(const std::vector<FieldLayout>& layout) {
  std::vector<FieldLayout> out;
  for (const auto& f : layout)
    if (f.scalar == ScalarType::float64 && f.name != "position" && f.name != "velocity" && f.name != "mass" &&
        f.name != "reference_volume" && f.name != "deformation_gradient" && f.name != "stress")
      out.push_back(f);
  return out;
}

/// Writes failure/'s frames and CSVs while the run is replayed. In a distributed run every rank takes part in each
/// frame (the particles are gathered on rank 0 in the one-process order, and the failing particle's nodes come from
/// the rank that held it during the step: its grid holds their full sums) and rank 0 writes; a write error is kept,
/// not thrown, so that rank 0 goes on taking part in the replay's collective steps (record_failure throws it after).
template <int Dim>
class Recorder {
 public:
  Recorder(const std::filesystem::path& dir, const StabilityReport& report, std::vector<std::string> fields,
           Communicator* comm)
      : dir_(dir), report_(report), fields_(std::move(fields)), comm_(comm), writes_(!comm || comm->rank() == 0) {
    fields_.erase(std::remove(fields_.begin(), fields_.end(), "domains"), fields_.end());  // a cell file
    fields_.push_back("id");
    if (!writes_) return;
    keep_error([&] {
      pvd_.emplace(dir / "particles.pvd");
      particle_.exceptions(std::ios::failbit | std::ios::badbit);
      nodes_.exceptions(std::ios::failbit | std::ios::badbit);
      particle_.open(dir / "particle.csv");
      nodes_.open(dir / "nodes.csv");
      particle_.precision(17);
      nodes_.precision(17);
    });
  }

  /// A collective call in a distributed run.
  void frame(const Simulation<Dim>& sim) {
    const bool first = last_step_ < 0;
    // The nodes of the cell the particle started the step in, as the step left them (none for the first frame: the
    // grid then holds another step's values), from the rank that held the particle during the step.
    std::vector<double> rows;
    if (!first && held_) rows = node_rows(sim.grid());
    std::vector<Body<Dim>> gathered;
    if (comm_) {
      gathered = sim.gather_bodies();
      std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(comm_->size()));
      if (comm_->rank() != 0) {
        out[0].resize(rows.size() * sizeof(double));
        std::memcpy(out[0].data(), rows.data(), out[0].size());
      }
      const auto in = comm_->all_to_all(std::move(out));
      for (const auto& bytes : in) {
        const std::size_t at = rows.size();
        rows.resize(at + bytes.size() / sizeof(double));
        std::memcpy(rows.data() + at, bytes.data(), bytes.size());
      }
    }
    const auto local = find_particle(sim.bodies(), report_);
    held_ = local.first != nullptr;
    if (held_) start_position_ = local.first->particles.x[local.second];
    if (writes_)
      keep_error([&] {
        const std::vector<Body<Dim>>& bodies = comm_ ? gathered : sim.bodies();
        write_frame(bodies, sim);
        const auto [body, i] = find_particle(bodies, report_);
        if (!body)
          throw std::runtime_error(fmt::format("particle {} of body '{}' not found", report_.particle, report_.body));
        write_particle(body->particles, i, sim, first);
        const std::size_t width = 1 + 3 * Dim + 1 + 2 * Dim;  // node, i.., x.., mass, momentum.., force..
        for (std::size_t r = 0; r + width <= rows.size(); r += width) {
          nodes_ << sim.step() << ',' << sim.time();
          for (std::size_t k = 0; k < width; ++k) nodes_ << ',' << rows[r + k];
          nodes_ << '\n';
        }
      });
    last_step_ = sim.step();
    last_time_ = sim.time();
    ++frames_;
  }

  void close() {
    if (writes_)
      keep_error([&] {
        particle_.close();
        nodes_.close();
      });
  }
  Index frames() const { return frames_; }
  Index last_step() const { return last_step_; }
  /// The first write error (rank 0), empty if none.
  const std::string& error() const { return error_; }

 private:
  template <class F>
  void keep_error(F&& f) {
    if (!error_.empty()) return;
    try {
      f();
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }

  /// The failing particle's body and index among `bodies` (ids survive the reordering by cell); none if absent (in a
  /// distributed run, on the ranks that do not hold it).
  static std::pair<const Body<Dim>*, Index> find_particle(const std::vector<Body<Dim>>& bodies,
                                                          const StabilityReport& report) {
    for (const auto& b : bodies) {
      if (b.name != report.body) continue;
      for (Index i = 0; i < b.particles.size(); ++i)
        if (b.particles.id[i] == report.particle) return {&b, i};
    }
    return {nullptr, 0};
  }

  /// nodes.csv's columns after step and time, for the corners of the cell holding start_position_.
  std::vector<double> node_rows(const Grid<Dim>& g) const {
    std::vector<double> rows;
    for (Index n : cell_nodes(g.geometry, start_position_)) {
      const auto ijk = g.geometry.node_indices(n);
      rows.push_back(static_cast<double>(n));
      for (int d = 0; d < Dim; ++d) rows.push_back(ijk[d]);
      const Vec<Dim> x = g.geometry.node_position(ijk);
      for (int d = 0; d < Dim; ++d) rows.push_back(x[d]);
      rows.push_back(g.node[n].mass);
      for (int d = 0; d < Dim; ++d) rows.push_back(g.node[n].momentum[d]);
      for (int d = 0; d < Dim; ++d) rows.push_back(g.node[n].force[d]);
    }
    return rows;
  }

  void write_particle(const ParticleSet<Dim>& p, Index i, const Simulation<Dim>& sim, bool first) {
    if (!header_) write_headers(p);
    const Real dt = first ? 0 : sim.time() - last_time_;
    particle_ << sim.step() << ',' << sim.time() << ',' << dt;
    for (int d = 0; d < Dim; ++d) particle_ << ',' << p.x[i][d];
    for (int d = 0; d < Dim; ++d) particle_ << ',' << p.v[i][d];
    const Mat<Dim> F = p.F[i];
    for (int r = 0; r < Dim; ++r)
      for (int c = 0; c < Dim; ++c) particle_ << ',' << F(r, c);
    particle_ << ',' << F.determinant();
    const Mat3 stress = p.stress[i].full();  // with the out-of-plane components of 1D and 2D
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) particle_ << ',' << stress(r, c);
    for (const auto& f : state_) {
      std::vector<std::byte> bytes;
      const std::array<Index, 1> which{i};
      p.pack_field(f.name, which, bytes);
      for (std::size_t k = 0; k < f.components; ++k) {
        double v = 0;
        std::memcpy(&v, bytes.data() + k * sizeof(double), sizeof(double));
        particle_ << ',' << v;
      }
    }
    particle_ << '\n';
  }

  void write_headers(const ParticleSet<Dim>& p) {
    header_ = true;
    state_ = state_fields(p.field_layout());
    particle_ << "step,time,dt";
    for (int d = 0; d < Dim; ++d) particle_ << ",x_" << axes[d];
    for (int d = 0; d < Dim; ++d) particle_ << ",v_" << axes[d];
    for (int r = 0; r < Dim; ++r)
      for (int c = 0; c < Dim; ++c) particle_ << ",F_" << axes[r] << axes[c];
    particle_ << ",det_F";
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) particle_ << ",stress_" << axes[r] << axes[c];
    for (const auto& f : state_)
      for (std::size_t k = 0; k < f.components; ++k)
        particle_ << ',' << f.name << (f.components > 1 ? fmt::format("_{}", k) : std::string());
    particle_ << '\n';
    nodes_ << "step,time,node";
    for (int d = 0; d < Dim; ++d) nodes_ << ",i_" << axes[d];
    for (int d = 0; d < Dim; ++d) nodes_ << ',' << axes[d];
    nodes_ << ",mass";
    for (int d = 0; d < Dim; ++d) nodes_ << ",momentum_" << axes[d];
    for (int d = 0; d < Dim; ++d) nodes_ << ",force_" << axes[d];
    nodes_ << '\n';
  }

  /// A particle frame: the output fields as they are (the failing frame may hold the non-finite values the
  /// guard rejected: that is what it shows).
  void write_frame(const std::vector<Body<Dim>>& bodies, const Simulation<Dim>& sim) {
    io::PointCloud cloud;
    cloud.non_finite_allowed = true;  // the failing frame shows what the guard rejected
    for (const auto& b : bodies)
      for (Index i = 0; i < b.particles.size(); ++i) append_padded<Dim>(cloud.points, b.particles.x[i]);
    for (const auto& name : fields_) {
      const OutputField* field = find_output_field(name);
      if (!field) continue;
      io::FieldArray f{name, field->components, {}};
      for (const auto& b : bodies) append_output_field<Dim>(name, b, f.values);
      cloud.fields.push_back(std::move(f));
    }
    cloud.field_data.numbers.emplace_back("TIME", sim.time());
    cloud.field_data.numbers.emplace_back("step", static_cast<double>(sim.step()));
    const auto file = dir_ / fmt::format("particles_{:06d}.vtu", frames_);
    io::write_vtu(file, cloud);
    pvd_->add(sim.time(), file);
    pvd_->write();
  }

  std::filesystem::path dir_;
  StabilityReport report_;
  std::vector<std::string> fields_;
  Communicator* comm_;
  bool writes_;
  std::string error_;
  std::optional<io::PvdCollection> pvd_;
  std::ofstream particle_, nodes_;
  bool header_ = false;
  std::vector<FieldLayout> state_;
  bool held_ = false;  ///< this rank holds the particle (after the last frame's step: during the next one)
  Vec<Dim> start_position_ = Vec<Dim>::Zero();
  Index last_step_ = -1;
  Real last_time_ = 0;
  Index frames_ = 0;
};

}  // namespace

template <int Dim>
FlightRecord record_failure(Simulation<Dim>& sim, const StabilityReport& report, const HintContext& context,
                            const std::filesystem::path& output_directory, const std::vector<std::string>& fields,
                            const std::string& command) {
  namespace fs = std::filesystem;
  Communicator* const comm = sim.communicator();
  const bool writes = !comm || comm->rank() == 0;  // a distributed run: every rank replays, rank 0 writes
  FlightRecord record;
  record.directory = output_directory / "failure";
  const fs::path partial = output_directory / ".failure.partial";
  std::string error;
  if (writes) try {
      fs::remove_all(partial);
      fs::create_directories(partial);
    } catch (const std::exception& e) {
      error = e.what();
    }
  try {
    Recorder<Dim> recorder(partial, report, fields, comm);
    if (!sim.replay_failure([&](const Simulation<Dim>& s) { recorder.frame(s); }))
      throw std::runtime_error("no failed step to replay");
    recorder.close();
    if (!error.empty()) throw std::runtime_error(error);
    if (!recorder.error().empty()) throw std::runtime_error(recorder.error());
    if (recorder.last_step() != report.step)
      throw std::runtime_error(
          fmt::format("the replay ended at step {}, not at the failing step {}", recorder.last_step(), report.step));
    record.frames = recorder.frames();
    record.first_step = sim.failure_replay_start();
    if (!writes) return record;
    const EnergyHint& hint = find_energy_hint(context, report.face.empty() ? trigger_guard : trigger_left_grid);
    std::ofstream d;
    d.exceptions(std::ios::failbit | std::ios::badbit);
    d.open(partial / "diagnosis.txt");
    fmt::print(d,
               "check that failed: {} of particle {} of body '{}' at step {} (t = {:.9g} s at its start): {}\n"
               "replayed: steps {} to {} from the guard's last snapshot, one frame each (particles.pvd; the last "
               "frame is the failing step, with the values the guard rejected); particle.csv: the particle per "
               "step; nodes.csv: the nodes of the cell it started each step in\n"
               "nearest documented cause ({}): {}\n"
               "measured: {}\n"
               "reproduce: {}\n",
               report.field, report.particle, report.body, report.step, report.time, report.detail, record.first_step,
               report.step, hint.condition, hint.hint, hint.measurement, command);
    d.close();
    fs::remove_all(record.directory);
    fs::rename(partial, record.directory);
  } catch (...) {
    std::error_code ignored;
    if (writes) fs::remove_all(partial, ignored);
    throw;
  }
  return record;
}

template FlightRecord record_failure<1>(Simulation<1>&, const StabilityReport&, const HintContext&,
                                        const std::filesystem::path&, const std::vector<std::string>&,
                                        const std::string&);
template FlightRecord record_failure<2>(Simulation<2>&, const StabilityReport&, const HintContext&,
                                        const std::filesystem::path&, const std::vector<std::string>&,
                                        const std::string&);
template FlightRecord record_failure<3>(Simulation<3>&, const StabilityReport&, const HintContext&,
                                        const std::filesystem::path&, const std::vector<std::string>&,
                                        const std::string&);

}  // namespace mpm::app
