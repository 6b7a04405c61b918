#include "mpm/output/output_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "mpm/core/due_time.hpp"
#include "mpm/failure/failure_module.hpp"
#include "mpm/grid/node_volume.hpp"
#include "mpm/io/collective_write.hpp"
#include "mpm/io/pvtu_writer.hpp"
#include "mpm/output/particle_domain_mesh.hpp"

namespace mpm {
namespace {

/// energy.csv's columns without outflow faces.
const std::vector<std::string> base_energy_columns{
    "time",         "step",          "kinetic_energy", "strain_energy", "gravity_potential_energy",
    "total_energy", "momentum_x",    "momentum_y",     "momentum_z",    "mass",
    "plastic_work", "thermal_energy"};
/// Per outflow face F, what left through it since t = 0 (GridBoundary::outflow): outflow_F_ and the names of the
/// columns from kinetic_energy to thermal_energy, then the number of particles. The books close column by column:
/// mass + sum over F of outflow_F_mass is the initial mass, and total_energy + sum of outflow_F_total_energy is
/// E(0) + W (docs/theory.md §8).
const std::vector<std::string> outflow_energy_columns{"kinetic_energy", "strain_energy", "gravity_potential_energy",
                                                      "total_energy",   "momentum_x",    "momentum_y",
                                                      "momentum_z",     "mass",          "plastic_work",
                                                      "thermal_energy", "particles"};

/// With erosion (a material's `failure:` with action erode), what the eroded particles took along since t = 0
/// (FailureModule::eroded): eroded_ and the outflow columns' names, with eroded_internal_energy (strain + thermal)
/// after eroded_strain_energy. The books close as the outflow's: mass + eroded_mass is the initial mass, and
/// total_energy + eroded_total_energy is E(0) + W (docs/theory.md eq. 8.4).
const std::vector<std::string> eroded_energy_columns{
    "kinetic_energy", "strain_energy", "internal_energy", "gravity_potential_energy",
    "total_energy",   "momentum_x",    "momentum_y",      "momentum_z",
    "mass",           "plastic_work",  "thermal_energy",  "particles"};

/// The run's failure module when a material erodes, else null.
template <int Dim>
const FailureModule<Dim>* erosion_of(const Simulation<Dim>& sim) {
  for (const auto& m : sim.modules())
    if (const auto* f = dynamic_cast<const FailureModule<Dim>*>(m.get()); f && f->erodes()) return f;
  return nullptr;
}

template <int Dim>
std::vector<std::string> energy_columns(const Simulation<Dim>& sim) {
  std::vector<std::string> columns = base_energy_columns;
  for (const auto& book : sim.boundary().outflow())
    for (const auto& c : outflow_energy_columns)
      columns.push_back(fmt::format("outflow_{}_{}", face_names[static_cast<std::size_t>(book.face)], c));
  if (erosion_of(sim))
    for (const auto& c : eroded_energy_columns) columns.push_back("eroded_" + c);
  // the modules' own books (Module::energy_column): local damping's damped_energy, the thermal strain's work
  for (const auto& m : sim.modules())
    if (!m->energy_column().empty()) columns.emplace_back(m->energy_column());
  return columns;
}

/// The columns of the energy.csv a restart continues: the base ones and the outflow, eroded and modules' ones its
/// header has (a restart continues the same scene: every column after the base ones is one of those).
std::vector<std::string> continued_energy_columns(const io::FileMark& mark) {
  std::vector<std::string> columns = base_energy_columns;
  std::ifstream in(mark.path);
  std::string header;
  if (!std::getline(in, header)) return columns;
  std::size_t begin = 0;
  for (std::size_t k = 0; begin <= header.size(); ++k) {
    const std::size_t end = std::min(header.find(',', begin), header.size());
    const std::string name = header.substr(begin, end - begin);
    if (k >= base_energy_columns.size()) columns.push_back(name);
    begin = end + 1;
  }
  return columns;
}

}  // namespace

template <int Dim>
OutputWriter<Dim>::OutputWriter(std::filesystem::path directory, std::string prefix, std::vector<std::string> fields,
                                bool grid, Real interval, const StateArchive* restart, Communicator* comm)
    : directory_(std::move(directory)),
      prefix_(std::move(prefix)),
      fields_(std::move(fields)),
      grid_(grid),
      interval_(interval),
      particles_pvd_(directory_ / (prefix_ + ".pvd")),
      comm_(comm) {
  // `domains` is not a point field: the particle domains go to a cell file of their own per frame.
  if (const auto it = std::find(fields_.begin(), fields_.end(), "domains"); it != fields_.end()) {
    fields_.erase(it);
    domains_pvd_ = std::make_unique<io::PvdCollection>(directory_ / (prefix_ + "_domains.pvd"));
  }
  fields_.push_back("id");
  if (grid_) grid_pvd_ = std::make_unique<io::PvdCollection>(directory_ / (prefix_ + "_grid.pvd"));
  const std::vector<std::string>& columns = base_energy_columns;  // a scene with outflow: widened by the first row
  if (restart) {
    // Rank 0 of a distributed run continues the files; every rank continues the schedule.
    io::write_collectively(comm_, "continuing the output in '" + directory_.string() + "'", [&] {
      if (distributed() && comm_->rank() != 0) return;
      std::filesystem::create_directories(directory_);
      const io::FileMark mark = io::load_mark(*restart, "output/energy");
      energy_ = std::make_unique<io::CsvLog>(directory_ / "energy.csv", continued_energy_columns(mark), mark);
    });
    restore_state(*restart);
  } else {
    io::write_collectively(comm_, "creating the output directory '" + directory_.string() + "'", [&] {
      std::filesystem::create_directories(directory_);
      if (!distributed() || comm_->rank() == 0)  // the values are global: one table, from rank 0
        energy_ = std::make_unique<io::CsvLog>(directory_ / "energy.csv", columns);
    });
  }
}

template <int Dim>
io::PointCloud OutputWriter<Dim>::particle_cloud(const Simulation<Dim>& sim) const {
  io::PointCloud cloud;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) append_padded<Dim>(cloud.points, b.particles.x[i]);
  for (const auto& name : fields_) {
    const OutputField* field = find_output_field(name);  // the table of output_fields.hpp
    if (!field) throw std::invalid_argument("unknown output field '" + name + "'");
    io::FieldArray f{name, field->components, {}};
    if (sim.grid().geometry.coordinates == Coordinates::axisymmetric)
      f.component_names = io::cylindrical_component_names(field->components);
    f.values.reserve(cloud.size() * f.components);
    for (const auto& b : sim.bodies()) append_output_field<Dim>(name, b, f.values);
    cloud.fields.push_back(std::move(f));
  }
  return cloud;
}

