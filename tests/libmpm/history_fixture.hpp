#pragma once
// Histories (output.histories) of a simulation built from YAML text, sampled in the test instead of written.
#include <memory>
#include <string>
#include <vector>

#include "mpm/history/history_kind.hpp"
#include "scene_fixture.hpp"

namespace mpm::test {

template <int Dim>
struct Measured {
  SceneDescription scene;  ///< the histories point into it: kept at a fixed address (Measured is heap-held)
  std::unique_ptr<Simulation<Dim>> sim;
  std::vector<BuiltHistory<Dim>> histories;
  std::vector<std::string> warnings;

  /// The columns of history k, then its values now.
  std::vector<std::string> columns(std::size_t k) const { return histories[k].history->columns(); }
  std::vector<double> sample(std::size_t k) {
    OutputFieldCache<Dim> cache(*sim);
    std::vector<double> row;
    histories[k].history->sample(*sim, cache, row);
    return row;
  }
};

template <int Dim>
std::unique_ptr<Measured<Dim>> measured(const std::string& yaml) {
  app::register_modules();
  auto m = std::make_unique<Measured<Dim>>();
  m->scene = parse_scene(yaml, "test.yaml");
  m->sim = app::build_simulation<Dim>(m->scene);
  m->histories = build_histories<Dim>(m->scene, *m->sim, m->warnings);
  return m;
}

}  // namespace mpm::test
