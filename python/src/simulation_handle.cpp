#include "simulation_handle.hpp"

#include <tbb/task_arena.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "mpm/app/run_description.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/history/history_writer.hpp"
#include "mpm/output_fields.hpp"
#include "mpm/output_writer.hpp"

namespace mpm::python {
namespace {

/// Thrown by run()'s step callback to leave Simulation::run() when the Python callback asks to stop.
struct StopRequested {};

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

template <int Dim>
class SimulationFor final : public SimulationHandle {
 public:
  SimulationFor(const SceneDescription& scene_in, int threads, const std::string& output_directory)
      : arena_(threads > 0 ? threads : tbb::task_arena::automatic), output_description_(scene_in.output) {
    SceneDescription scene = scene_in;  // modules writing their own files (contact forces) follow the directory
    if (!output_directory.empty()) scene.output.directory = output_directory;
    output_description_ = scene.output;
    field_data_ = app::run_field_data(scene, {});  // self-describing frames, as `mpm run` writes them
    view_script_ = app::view_script_for(scene);
    std::vector<BuiltHistory<Dim>> histories;
    arena_.execute([&] {
      sim_ = app::build_simulation<Dim>(scene);
      histories = build_histories<Dim>(scene, *sim_, history_warnings_);  // throws SceneError as the program
    });
    for (const auto& w : history_warnings_) std::cerr << "warning: " << w << '\n';  // as `mpm run` logs them
    if (!output_directory.empty()) {
      output_ = make_writer(output_directory);
      histories_ = std::make_unique<HistoryWriter<Dim>>(output_->directory(), std::move(histories));
      // the scheme's own per-step table (the implicit scheme's solver.csv), as `mpm run` writes it
      if (const std::string_view file = sim_->scheme().step_log_file(); !file.empty())
        step_log_ =
            std::make_unique<io::CsvLog>(output_->directory() / std::string(file), sim_->scheme().step_log_columns());
    }
    logged_step_ = sim_->step();
  }

  int dimension() const override { return Dim; }

  void step() override {
    stepping([&] {
      const bool was_finished = sim_->finished();
      sim_->advance(was_finished ? sim_->next_time_step() : sim_->time_step_toward(sim_->settings().end_time));
      after_step();
      if (!was_finished && sim_->finished()) write_final_frame();
    });
  }

  void advance_to(double t, const std::function<void()>& poll, double poll_seconds) override {
    Poller poller(poll, poll_seconds);
    stepping([&] {
      const bool was_finished = sim_->finished();
      while (!sim_->reached(t)) {
        sim_->advance(sim_->time_step_toward(t));
        after_step();
        poller.poll_if_due();
        apply_changes();
      }
      if (!was_finished && sim_->finished()) write_final_frame();
    });
  }

  bool run(const RunControl& control) override {
    bool stopped = false;
    Poller poller(control.poll, control.poll_seconds);
    stepping([&] {
      std::optional<Index> last_step;
      if (control.steps) last_step = sim_->step() + *control.steps;
      try {
        sim_->run(
            [&](const Simulation<Dim>& s) {
              after_step();
              if (control.callback && s.step() % control.every == 0 && control.callback()) throw StopRequested{};
              poller.poll_if_due();
              apply_changes();  // made by the callback through views, before the next step
            },
            last_step);
      } catch (const StopRequested&) {
        stopped = true;
        apply_changes();
      }
      write_final_frame();
    });
    if (control.poll) control.poll();
    return stopped;
  }

  double time() const override { return sim_->time(); }
  Index step_count() const override { return sim_->step(); }
  double dt() override {
    apply_changes();
    return sim_->finished() ? sim_->next_time_step() : sim_->time_step_toward(sim_->settings().end_time);
  }
  double end_time() const override { return sim_->settings().end_time; }
  bool finished() const override { return sim_->finished(); }
  double stable_time_step() override {
    apply_changes();
    return sim_->stable_time_step();
  }
  Index particle_count() const override { return sim_->particle_count(); }
  EnergyBalance energy() const override { return sim_->energy(); }