template <int Dim>
bool OutputWriter<Dim>::write_if_due(const Simulation<Dim>& sim) {
  const Real tolerance = 1e-9 * std::max<Real>(1, sim.settings().end_time);
  const bool due = frame_ == 0 || (interval_ > 0 && sim.time() >= next_time_ - tolerance);
  if (!due) return false;
  write(sim);
  return true;
}

template <int Dim>
void OutputWriter<Dim>::write(const Simulation<Dim>& sim) {
  if (sim.time() == last_written_) return;
  const io::FieldData data = frame_field_data(sim);
  if (distributed())
    write_pieces(sim, data);
  else
    write_files(sim, data);
  last_written_ = sim.time();
  ++frame_;
  if (interval_ > 0)
    next_time_ = next_due_time(next_time_, interval_, sim.time() + 1e-9 * std::max<Real>(1, sim.settings().end_time));
}

template <int Dim>
io::FieldData OutputWriter<Dim>::frame_field_data(const Simulation<Dim>& sim) const {
  io::FieldData data = field_data_;  // self-describing files: the run's description, the time and the step
  data.numbers.emplace_back("TIME", sim.time());
  data.numbers.emplace_back("step", static_cast<double>(sim.step()));
  return data;
}

template <int Dim>
void OutputWriter<Dim>::write_files(const Simulation<Dim>& sim, const io::FieldData& data) {
  const std::string name = fmt::format("{}_{:06d}.vtu", prefix_, frame_);
  io::PointCloud cloud = particle_cloud(sim);
  cloud.field_data = data;
  io::write_vtu(directory_ / name, cloud);
  particles_pvd_.add(sim.time(), directory_ / name);
  particles_pvd_.write();
  if (domains_pvd_) {
    const std::string domains_name = fmt::format("{}_domains_{:06d}.vtu", prefix_, frame_);
    io::CellMesh mesh = particle_domain_mesh(sim.bodies());
    mesh.field_data = data;
    io::write_cells_vtu(directory_ / domains_name, mesh);
    domains_pvd_->add(sim.time(), directory_ / domains_name);
    domains_pvd_->write();
  }
  if (grid_) {
    const std::string grid_name = fmt::format("{}_grid_{:06d}.vti", prefix_, frame_);
    io::write_vti(directory_ / grid_name, grid_image(sim, data));
    grid_pvd_->add(sim.time(), directory_ / grid_name);
    grid_pvd_->write();
  }
  append_energy_row(sim, energy_row(sim));
}

