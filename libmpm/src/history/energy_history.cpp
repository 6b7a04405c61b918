// `type: energy` (docs/scene-reference.md#histories): the conservation audit of energy.csv for one body (or all
// of them): kinetic, strain, gravity potential, plastic work, thermal energy, momentum, mass, and the centre
// of mass's position and velocity. The bodies' histories sum to energy.csv (Simulation::body_energy is the
// same accumulation per body).
#include <array>

#include "history_support.hpp"
#include "mpm/core/exact_sum.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace energy {

struct EnergySpec {
  int body = -1;  ///< -1: all bodies
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  EnergySpec s;
  if (const auto body = entry.find("body")) s.body = read_body(reader, *body, scene);
  return s;
}

template <int Dim>
class EnergyHistory final : public History<Dim> {
 public:
  EnergyHistory(int body, Coordinates coordinates) : body_(body), coordinates_(coordinates) {}

  std::vector<std::string> columns() const override {
    const std::string J = extensive_unit("J", Dim, coordinates_);
    std::vector<std::string> names;
    for (const char* e : {"kinetic_energy", "strain_energy", "gravity_potential_energy", "plastic_work",
                          "thermal_energy", "total_energy"})
      names.push_back(column_name(e, J));
    const char* axis[] = {"x", "y", "z"};
    for (int d = 0; d < Dim; ++d)
      names.push_back(column_name(std::string("momentum_") + axis[d], extensive_unit("kg m/s", Dim, coordinates_)));
    names.push_back(column_name("mass", extensive_unit("kg", Dim, coordinates_)));
    for (int d = 0; d < Dim; ++d) names.push_back(column_name(std::string("position_cm_") + axis[d], "m"));
    for (int d = 0; d < Dim; ++d) names.push_back(column_name(std::string("velocity_cm_") + axis[d], "m/s"));
    return names;
  }

  void sample(const Simulation<Dim>& sim, OutputFieldCache<Dim>&, std::vector<double>& row) override {
    const EnergyBalance e = body_ < 0 ? sim.energy() : sim.body_energy(sim.bodies()[static_cast<std::size_t>(body_)]);
    for (double v : {e.kinetic, e.strain, e.gravity, e.plastic_work, e.thermal, e.total()}) row.push_back(v);
    for (int d = 0; d < Dim; ++d) row.push_back(e.momentum[d]);
    row.push_back(e.mass);
    std::array<ExactSum, Dim> first;  // sum m x, exactly: the same for any particle order
    for (int b = 0; b < static_cast<int>(sim.bodies().size()); ++b) {
      if (body_ >= 0 && b != body_) continue;
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      for (Index i = 0; i < p.size(); ++i)
        for (int d = 0; d < Dim; ++d) first[d] += p.mass[i] * p.x[i][d];
    }
    if (Communicator* comm = sim.communicator()) comm->sum(first);  // every rank's particles
    for (int d = 0; d < Dim; ++d) row.push_back(e.mass > 0 ? first[d].value() / e.mass : 0);
    for (int d = 0; d < Dim; ++d) row.push_back(e.mass > 0 ? e.momentum[d] / e.mass : 0);
  }

 private:
  int body_;
  Coordinates coordinates_;
};

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription& scene, Simulation<Dim>&,
                                   std::vector<std::string>&) {
  return std::make_unique<EnergyHistory<Dim>>(std::any_cast<const EnergySpec&>(h.spec).body, scene.grid.coordinates);
}

}  // namespace energy
}  // namespace

HistoryKind energy_kind() {
  using namespace energy;
  return history_kind("energy", "energies, momentum, mass and centre of mass of one body (or of all, as energy.csv)",
                      {"body"}, parse, make<1>, make<2>, make<3>);
}

}  // namespace mpm::history
