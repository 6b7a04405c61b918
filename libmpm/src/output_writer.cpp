#include "mpm/output_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/particle_domain_mesh.hpp"

namespace mpm {

std::vector<std::string> output_field_names() {
  return {"velocity",
          "displacement",
          "stress",
          "deformation_gradient",
          "mass",
          "volume",
          "density",
          "body",
          "velocity_gradient",
          "pressure",
          "von_mises_stress",
          "domain_size",
          "domains",
          "plastic_strain",
          "plastic_strain_rate",
          "damage",
          "temperature",
          "internal_energy",
          "heat_flux"};
}

namespace {

template <int Dim>
void pad3(std::vector<double>& out, const VecU<Dim>& v) {
  for (int d = 0; d < 3; ++d) out.push_back(d < Dim ? v[d] : 0.0);
}
void push_mat3(std::vector<double>& out, const Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
}

// Values of one named field for every particle of a body, appended to `out`. The field is chosen once,
// then one loop runs over the particles.
template <int Dim>
void append_field(const std::string& name, const Body<Dim>& b, std::vector<double>& out) {
  const auto& p = b.particles;
  auto each = [&](auto&& f) {
    for (Index i = 0; i < p.size(); ++i) f(i);
  };
  if (name == "velocity") {
    each([&](Index i) { pad3<Dim>(out, p.v[i]); });
  } else if (name == "displacement") {
    const auto& x0 = p.template field<VecU<Dim>>("reference_position");
    each([&](Index i) { pad3<Dim>(out, VecU<Dim>(p.x[i] - x0[i])); });
  } else if (name == "stress") {
    each([&](Index i) {  // ParaView order XX YY ZZ XY YZ XZ
      const Mat3 s = p.stress[i].full();
      for (double v : {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)}) out.push_back(v);
    });
  } else if (name == "deformation_gradient") {
    each([&](Index i) { push_mat3(out, embed<Dim>(p.F[i], 1)); });
  } else if (name == "velocity_gradient") {
    const auto& L = p.template field<MatU<Dim>>("velocity_gradient");
    each([&](Index i) { push_mat3(out, embed<Dim>(Mat<Dim>(L[i]), 0)); });
  } else if (name == "mass") {
    each([&](Index i) { out.push_back(p.mass[i]); });
  } else if (name == "volume") {
    each([&](Index i) { out.push_back(p.volume0[i] * p.F[i].determinant()); });
  } else if (name == "density") {
    each([&](Index i) { out.push_back(p.mass[i] / (p.volume0[i] * p.F[i].determinant())); });
  } else if (name == "body") {
    each([&](Index) { out.push_back(b.index); });
  } else if (name == "pressure") {
    each([&](Index i) { out.push_back(-p.stress[i].full().trace() / 3); });
  } else if (name == "von_mises_stress") {
    each([&](Index i) {
      const Mat3 s = p.stress[i].full();
      const Mat3 dev = s - s.trace() / 3 * Mat3::Identity();
      out.push_back(std::sqrt(1.5 * dev.squaredNorm()));
    });
  } else if (name == "domain_size") {
    // GIMP particle domain lengths per axis, l_p = 2 x half-length (cpGIMP: stretched by diag F, eq.
    // 3.14); in ParaView: Glyph filter, glyph type Box, scale array domain_size, scale by components.
    const auto& half0 = p.template field<VecU<Dim>>("domain_half_length0");
    const bool stretched = b.stretched_domain;
    each([&](Index i) {
      VecU<Dim> l = 2 * half0[i];
      if (stretched) l = l.cwiseProduct(VecU<Dim>(p.F[i].diagonal()));
      pad3<Dim>(out, l);
    });
  } else if (b.material->append_output(name, p, out)) {
    // a field of the body's material model (plasticity: plastic_strain, plastic_strain_rate, damage)
  } else if (name == "plastic_strain" || name == "plastic_strain_rate" || name == "damage") {
    each([&](Index) { out.push_back(0.0); });  // a body without plasticity: no plastic flow, no damage
  } else if (name == "internal_energy") {
    each([&](Index) { out.push_back(0.0); });  // J/kg; only gas bodies (ideal_gas) carry one
  } else if (name == "temperature") {
    if (p.has_field("temperature")) {
      const auto& T = p.template field<Real>("temperature");  // K
      each([&](Index i) { out.push_back(T[i]); });
    } else {
      each([&](Index) { out.push_back(0.0); });  // a body that does not track temperature (documented: 0)
    }
  } else if (name == "heat_flux") {
    if (p.has_field("heat_flux")) {
      const auto& q = p.template field<VecU<Dim>>("heat_flux");  // W/m^2 (thermal module)
      each([&](Index i) { pad3<Dim>(out, q[i]); });
    } else {
      each([&](Index) { pad3<Dim>(out, VecU<Dim>::Zero()); });  // a body without conduction
    }
  } else if (name == "id") {
    each([&](Index i) { out.push_back(p.id[i]); });
  } else {
    throw std::invalid_argument("unknown output field '" + name + "'");
  }
}

int components(const std::string& name) {
  if (name == "velocity" || name == "displacement" || name == "domain_size" || name == "heat_flux") return 3;
  if (name == "stress") return 6;
  if (name == "deformation_gradient" || name == "velocity_gradient") return 9;
  return 1;
}

}  // namespace

template <int Dim>
OutputWriter<Dim>::OutputWriter(std::filesystem::path directory, std::string prefix, std::vector<std::string> fields,
                                bool grid, Real interval)
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
  energy_ = std::make_unique<io::CsvLog>(
      directory_ / "energy.csv",
      std::vector<std::string>{"time", "step", "kinetic_energy", "strain_energy", "gravity_potential_energy",
                               "total_energy", "momentum_x", "momentum_y", "momentum_z", "mass", "plastic_work",
                               "thermal_energy"});
}

template <int Dim>
io::PointCloud OutputWriter<Dim>::particle_cloud(const Simulation<Dim>& sim) const {
  io::PointCloud cloud;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) pad3<Dim>(cloud.points, b.particles.x[i]);
  for (const auto& name : fields_) {
    io::FieldArray f{name, components(name), {}};
    f.values.reserve(cloud.size() * f.components);
    for (const auto& b : sim.bodies()) append_field(name, b, f.values);
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
  const std::string name = fmt::format("{}_{:06d}.vtu", prefix_, frame_);
  io::write_vtu(directory_ / name, particle_cloud(sim));
  particles_pvd_.add(sim.time(), directory_ / name);
  particles_pvd_.write();
  if (domains_pvd_) {
    const std::string domains_name = fmt::format("{}_domains_{:06d}.vtu", prefix_, frame_);
    io::write_cells_vtu(directory_ / domains_name, particle_domain_mesh(sim.bodies()));
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
      pad3<Dim>(velocity.values, g.velocity[n].mapped);
      pad3<Dim>(force.values, g.node[n].force);
    }
    image.fields = {mass, velocity, force};
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
    while (next_time_ <= sim.time() + 1e-9 * std::max<Real>(1, sim.settings().end_time)) next_time_ += interval_;
}

template class OutputWriter<1>;
template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace mpm
