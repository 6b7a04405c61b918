// `type: particle` (docs/scene-reference.md#histories): a material-point history, LS-DYNA's
// *DATABASE_HISTORY_NODE for particles: the position and output fields of particles followed by id, or of the
// particle nearest to a point at t = 0, wherever they go. A spatial probe loses a point of a body that moves by
// more than its radius; this one does not. A particle that has left the run (eroded, out through an outflow
// face) writes no data (empty cells).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "history_support.hpp"
#include "mpm/io/csv_log.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace followed {

struct ParticleSpec {
  std::vector<std::string> fields;
  int body = 0;
  std::vector<std::uint32_t> ids;                ///< given ids, or empty with `nearest`
  std::optional<std::array<double, 3>> nearest;  ///< m: the particle nearest to it at t = 0
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  ParticleSpec s;
  if (const auto fields = entry.find("fields")) s.fields = read_point_fields(reader, *fields);
  if (const auto body = entry.find("body"))
    s.body = read_body(reader, *body, scene);
  else if (scene.bodies.size() > 1)
    reader.fail(entry.self().mark, entry.self().path,
                fmt::format("missing 'body': the scene has {} bodies and particle ids are counted per body",
                            scene.bodies.size()));
  const auto ids = entry.find("ids"), nearest = entry.find("nearest");
  if (ids && nearest) reader.fail(*nearest, "give either ids or nearest, not both");
  if (nearest) {
    s.nearest = read_point_in_grid(reader, *nearest, scene, "point");
  } else if (ids) {
    for (const auto& item : reader.list(*ids, std::nullopt, "particle ids")) {
      const auto id = static_cast<std::uint32_t>(reader.integer(item, 0));
      if (std::find(s.ids.begin(), s.ids.end(), id) != s.ids.end())
        reader.fail(item, fmt::format("id {} is listed twice", id));
      s.ids.push_back(id);
    }
    if (s.ids.empty()) reader.fail(*ids, "list at least one particle id");
  } else {
    reader.fail(entry.self().mark, entry.self().path,
                "missing 'ids' (particles by their id, the `id` field of the frames) or 'nearest' (the particle "
                "nearest to a point at t = 0)");
  }
  return s;
}

std::vector<std::string> fields_of(const std::any& spec) { return std::any_cast<const ParticleSpec&>(spec).fields; }