namespace {

/// What a .pvtu declares of the pieces' arrays: names, components, component names (not the values).
std::vector<io::FieldArray> array_layout(const std::vector<io::FieldArray>& fields) {
  std::vector<io::FieldArray> layout;
  layout.reserve(fields.size());
  for (const auto& f : fields) layout.push_back({f.name, f.components, {}, f.component_names});
  return layout;
}

}  // namespace

// Two collective phases, so that a .pvtu and a .pvd entry exist only once every piece does: (1) every rank writes
// its pieces; (2) rank 0 writes the .pvtu files, the .pvd files and the energy row. A failure on any rank in
// either phase makes every rank throw (write_collectively).
template <int Dim>
void OutputWriter<Dim>::write_pieces(const Simulation<Dim>& sim, const io::FieldData& data) {
  const std::vector<double> energy = energy_row(sim);  // on every rank: a distributed energy() is a reduction
  const int rank = comm_->rank();
  const auto particles_pvtu = directory_ / fmt::format("{}_{:06d}.pvtu", prefix_, frame_);
  const auto domains_pvtu = directory_ / fmt::format("{}_domains_{:06d}.pvtu", prefix_, frame_);
  io::PvtuSummary particles, domains;
  std::optional<io::ImageGrid> grid;  // complete on rank 0
  if (grid_) grid = gathered_grid_image(sim, data);
  io::write_collectively(comm_, fmt::format("output frame {} ({})", frame_, particles_pvtu.string()), [&] {
    io::PointCloud cloud = particle_cloud(sim);
    cloud.field_data = data;
    const auto piece = io::pvtu_piece_path(particles_pvtu, rank);
    std::filesystem::create_directories(piece.parent_path());
    io::write_vtu(piece, cloud);
    particles.point_fields = array_layout(cloud.fields);
    if (domains_pvd_) {
      io::CellMesh mesh = particle_domain_mesh(sim.bodies());
      mesh.field_data = data;
      const auto domains_piece = io::pvtu_piece_path(domains_pvtu, rank);
      std::filesystem::create_directories(domains_piece.parent_path());
      io::write_cells_vtu(domains_piece, mesh);
      domains.cell_fields = array_layout(mesh.cell_fields);
    }
  });
  io::write_collectively(comm_, fmt::format("output frame {} (the .pvtu, .pvd and energy.csv)", frame_), [&] {
    if (rank != 0) return;
    for (int r = 0; r < comm_->size(); ++r) {
      particles.pieces.push_back(io::pvtu_piece_path(particles_pvtu, r));
      domains.pieces.push_back(io::pvtu_piece_path(domains_pvtu, r));
    }
    particles.field_data = domains.field_data = data;
    io::write_pvtu(particles_pvtu, particles);
    particles_pvd_.add(sim.time(), particles_pvtu);
    particles_pvd_.write();
    if (domains_pvd_) {
      io::write_pvtu(domains_pvtu, domains);
      domains_pvd_->add(sim.time(), domains_pvtu);
      domains_pvd_->write();
    }
    if (grid) {  // one image, the one-process file
      const std::string grid_name = fmt::format("{}_grid_{:06d}.vti", prefix_, frame_);
      io::write_vti(directory_ / grid_name, *grid);
      grid_pvd_->add(sim.time(), directory_ / grid_name);
      grid_pvd_->write();
    }
    append_energy_row(sim, energy);
  });
}

template <int Dim>
io::ImageGrid OutputWriter<Dim>::grid_image(const Simulation<Dim>& sim, const io::FieldData& data) const {
  const auto& g = sim.grid();
  io::ImageGrid image;
  for (int d = 0; d < Dim; ++d) {
    image.origin[d] = g.geometry.origin[d];
    image.spacing[d] = g.geometry.h[d];
    image.nodes[d] = g.geometry.nodes[d];
  }
  io::FieldArray mass{"mass", 1, {}}, density{"density", 1, {}}, velocity{"velocity", 3, {}}, force{"force", 3, {}};
  const VecU<Dim> none = VecU<Dim>::Zero();
  for (Index n = 0; n < g.size(); ++n) {
    mass.values.push_back(g.node[n].mass);
    density.values.push_back(g.node[n].mass / node_volume(g.geometry, n));
    // A node without mass has no velocity: zero there, whatever a face condition wrote. Kernels with sparse tiles
    // write a face's nodes only where particles reach (GridBoundary::apply), so without this the file would show
    // the prescribed velocities of the empty face nodes some particles once reached and not of the others.
    append_padded<Dim>(velocity.values, g.node[n].mass > 0 ? g.velocity[n].mapped : none);
    append_padded<Dim>(force.values, g.node[n].force);
  }
  if (g.geometry.coordinates == Coordinates::axisymmetric)
    velocity.component_names = force.component_names = io::cylindrical_component_names(3);
  image.fields = {mass, density, velocity, force};
  image.field_data = data;
  for (const auto& [name, values] : g.node_fields)  // modules' nodal fields (thermal: temperature)
    if (static_cast<Index>(values.size()) == g.size()) image.fields.push_back({name, 1, values});
  return image;
}

