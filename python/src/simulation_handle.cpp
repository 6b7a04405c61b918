#include "simulation_handle.hpp"

#include <tbb/task_arena.h>

#include <chrono>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "mpm/app/run_checkpoints.hpp"
#include "mpm/app/run_description.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/boundary/face_names.hpp"
#include "mpm/failure/failure_module.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/run/run.hpp"

namespace mpm::python {
namespace {

/// Calls `poll` when `seconds` of wall time have passed since the last call (a clock read per step).
class Poller {
 public:
  Poller(const std::function<void()>& poll, double seconds) : poll_(poll), interval_(seconds) {}
  void poll_if_due() {
    if (!poll_ || Clock::now() - last_ < interval_) return;
    poll_();
    last_ = Clock::now();
  }

 private:
  using Clock = std::chrono::steady_clock;
  const std::function<void()>& poll_;
  std::chrono::duration<double> interval_;
  Clock::time_point last_ = Clock::now();
};

/// The particle fields every body has (ParticleSet's typed members), by the names the stability guard's
/// report uses; `id` is read-only.
template <int Dim>
std::optional<FieldArray> core_field(ParticleSet<Dim>& p, const std::string& name) {
  FieldArray a;
  a.writable = true;
  if (name == "position") {
    a.storage = field_storage(p.x);
  } else if (name == "velocity") {
    a.storage = field_storage(p.v);
  } else if (name == "mass") {
    a.storage = field_storage(p.mass);
  } else if (name == "reference_volume") {
    a.storage = field_storage(p.volume0);
  } else if (name == "deformation_gradient") {
    a.storage = field_storage(p.F);
    // F is Dim x Dim (column-major), also in 1D where Eigen's 1 x 1 matrix type is its 1-vector.
    a.storage.layout.shape = {Dim, Dim};
    a.storage.layout.strides = {sizeof(Real), Dim * sizeof(Real)};
  } else if (name == "stress") {
    a.storage = field_storage(p.stress);
  } else if (name == "id") {
    a.storage = field_storage(p.id);
    a.writable = false;
  } else {
    return std::nullopt;
  }
  return a;
}
const std::vector<std::string> core_field_names{
    "position", "velocity", "mass", "reference_volume", "deformation_gradient", "stress", "id"};

/// The whole array's shape and strides: `count` values of `storage` (a field per particle or per node).
void add_value_axes(FieldArray& a, std::vector<Index> shape, std::vector<Index> strides) {
  for (std::size_t k = 0; k < a.storage.layout.shape.size(); ++k) {
    shape.push_back(a.storage.layout.shape[k]);
    strides.push_back(a.storage.layout.strides[k]);
  }
  a.shape = std::move(shape);
  a.strides = std::move(strides);
}

/// The package's log: the run's lines on stderr, as `mpm run` prints them.
class StderrLog final : public RunLog {
 public:
  void line(const std::string& text) override { std::cerr << text << '\n'; }
};

/// What the package watches while the run steps: the callback after every `every`-th step (true stops the run),
/// then the poll when it is due.
template <int Dim>
class Control final : public RunObserver<Dim> {
 public:
  explicit Control(const RunControl& control) : control_(control), poller_(control.poll, control.poll_seconds) {}
  bool after_step(const Simulation<Dim>& s) override {
    if (control_.callback && s.step() % control_.every == 0 && control_.callback()) return true;
    poller_.poll_if_due();
    return false;
  }