template <int Dim>
class ParticleHistory final : public History<Dim> {
 public:
  ParticleHistory(const ParticleSpec& spec, std::vector<const OutputField*> fields)
      : s_(spec), fields_(std::move(fields)) {}

  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    const bool one = s_.ids.size() == 1;
    if (one) names.push_back(column_name("id", "-"));
    for (const std::uint32_t id : s_.ids) {
      const std::string prefix = one ? "" : fmt::format("p{}_", id);
      for (int d = 0; d < Dim; ++d) names.push_back(column_name(prefix + "xyz"[d], "m"));
      for (const OutputField* f : fields_)
        for (const auto& suffix : component_suffixes(*f, Dim))
          names.push_back(column_name(fmt::format("{}{}{}", prefix, f->name, suffix), f->unit));
    }
    return names;
  }

  void sample(const Simulation<Dim>& sim, OutputFieldCache<Dim>& cache, std::vector<double>& row) override {
    const auto& p = sim.bodies()[static_cast<std::size_t>(s_.body)].particles;
    find(p);
    const std::size_t per = static_cast<std::size_t>(Dim) + components();
    // -inf where this rank does not hold the particle: the max over the ranks is the holder's value, bit for
    // bit, and -inf everywhere means it has left the run.
    std::vector<double> values(per * s_.ids.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < s_.ids.size(); ++k) {
      const Index i = where_[k];
      if (i < 0) continue;
      double* out = values.data() + per * k;
      for (int d = 0; d < Dim; ++d) *out++ = p.x[i][d];
      for (const OutputField* f : fields_) {
        const double* v = cache.values(f->name, s_.body).data() + i * f->components;
        for (std::size_t c = 0; c < component_suffixes(*f, Dim).size(); ++c) *out++ = v[c];
      }
    }
    if (Communicator* comm = sim.communicator()) comm->max(values);
    if (s_.ids.size() == 1) row.push_back(s_.ids[0]);
    for (const double v : values) row.push_back(v == -std::numeric_limits<double>::infinity() ? io::no_data() : v);
  }

  /// The followed ids (found at t = 0 for `nearest`), so that a restart follows the same particles.
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put_values<std::uint32_t>(prefix + "ids", std::span<const std::uint32_t>(s_.ids));
  }
  void restore_state(const StateArchive& archive, const std::string& prefix) override {
    s_.ids = archive.values<std::uint32_t>(prefix + "ids");
    where_.clear();
  }

  /// Chooses the particle nearest to the point (ties: the smaller id, the same on any number of ranks).
  void choose_nearest(const Simulation<Dim>& sim) {
    const auto& p = sim.bodies()[static_cast<std::size_t>(s_.body)].particles;
    double best[] = {std::numeric_limits<double>::infinity()};
    double key[] = {std::numeric_limits<double>::infinity()};
    for (Index i = 0; i < p.size(); ++i) {
      double r2 = 0;
      for (int d = 0; d < Dim; ++d) r2 += (p.x[i][d] - (*s_.nearest)[d]) * (p.x[i][d] - (*s_.nearest)[d]);
      if (r2 < best[0] || (r2 == best[0] && p.id[i] < key[0])) best[0] = r2, key[0] = p.id[i];
    }
    if (Communicator* comm = sim.communicator()) {
      const double mine = best[0];
      comm->min(best);
      if (mine != best[0]) key[0] = std::numeric_limits<double>::infinity();
      comm->min(key);
    }
    if (std::isfinite(key[0])) s_.ids = {static_cast<std::uint32_t>(key[0])};
    distance_ = std::sqrt(best[0]);
  }

  /// How many of the ids a particle of the body has now (on every rank).
  std::int64_t found(const Simulation<Dim>& sim) {
    find(sim.bodies()[static_cast<std::size_t>(s_.body)].particles);
    std::int64_t n[] = {
        static_cast<std::int64_t>(std::count_if(where_.begin(), where_.end(), [](Index i) { return i >= 0; }))};
    if (Communicator* comm = sim.communicator()) comm->sum(n);
    return n[0];
  }

  const ParticleSpec& spec() const { return s_; }
  double distance() const { return distance_; }

 private:
  std::size_t components() const {
    std::size_t n = 0;
    for (const OutputField* f : fields_) n += component_suffixes(*f, Dim).size();
    return n;
  }

  /// where_[k]: the index of the particle with id ids[k] on this rank, or -1. The particles are reordered
  /// (sorting, migration, erosion): the last index is checked and the body searched again only when it moved.
  void find(const ParticleSet<Dim>& p) {
    where_.resize(s_.ids.size(), -1);
    bool stale = false;
    for (std::size_t k = 0; k < s_.ids.size(); ++k)
      stale = stale || where_[k] < 0 || where_[k] >= p.size() || p.id[where_[k]] != s_.ids[k];
    if (!stale) return;
    std::fill(where_.begin(), where_.end(), -1);
    for (Index i = 0; i < p.size(); ++i)
      for (std::size_t k = 0; k < s_.ids.size(); ++k)
        if (p.id[i] == s_.ids[k]) where_[k] = i;
  }

  ParticleSpec s_;
  std::vector<const OutputField*> fields_;
  std::vector<Index> where_;
  double distance_ = 0;
};

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription& scene, Simulation<Dim>& sim,
                                   std::vector<std::string>&) {
  const auto& s = std::any_cast<const ParticleSpec&>(h.spec);
  std::vector<const OutputField*> fields;
  for (const auto& name : s.fields) fields.push_back(find_output_field(name));
  if (!fields.empty()) bodies_defining<Dim>(h, fields, s.body, sim.bodies());  // each field defined on the body
  auto history = std::make_unique<ParticleHistory<Dim>>(s, std::move(fields));
  const std::string& body = scene.bodies[static_cast<std::size_t>(s.body)].name;
  if (s.nearest) {
    history->choose_nearest(sim);
    if (history->spec().ids.empty()) fail(h, "nearest", fmt::format("body '{}' has no particle", body));
    return history;
  }
  if (history->found(sim) != static_cast<std::int64_t>(s.ids.size())) {
    Index count = sim.bodies()[static_cast<std::size_t>(s.body)].particles.size();
    std::int64_t n[] = {static_cast<std::int64_t>(count)};
    if (Communicator* comm = sim.communicator()) comm->sum(n);
    std::uint32_t missing = 0;
    for (const std::uint32_t id : s.ids)
      if (id >= n[0]) missing = id;
    fail(h, "ids",
         fmt::format("body '{}' has no particle with id {}: its ids run from 0 to {} (the `id` field of the frames)",
                     body, missing, n[0] - 1));
  }
  return history;
}

}  // namespace followed
}  // namespace

HistoryKind particle_kind() {
  using namespace followed;
  return history_kind("particle",
                      "position and output fields of particles followed by id, or of the particle nearest to a point "
                      "at t = 0, wherever they go (a material-point history)",
                      {"fields", "body", "ids", "nearest"}, parse, make<1>, make<2>, make<3>, fields_of);
}

}  // namespace mpm::history