template <int Dim>
io::ImageGrid OutputWriter<Dim>::gathered_grid_image(const Simulation<Dim>& sim, const io::FieldData& data) const {
  io::ImageGrid image = grid_image(sim, data);
  const Index nodes = sim.grid().size();
  // Each rank other than 0 sends its owned nodes: their count, their indices, then every field's values at them.
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(comm_->size()));
  if (comm_->rank() != 0) {
    std::vector<std::int64_t> owned;
    for (Index n = 0; n < nodes; ++n)
      if (sim.owns_node(n)) owned.push_back(n);
    std::vector<double> values;
    for (const io::FieldArray& f : image.fields)
      for (const std::int64_t n : owned)
        for (int c = 0; c < f.components; ++c)
          values.push_back(f.values[static_cast<std::size_t>(n * f.components + c)]);
    const auto count = static_cast<std::int64_t>(owned.size());
    std::vector<std::byte>& bytes = out[0];
    bytes.resize(sizeof count + owned.size() * sizeof(std::int64_t) + values.size() * sizeof(double));
    std::memcpy(bytes.data(), &count, sizeof count);
    std::memcpy(bytes.data() + sizeof count, owned.data(), owned.size() * sizeof(std::int64_t));
    std::memcpy(bytes.data() + sizeof count + owned.size() * sizeof(std::int64_t), values.data(),
                values.size() * sizeof(double));
  }
  const auto in = comm_->all_to_all(std::move(out));
  if (comm_->rank() != 0) return image;
  for (const auto& bytes : in) {
    if (bytes.empty()) continue;
    std::int64_t count = 0;
    std::memcpy(&count, bytes.data(), sizeof count);
    std::vector<std::int64_t> owned(static_cast<std::size_t>(count));
    std::memcpy(owned.data(), bytes.data() + sizeof count, owned.size() * sizeof(std::int64_t));
    const std::byte* at = bytes.data() + sizeof count + owned.size() * sizeof(std::int64_t);
    for (io::FieldArray& f : image.fields)
      for (const std::int64_t n : owned)
        for (int c = 0; c < f.components; ++c) {
          std::memcpy(&f.values[static_cast<std::size_t>(n * f.components + c)], at, sizeof(double));
          at += sizeof(double);
        }
  }
  return image;
}

template <int Dim>
std::vector<double> OutputWriter<Dim>::energy_row(const Simulation<Dim>& sim) const {
  const EnergyBalance e = sim.energy();
  std::vector<double> row{sim.time(),     static_cast<double>(sim.step()),
                          e.kinetic,      e.strain,
                          e.gravity,      e.total(),
                          e.momentum[0],  e.momentum[1],
                          e.momentum[2],  e.mass,
                          e.plastic_work, e.thermal};
  for (const auto& book : sim.boundary().outflow()) {  // the same on every rank
    const EnergyBalance out = book.value();
    row.insert(row.end(), {out.kinetic, out.strain, out.gravity, out.total(), out.momentum[0], out.momentum[1],
                           out.momentum[2], out.mass, out.plastic_work, out.thermal, book.particle_count()});
  }
  if (const auto* failure = erosion_of(sim)) {  // the same on every rank
    const RemovedBook book = failure->eroded();
    const EnergyBalance out = book.value();
    row.insert(row.end(),
               {out.kinetic, out.strain, out.strain + out.thermal, out.gravity, out.total(), out.momentum[0],
                out.momentum[1], out.momentum[2], out.mass, out.plastic_work, out.thermal, book.particle_count()});
  }
  for (const auto& m : sim.modules())  // the same on every rank
    if (!m->energy_column().empty()) row.push_back(m->energy_column_value());
  return row;
}

template <int Dim>
void OutputWriter<Dim>::append_energy_row(const Simulation<Dim>& sim, const std::vector<double>& row) {
  // A scene with outflow faces, erosion or damping has their columns too: the first frame writes the header again.
  if (frame_ == 0 && energy_->columns().size() != row.size())
    energy_ = std::make_unique<io::CsvLog>(energy_->path(), energy_columns(sim));
  energy_->append(row);
}

template class OutputWriter<1>;
template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace mpm