 private:
  const RunControl& control_;
  Poller poller_;
};

template <int Dim>
class SimulationFor final : public SimulationHandle {
 public:
  SimulationFor(const SceneDescription& scene_in, int threads, const std::string& output_directory)
      : arena_(threads > 0 ? threads : tbb::task_arena::automatic) {
    SceneDescription scene = scene_in;  // modules writing their own files (contact forces) follow the directory
    if (!output_directory.empty()) scene.output.directory = output_directory;
    // output.checkpoint: the program's checkpoint files (a YAML scene's run continues with `mpm run --restart`)
    if (!output_directory.empty() && scene.output.checkpoint.enabled)
      checkpoints_ = std::make_unique<app::RunCheckpoints>(scene, scene.source,
                                                           app::checkpoint_directory(scene, output_directory));
    arena_.execute([&] {
      run_ = app::make_run<Dim>(scene, log_);  // throws SceneError as the program
      run_->log_warnings();
      RunOutput output{output_directory,  app::run_field_data(scene, {}), app::view_script_for(scene), nullptr, nullptr,
                       checkpoints_.get()};
      output.keep_history_rows = true;  // Simulation.histories, with output=False too
      run_->start(std::move(output));
    });
  }

  int dimension() const override { return Dim; }

  void step() override {
    arena_.execute([&] { run_->step(); });
  }

  void advance_to(double t, const std::function<void()>& poll, double poll_seconds) override {
    RunControl control;
    control.poll = poll;
    control.poll_seconds = poll_seconds;
    Control<Dim> observer(control);
    arena_.execute([&] { run_->advance_to(t, &observer); });
  }

  bool run(const RunControl& control) override {
    Control<Dim> observer(control);
    RunEnd end = RunEnd::end_time;
    arena_.execute([&] {
      std::optional<Index> last_step;
      if (control.steps) last_step = sim().step() + *control.steps;
      end = run_->run(last_step, &observer);
    });
    if (control.poll) control.poll();
    return end == RunEnd::stopped;
  }

  double time() const override { return sim().time(); }
  Index step_count() const override { return sim().step(); }
  double dt() override {
    run_->apply_particle_changes();
    return sim().finished() ? sim().next_time_step() : sim().time_step_toward(sim().settings().end_time);
  }
  double end_time() const override { return sim().settings().end_time; }
  bool finished() const override { return sim().finished(); }
  double stable_time_step() override {
    run_->apply_particle_changes();
    return sim().stable_time_step();
  }
  Index particle_count() const override { return sim().particle_count(); }
  EnergyBalance energy() const override { return sim().energy(); }
  std::vector<RemovedTotals> removed() const override {
    std::vector<RemovedTotals> out;
    for (const auto& book : sim().boundary().outflow())
      out.push_back({fmt::format("outflow_{}", face_names[static_cast<std::size_t>(book.face)]), book.value(),
                     book.particle_count()});
    for (const auto& m : sim().modules())
      if (const auto* f = dynamic_cast<const FailureModule<Dim>*>(m.get()); f && f->erodes()) {
        const RemovedBook book = f->eroded();
        out.push_back({"eroded", book.value(), book.particle_count()});
      }
    return out;
  }

  void write_frame(const std::string& directory) override {
    arena_.execute([&] { run_->write_frame(directory); });
  }
  std::string output_directory() const override { return run_->output_directory().string(); }
  std::vector<std::string> history_names() const override {
    std::vector<std::string> names;
    if (const auto* h = run_->histories())
      for (std::size_t k = 0; k < h->size(); ++k) names.push_back(h->description(k).name);
    return names;
  }
  std::vector<std::string> history_columns(std::size_t k) const override { return run_->histories()->columns(k); }
  std::vector<double> history_rows(std::size_t k) const override { return run_->histories()->rows(k); }

  std::vector<std::string> body_names() const override {
    std::vector<std::string> names;
    for (const auto& b : sim().bodies()) names.push_back(b.name);
    return names;
  }
  Index body_size(int body) const override { return sim().bodies().at(body).particles.size(); }

  std::vector<std::string> particle_fields(int body) override {
    std::vector<std::string> names = core_field_names;
    auto& p = sim().bodies().at(body).particles;
    for (const auto& name : p.field_names())
      if (p.storage(name).layout.scalar != 0) names.push_back(name);
    return names;
  }