  void write_frame(const std::string& directory) override {
    apply_changes();
    // One writer per directory (its .pvd series and energy.csv), the scene's own output included.
    const std::string key = std::filesystem::weakly_canonical(directory).string();
    if (output_ && key == std::filesystem::weakly_canonical(output_->directory()).string()) {
      output_->write(*sim_);
      return;
    }
    auto& writer = frames_[key];
    if (!writer) writer = make_writer(directory);
    writer->write(*sim_);
  }
  std::string output_directory() const override { return output_ ? output_->directory().string() : std::string(); }

  std::vector<std::string> body_names() const override {
    std::vector<std::string> names;
    for (const auto& b : sim_->bodies()) names.push_back(b.name);
    return names;
  }
  Index body_size(int body) const override { return sim_->bodies().at(body).particles.size(); }

  std::vector<std::string> particle_fields(int body) override {
    std::vector<std::string> names = core_field_names;
    auto& p = sim_->bodies().at(body).particles;
    for (const auto& name : p.field_names())
      if (p.storage(name).layout.scalar != 0) names.push_back(name);
    return names;
  }

  FieldArray particle_field(int body, const std::string& name) override {
    auto& p = sim_->bodies().at(body).particles;
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

  std::uint64_t generation(int body) const override { return sim_->bodies().at(body).particles.generation(); }

  std::vector<double> output_values(int body, const std::string& name, int& components) const override {
    const OutputField* field = find_output_field(name);
    if (!field) throw std::out_of_range("no output field '" + name + "'");
    components = field->components;
    std::vector<double> values;
    append_output_field<Dim>(name, sim_->bodies().at(body), values);
    return values;
  }

  void mark_changed() override { changed_ = true; }

  GridInfo grid_info() const override {
    const auto& g = sim_->grid().geometry;
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
    for (const auto& [name, values] : sim_->grid().node_fields)
      if (static_cast<Index>(values.size()) == sim_->grid().size()) names.push_back(name);
    return names;
  }

  FieldArray grid_field(const std::string& name) override {
    // The grid is const outside the step; the view is read-only.
    auto& g = const_cast<Grid<Dim>&>(sim_->grid());
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
  std::unique_ptr<OutputWriter<Dim>> make_writer(const std::string& directory) const {
    const auto& o = output_description_;
    auto writer = std::make_unique<OutputWriter<Dim>>(directory, o.prefix, o.fields, o.grid, o.interval);
    writer->set_field_data(field_data_);
    io::write_view_script(writer->directory() / "view.py", view_script_);
    return writer;
  }
  void apply_changes() {
    if (!changed_) return;
    sim_->particles_changed();
    changed_ = false;
  }
  void after_step() {
    if (step_log_ && sim_->step() > logged_step_) step_log_->append(sim_->scheme().step_log_row());
    logged_step_ = sim_->step();
    if (output_) output_->write_if_due(*sim_);
    if (histories_) histories_->write_if_due(*sim_);
  }
  void write_final_frame() {
    if (output_) output_->write(*sim_);
    if (histories_) histories_->write(*sim_);
  }
  /// Runs `f` in the arena after applying the views' changes and writing the frames that are due; when the
  /// stability guard trips, writes the last good state (the simulation was rolled back) before rethrowing.
  template <class F>
  void stepping(F&& f) {
    arena_.execute([&] {
      apply_changes();
      after_step();
      try {
        f();
      } catch (const StabilityError&) {
        write_final_frame();
        throw;
      }
    });
  }

  tbb::task_arena arena_;
  OutputDescription output_description_;
  std::unique_ptr<Simulation<Dim>> sim_;
  std::unique_ptr<OutputWriter<Dim>> output_;                         ///< the scene's output section
  std::map<std::string, std::unique_ptr<OutputWriter<Dim>>> frames_;  ///< write_frame(), by directory
  std::unique_ptr<HistoryWriter<Dim>> histories_;                     ///< output.histories, beside output_
  std::vector<std::string> history_warnings_;
  std::unique_ptr<io::CsvLog> step_log_;  ///< the scheme's per-step table (solver.csv), one row per step
  Index logged_step_ = 0;                 ///< the last step with a row (after_step also runs before a step)
  io::FieldData field_data_;
  io::ViewScript view_script_;
  bool changed_ = false;
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
