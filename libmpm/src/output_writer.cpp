#include "mpm/output_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "mpm/due_time.hpp"
#include "mpm/particle_domain_mesh.hpp"

namespace mpm {

template <int Dim>
OutputWriter<Dim>::OutputWriter(std::filesystem::path directory, std::string prefix, std::vector<std::string> fields,
                                bool grid, Real interval, const StateArchive* restart)
    : directory_(std::move(directory)),
      prefix_(std::move(prefix)),
      fields_(std::move(fields)),
      grid_(grid),
      interval_(interval),
      particles_pvd_(directory_ / (prefix_ + ".pvd")) {
  std::filesystem::create_directories(directory_);
  // `domains` is not a point field: the particle domains go to a cell file of their own per frame.
  if (const auto it = std::find(fields_.begin(), fields_.end(), "domains"); it != fields_.end()) {
    fields_.erase(it);
    domains_pvd_ = std::make_unique<io::PvdCollection>(directory_ / (prefix_ + "_domains.pvd"));
  }
  fields_.push_back("id");
  if (grid_) grid_pvd_ = std::make_unique<io::PvdCollection>(directory_ / (prefix_ + "_grid.pvd"));
  const std::vector<std::string> columns{
      "time",         "step",          "kinetic_energy", "strain_energy", "gravity_potential_energy",
      "total_energy", "momentum_x",    "momentum_y",     "momentum_z",    "mass",
      "plastic_work", "thermal_energy"};
  if (restart) {
    energy_ =
        std::make_unique<io::CsvLog>(directory_ / "energy.csv", columns, io::load_mark(*restart, "output/energy"));
    restore_state(*restart);
  } else {
    energy_ = std::make_unique<io::CsvLog>(directory_ / "energy.csv", columns);
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
  io::FieldData data = field_data_;  // self-describing files: the run's description, the time and the step
  data.numbers.emplace_back("TIME", sim.time());
  data.numbers.emplace_back("step", static_cast<double>(sim.step()));
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
    const auto& g = sim.grid();
    io::ImageGrid image;
    for (int d = 0; d < Dim; ++d) {
      image.origin[d] = g.geometry.origin[d];
      image.spacing[d] = g.geometry.h[d];
      image.nodes[d] = g.geometry.nodes[d];
    }
    io::FieldArray mass{"mass", 1, {}}, velocity{"velocity", 3, {}}, force{"force", 3, {}};
    for (Index n = 0; n < g.size(); ++n) {
      mass.values.push_back(g.node[n].mass);
      append_padded<Dim>(velocity.values, g.velocity[n].mapped);
      append_padded<Dim>(force.values, g.node[n].force);
    }
    if (g.geometry.coordinates == Coordinates::axisymmetric)
      velocity.component_names = force.component_names = io::cylindrical_component_names(3);
    image.fields = {mass, velocity, force};
    image.field_data = data;
    for (const auto& [name, values] : g.node_fields)  // modules' nodal fields (thermal: temperature)
      if (static_cast<Index>(values.size()) == g.size()) image.fields.push_back({name, 1, values});
    const std::string grid_name = fmt::format("{}_grid_{:06d}.vti", prefix_, frame_);
    io::write_vti(directory_ / grid_name, image);
    grid_pvd_->add(sim.time(), directory_ / grid_name);
    grid_pvd_->write();
  }
  const EnergyBalance e = sim.energy();
  energy_->append({sim.time(), static_cast<double>(sim.step()), e.kinetic, e.strain, e.gravity, e.total(),
                   e.momentum[0], e.momentum[1], e.momentum[2], e.mass, e.plastic_work, e.thermal});
  last_written_ = sim.time();
  ++frame_;
  if (interval_ > 0)
    next_time_ = next_due_time(next_time_, interval_, sim.time() + 1e-9 * std::max<Real>(1, sim.settings().end_time));
}

template class OutputWriter<1>;
template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace mpm