  FieldArray particle_field(int body, const std::string& name) override {
    auto& p = sim().bodies().at(body).particles;
    std::optional<FieldArray> a = core_field(p, name);
    if (!a) {
      if (!p.has_field(name)) throw std::out_of_range("no particle field '" + name + "'");
      a = FieldArray{p.storage(name), {}, {}, true};
      if (a->storage.layout.scalar == 0)
        throw std::out_of_range("particle field '" + name +
                                "' holds records (a material's history) that cannot be viewed as an array; its "
                                "quantities are output fields (Body.output(name))");
    }
    add_value_axes(*a, {a->storage.count}, {a->storage.stride});
    return *a;
  }

  std::uint64_t generation(int body) const override { return sim().bodies().at(body).particles.generation(); }

  std::vector<double> output_values(int body, const std::string& name, int& components) const override {
    const OutputField* field = find_output_field(name);
    if (!field) throw std::out_of_range("no output field '" + name + "'");
    components = field->components;
    std::vector<double> values;
    append_output_field<Dim>(name, sim().bodies().at(body), values);
    return values;
  }

  void mark_changed() override { run_->mark_particles_changed(); }

  GridInfo grid_info() const override {
    const auto& g = sim().grid().geometry;
    GridInfo info;
    for (int d = 0; d < Dim; ++d) {
      info.origin.push_back(g.origin[d]);
      info.cell_size.push_back(g.h[d]);
      info.nodes.push_back(g.nodes[d]);
    }
    return info;
  }

  std::vector<std::string> grid_fields() const override {
    std::vector<std::string> names{"mass", "momentum", "force", "velocity", "updated_velocity"};
    for (const auto& [name, values] : sim().grid().node_fields)
      if (static_cast<Index>(values.size()) == sim().grid().size()) names.push_back(name);
    return names;
  }

  FieldArray grid_field(const std::string& name) override {
    // The grid is const outside the step; the view is read-only.
    auto& g = const_cast<Grid<Dim>&>(sim().grid());
    FieldArray a;
    auto member = [&](auto& records, auto& first_value) {
      using Value = std::remove_reference_t<decltype(first_value)>;
      a.storage.data = &first_value;
      a.storage.count = static_cast<Index>(records.size());
      a.storage.stride = sizeof(records[0]);
      a.storage.layout = array_layout<std::remove_const_t<Value>>();
    };
    if (name == "mass") {
      member(g.node, g.node[0].mass);
    } else if (name == "momentum") {
      member(g.node, g.node[0].momentum);
    } else if (name == "force") {
      member(g.node, g.node[0].force);
    } else if (name == "velocity") {
      member(g.velocity, g.velocity[0].mapped);
    } else if (name == "updated_velocity") {
      member(g.velocity, g.velocity[0].updated);
    } else if (auto it = g.node_fields.find(name); it != g.node_fields.end() && it->second.size() == g.node.size()) {
      a.storage = field_storage(it->second);
    } else {
      throw std::out_of_range("no grid field '" + name + "'");
    }
    std::vector<Index> shape, strides;
    Index stride = a.storage.stride;
    for (int d = 0; d < Dim; ++d) {
      shape.push_back(g.geometry.nodes[d]);
      strides.push_back(stride);
      stride *= g.geometry.nodes[d];
    }
    add_value_axes(a, shape, strides);
    return a;
  }

 private:
  Simulation<Dim>& sim() { return run_->simulation(); }
  const Simulation<Dim>& sim() const { return run_->simulation(); }

  tbb::task_arena arena_;
  StderrLog log_;
  std::unique_ptr<app::RunCheckpoints> checkpoints_;  ///< output.checkpoint, with an output directory
  std::unique_ptr<Run<Dim>> run_;                     ///< the simulation, its output and checks, as `mpm run`'s
};

}  // namespace

std::unique_ptr<SimulationHandle> make_simulation(const SceneDescription& scene, int threads,
                                                  const std::string& output_directory) {
  switch (scene.dimension) {
    case 1:
      return std::make_unique<SimulationFor<1>>(scene, threads, output_directory);
    case 2:
      return std::make_unique<SimulationFor<2>>(scene, threads, output_directory);
    default:
      return std::make_unique<SimulationFor<3>>(scene, threads, output_directory);
  }
}

}  // namespace mpm::python
