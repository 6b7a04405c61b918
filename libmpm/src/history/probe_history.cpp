// `type: probe` (docs/scene-reference.md#histories): output fields (the one table of output_fields.hpp, so a
// module's fields are probe-able too) at a point, from the particles within a radius or from the grid, or
// statistics over the particles of a box or of whole bodies (mean, min, max, sum; where the min and max are).
// A probe that reads no particle writes no data (empty cells), never a 0 that reads like a measurement.
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "history_support.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/io/csv_log.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace probe {

enum class Where { particles, grid, region };
const std::vector<std::string> statistic_names{"mean", "min", "max", "sum", "min_at", "max_at"};
/// min_at, max_at: the particle holding the min (max): its body (when the probe reads several), id and position.
enum Statistic { stat_mean, stat_min, stat_max, stat_sum, stat_min_at, stat_max_at };

struct ProbeSpec {
  std::vector<std::string> fields;
  int body = -1;  ///< -1: every body that defines the fields
  int set = -1;   ///< a particle set (`set:`): only its particles; -1: every particle
  Where where = Where::particles;
  std::array<double, 3> point{0, 0, 0};
  double radius = 0;       ///< m (from: particles); 0: the largest cell size of the built grid (follows refinement)
  std::optional<Box> box;  ///< region: the particles inside it; none: every particle of the bodies
  std::vector<int> statistics;  ///< region: indices into statistic_names
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  ProbeSpec s;
  s.fields = read_point_fields(reader, entry.required("fields"));
  if (s.fields.empty()) reader.fail(entry.required("fields"), "list at least one field");
  if (const auto body = entry.find("body")) s.body = read_body(reader, *body, scene);
  const auto set = entry.find("set");
  if (set) s.set = read_set(reader, *set, scene);
  const auto point = entry.find("point"), box = entry.find("box"), from = entry.find("from"),
             radius = entry.find("radius"), statistics = entry.find("statistics");
  if (point && box) reader.fail(*box, "give either point or box, not both");
  if (point) {
    if (set) reader.fail(*set, "a point probe reads the particles near its point; set is for statistics over a set");
    s.point = read_point_in_grid(reader, *point, scene, "probe point");
    if (statistics)
      reader.fail(*statistics, "statistics are for a box or a whole body; a point probe gives one value per component");
    if (from && reader.choice(*from, {"particles", "grid"}) == "grid") {
      s.where = Where::grid;
      if (radius) reader.fail(*radius, "radius is for `from: particles`; `from: grid` uses the cell around the point");
    } else {
      if (radius) s.radius = reader.number(*radius, io::Range::above(0), "m");  // else the cell size, when built
    }
    return s;
  }
  // No point: statistics over the particles of a box, or over every particle of the bodies.
  s.where = Where::region;
  if (box) s.box = read_box(reader, *box, scene);
  const char* region = box ? "a box probe reads the particles inside the box"
                           : "a probe without point or box reads every particle of its bodies";
  if (from) reader.fail(*from, fmt::format("from is for a point probe; {}", region));
  if (radius) reader.fail(*radius, fmt::format("radius is for a point probe; {}", region));
  if (statistics) {
    for (const auto& item : reader.list(*statistics, std::nullopt, "statistics")) {
      const std::string name = reader.choice(item, statistic_names);
      const int k =
          static_cast<int>(std::find(statistic_names.begin(), statistic_names.end(), name) - statistic_names.begin());
      if (std::find(s.statistics.begin(), s.statistics.end(), k) != s.statistics.end())
        reader.fail(item, fmt::format("statistic '{}' is listed twice", name));
      s.statistics.push_back(k);
    }
    if (s.statistics.empty()) reader.fail(*statistics, "list at least one of mean, min, max, sum, min_at, max_at");
  } else {
    s.statistics = {stat_mean, stat_min, stat_max};
  }
  return s;
}

std::vector<std::string> fields_of(const std::any& spec) { return std::any_cast<const ProbeSpec&>(spec).fields; }

/// One column of values: field f, component c.
struct Component {
  const OutputField* field;
  int offset;
};

template <int Dim>
class ProbeHistory final : public History<Dim> {
 public:
  ProbeHistory(ProbeSpec spec, std::vector<const OutputField*> fields, std::vector<int> bodies,
               const GridGeometry<Dim>& grid)
      : s_(std::move(spec)), fields_(std::move(fields)), bodies_(std::move(bodies)), grid_(grid) {
    if (s_.where == Where::particles && !(s_.radius > 0)) s_.radius = grid_.h.maxCoeff();
    if (s_.set >= 0) set_mask_ = set_bit(s_.set);
    for (int d = 0; d < Dim; ++d) x0_[d] = s_.point[d];
    for (int a = 0; a < (1 << Dim); ++a)  // corner a of the point's cell: bit d set = the upper node on axis d
      for (int d = 0; d < Dim; ++d) {
        const int cells = grid_.nodes[d] - 1;
        const int base =
            std::clamp(static_cast<int>(std::floor((x0_[d] - grid_.origin[d]) * grid_.inv_h[d])), 0, cells - 1);
        corner_[a][d] = grid_.origin[d] + grid_.h[d] * (base + ((a >> d) & 1));
      }
    for (const OutputField* f : fields_)
      for (std::size_t c = 0; c < component_suffixes(*f, Dim).size(); ++c)
        components_.push_back({f, static_cast<int>(c)});
  }

  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    for (const OutputField* f : fields_)
      for (const auto& suffix : component_suffixes(*f, Dim)) {
        if (s_.where != Where::region) {
          names.push_back(column_name(f->name + suffix, f->unit));
          continue;
        }
        for (int k : s_.statistics) {
          const std::string name = fmt::format("{}{}_{}", f->name, suffix, statistic_names[k]);
          if (k != stat_min_at && k != stat_max_at) {
            names.push_back(column_name(name, f->unit));
            continue;
          }
          const std::string at = fmt::format("{}{}{}", f->name, suffix, k == stat_min_at ? "_min" : "_max");
          if (bodies_.size() > 1) names.push_back(column_name(at + "_body", "-"));
          names.push_back(column_name(at + "_id", "-"));
          for (int d = 0; d < Dim; ++d) names.push_back(column_name(at + "_" + "xyz"[d], "m"));
        }
      }
    names.push_back(column_name("count", "-"));
    return names;
  }

  void sample(const Simulation<Dim>& sim, OutputFieldCache<Dim>& cache, std::vector<double>& row) override {
    switch (s_.where) {
      case Where::particles:
        return fit_particles(sim, cache, row);
      case Where::grid:
        return from_grid(sim, cache, row);
      case Where::region:
        return over_region(sim, cache, row);
    }
  }

  /// Particles the probe reads now (for the warning at t = 0).
  Index particle_count(const Simulation<Dim>& sim) const {
    Index n = 0;
    for (int b : bodies_) {
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      for (Index i = 0; i < p.size(); ++i) n += reads(p.x[i]) && (set_mask_ == 0 || in_sets(p, i, set_mask_));
    }
    return n;
  }

 private:
  bool reads(const VecU<Dim>& x) const {
    if (s_.where == Where::region) return !s_.box || s_.box->contains<Dim>(x);
    if (s_.where == Where::particles) return (Vec<Dim>(x) - x0_).squaredNorm() < s_.radius * s_.radius;
    for (int a = 0; a < (1 << Dim); ++a)
      if (hat(a, x) > 0) return true;
    return false;
  }

  /// The value of a particle's component.
  const double* values(OutputFieldCache<Dim>& cache, const Component& c, int b) const {
    return cache.values(c.field->name, b).data() + c.offset;
  }

  /// Moving least squares: the weighted linear fit a + b.(x - x0) of the particles within the radius, with
  /// weights V_p (1 - r^2/R^2)^2; its value at the point is a. Exact for fields linear in x; the weighted mean
  /// where the particles do not span the space (fewer than Dim + 1, or on a line/plane). The moments are summed
  /// exactly, so they do not depend on the particles' order nor on the ranks holding them.
  void fit_particles(const Simulation<Dim>& sim, OutputFieldCache<Dim>& cache, std::vector<double>& row) const {
    using Basis = Eigen::Matrix<double, Dim + 1, 1>;
    using Moments = Eigen::Matrix<double, Dim + 1, Dim + 1>;
    constexpr int B = Dim + 1;
    constexpr std::size_t moments = static_cast<std::size_t>(B) * B, rows = B;  // where the right-hand sides start
    struct Near {
      int b;
      Index i;
      double w;
      Basis phi;
    };
    std::vector<Near> near;
    const Real R2 = s_.radius * s_.radius;
    for (int b : bodies_) {
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      const Real* hoop = axisym::hoop_stretch_of(p);  // V_p = V_p^0 det F F_tt in an axisymmetric run
      for (Index i = 0; i < p.size(); ++i) {
        const Vec<Dim> d = Vec<Dim>(p.x[i]) - x0_;
        const Real r2 = d.squaredNorm();
        if (!(r2 < R2)) continue;
        const Real q = 1 - r2 / R2;
        Basis phi;
        phi[0] = 1;
        phi.template tail<Dim>() = d / s_.radius;
        near.push_back({b, i, p.volume0[i] * axisym::volume_ratio(p, i, hoop) * q * q, phi});
      }
    }
    // sums: the moments M (B x B), then each component's right-hand side (B)
    std::vector<ExactSum> sums(moments + rows * components_.size());
    for (const Near& n : near)
      for (int r = 0; r < B; ++r)
        for (int c = 0; c < B; ++c)
          sums[rows * static_cast<std::size_t>(r) + static_cast<std::size_t>(c)] += n.w * n.phi[r] * n.phi[c];
    for (std::size_t k = 0; k < components_.size(); ++k) {
      const Component& c = components_[k];
      for (const Near& n : near) {
        const double v = values(cache, c, n.b)[n.i * c.field->components];
        for (int r = 0; r < B; ++r) sums[moments + rows * k + static_cast<std::size_t>(r)] += n.w * v * n.phi[r];
      }
    }
    std::int64_t count[] = {static_cast<std::int64_t>(near.size())};
    if (Communicator* comm = sim.communicator()) {  // every rank's particles
      comm->sum(sums);
      comm->sum(count);
    }
    Moments M;
    for (int r = 0; r < B; ++r)
      for (int c = 0; c < B; ++c)
        M(r, c) = sums[rows * static_cast<std::size_t>(r) + static_cast<std::size_t>(c)].value();
    bool linear = count[0] >= Dim + 1 && M(0, 0) > 0;
    Eigen::LDLT<Moments> solver;
    if (linear) {
      const Eigen::SelfAdjointEigenSolver<Moments> eigen(M / M(0, 0), Eigen::EigenvaluesOnly);
      linear = eigen.eigenvalues().minCoeff() > 1e-8 * eigen.eigenvalues().maxCoeff();
      if (linear) solver.compute(M);
    }
    for (std::size_t k = 0; k < components_.size(); ++k) {
      Basis rhs;
      for (int r = 0; r < B; ++r) rhs[r] = sums[moments + rows * k + static_cast<std::size_t>(r)].value();
      if (count[0] == 0 || !(M(0, 0) > 0))
        row.push_back(io::no_data());
      else
        row.push_back(linear ? Basis(solver.solve(rhs))[0] : rhs[0] / M(0, 0));
    }
    row.push_back(static_cast<double>(count[0]));
  }

  /// The linear hat of corner a of the point's cell at x (review eq. 3.1).
  Real hat(int a, const VecU<Dim>& x) const {
    Real w = 1;
    for (int d = 0; d < Dim; ++d) w *= std::max<Real>(0, 1 - std::abs(x[d] - corner_[a][d]) * grid_.inv_h[d]);
    return w;
  }

  /// The particles' values projected on the corners of the point's cell with the linear hat, mass-weighted
  /// (what P2G does with momentum), then interpolated at the point from the corners that have mass.
  void from_grid(const Simulation<Dim>& sim, OutputFieldCache<Dim>& cache, std::vector<double>& row) const {
    constexpr int corners = 1 << Dim;
    std::array<ExactSum, corners> mass;
    std::vector<std::array<ExactSum, corners>> value(components_.size());
    Index count = 0;
    std::array<Real, corners> w{};
    std::vector<const double*> column(components_.size());
    for (int b : bodies_) {
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      for (std::size_t k = 0; k < components_.size(); ++k) column[k] = values(cache, components_[k], b);
      for (Index i = 0; i < p.size(); ++i) {
        bool touches = false;
        for (int a = 0; a < corners; ++a) touches = (w[a] = hat(a, p.x[i])) > 0 || touches;
        if (!touches) continue;
        ++count;
        for (int a = 0; a < corners; ++a) {
          mass[a] += w[a] * p.mass[i];
          for (std::size_t k = 0; k < components_.size(); ++k)
            value[k][a] += w[a] * p.mass[i] * column[k][i * components_[k].field->components];
        }
      }
    }
    if (Communicator* comm = sim.communicator()) {  // every rank's particles
      std::vector<ExactSum> all(mass.begin(), mass.end());
      for (const auto& v : value) all.insert(all.end(), v.begin(), v.end());
      comm->sum(all);
      std::copy(all.begin(), all.begin() + corners, mass.begin());
      for (std::size_t k = 0; k < value.size(); ++k)
        std::copy(all.begin() + corners * (1 + static_cast<std::ptrdiff_t>(k)),
                  all.begin() + corners * (2 + static_cast<std::ptrdiff_t>(k)), value[k].begin());
      std::int64_t n[] = {static_cast<std::int64_t>(count)};
      comm->sum(n);
      count = static_cast<Index>(n[0]);
    }
    std::array<Real, corners> m{}, N{};
    Real weight = 0;
    for (int a = 0; a < corners; ++a) {
      m[a] = mass[a].value();
      N[a] = m[a] > 0 ? hat(a, VecU<Dim>(x0_)) : 0;
      weight += N[a];
    }
    for (std::size_t k = 0; k < components_.size(); ++k) {
      Real v = 0;
      for (int a = 0; a < corners; ++a)
        if (N[a] > 0) v += N[a] * value[k][a].value() / m[a];
      row.push_back(weight > 0 ? v / weight : io::no_data());
    }
    row.push_back(static_cast<double>(count));
  }

  /// Where the least or greatest value of a component lies: the particle (its body and id as one key,
  /// body * 2^32 + id, exact in a double) and its position. Ties go to the smaller key, so the particle named
  /// does not depend on the order the particles are stored in, nor on the ranks holding them.
  struct Extreme {
    double value;
    double key = std::numeric_limits<double>::infinity();
    std::array<double, 3> x{0, 0, 0};
  };
  static double particle_key(int body, std::uint32_t id) { return std::ldexp(static_cast<double>(body), 32) + id; }

  bool wants(Statistic stat) const {
    return std::find(s_.statistics.begin(), s_.statistics.end(), stat) != s_.statistics.end();
  }

  /// The global extreme from every rank's own: the value (min or max), then the smallest key among the ranks
  /// that hold it, then that particle's position (the other ranks give -inf to a max).
  static void reduce(Communicator& comm, std::vector<Extreme>& e, bool least, bool locate) {
    std::vector<double> v(e.size());
    for (std::size_t k = 0; k < e.size(); ++k) v[k] = e[k].value;
    if (least)
      comm.min(v);
    else
      comm.max(v);
    if (!locate) {
      for (std::size_t k = 0; k < e.size(); ++k) e[k].value = v[k];
      return;
    }
    std::vector<double> key(e.size());
    for (std::size_t k = 0; k < e.size(); ++k)
      key[k] = e[k].value == v[k] ? e[k].key : std::numeric_limits<double>::infinity();
    comm.min(key);
    std::vector<double> x(3 * e.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < e.size(); ++k)
      if (e[k].key == key[k] && e[k].value == v[k])
        std::copy(e[k].x.begin(), e[k].x.end(), x.begin() + 3 * static_cast<std::ptrdiff_t>(k));
    comm.max(x);
    for (std::size_t k = 0; k < e.size(); ++k) {
      e[k].value = v[k];
      e[k].key = key[k];
      std::copy(x.begin() + 3 * static_cast<std::ptrdiff_t>(k), x.begin() + 3 * static_cast<std::ptrdiff_t>(k + 1),
                e[k].x.begin());
    }
  }

  /// The columns of min_at or max_at: the body (when the probe reads several), the id and the position.
  void push_location(const Extreme& e, std::vector<double>& row) const {
    const double key = e.key;
    if (bodies_.size() > 1) row.push_back(std::floor(std::ldexp(key, -32)));
    row.push_back(key - std::ldexp(std::floor(std::ldexp(key, -32)), 32));
    for (int d = 0; d < Dim; ++d) row.push_back(e.x[static_cast<std::size_t>(d)]);
  }
  std::size_t location_columns() const { return (bodies_.size() > 1 ? 2 : 1) + Dim; }

  /// Volume-weighted mean (current volumes), min, max and sum over the particles in the box (or of the whole
  /// bodies), summed exactly, and where the min and max lie.
  void over_region(const Simulation<Dim>& sim, OutputFieldCache<Dim>& cache, std::vector<double>& row) const {
    const std::size_t n = components_.size();
    std::vector<ExactSum> weighted(n), sum(n);
    std::vector<Extreme> lo(n, Extreme{std::numeric_limits<double>::infinity()}),
        hi(n, Extreme{-std::numeric_limits<double>::infinity()});
    ExactSum volume;
    Index count = 0;
    std::vector<const double*> column(n);
    for (int b : bodies_) {
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      for (std::size_t k = 0; k < n; ++k) column[k] = values(cache, components_[k], b);
      const Real* hoop = axisym::hoop_stretch_of(p);  // the ring volumes of an axisymmetric run
      const std::uint32_t* sets = set_mask_ != 0 ? p.field(keys::particle_sets).data() : nullptr;
      for (Index i = 0; i < p.size(); ++i) {
        if (s_.box && !s_.box->contains<Dim>(p.x[i])) continue;
        if (set_mask_ != 0 && (sets[static_cast<std::size_t>(i)] & set_mask_) == 0) continue;
        ++count;
        const Real V = p.volume0[i] * axisym::volume_ratio(p, i, hoop);
        volume += V;
        const double key = particle_key(b, p.id[i]);
        for (std::size_t k = 0; k < n; ++k) {
          const double v = column[k][i * components_[k].field->components];
          weighted[k] += V * v;
          sum[k] += v;
          if (v < lo[k].value || (v == lo[k].value && key < lo[k].key)) lo[k] = {v, key, position(p.x[i])};
          if (v > hi[k].value || (v == hi[k].value && key < hi[k].key)) hi[k] = {v, key, position(p.x[i])};
        }
      }
    }
    if (Communicator* comm = sim.communicator()) {  // every rank's particles
      std::vector<ExactSum> all{volume};
      all.insert(all.end(), weighted.begin(), weighted.end());
      all.insert(all.end(), sum.begin(), sum.end());
      comm->sum(all);
      volume = all[0];
      std::copy(all.begin() + 1, all.begin() + 1 + static_cast<std::ptrdiff_t>(n), weighted.begin());
      std::copy(all.begin() + 1 + static_cast<std::ptrdiff_t>(n), all.end(), sum.begin());
      reduce(*comm, lo, true, wants(stat_min_at));
      reduce(*comm, hi, false, wants(stat_max_at));
      std::int64_t c[] = {static_cast<std::int64_t>(count)};
      comm->sum(c);
      count = static_cast<Index>(c[0]);
    }
    const Real V = volume.value();
    for (std::size_t k = 0; k < n; ++k)
      for (int stat : s_.statistics) {
        if (count == 0) {  // no particle: no data
          row.insert(row.end(), stat == stat_min_at || stat == stat_max_at ? location_columns() : 1, io::no_data());
          continue;
        }
        switch (stat) {
          case stat_mean:
            row.push_back(V > 0 ? weighted[k].value() / V : io::no_data());
            break;
          case stat_min:
            row.push_back(lo[k].value);
            break;
          case stat_max:
            row.push_back(hi[k].value);
            break;
          case stat_min_at:
            push_location(lo[k], row);
            break;
          case stat_max_at:
            push_location(hi[k], row);
            break;
          default:
            row.push_back(sum[k].value());
        }
      }
    row.push_back(static_cast<double>(count));
  }

  static std::array<double, 3> position(const VecU<Dim>& x) {
    std::array<double, 3> a{0, 0, 0};
    for (int d = 0; d < Dim; ++d) a[static_cast<std::size_t>(d)] = x[d];
    return a;
  }

  ProbeSpec s_;
  std::vector<const OutputField*> fields_;
  std::vector<int> bodies_;
  GridGeometry<Dim> grid_;
  Vec<Dim> x0_ = Vec<Dim>::Zero();
  std::array<VecU<Dim>, (1 << Dim)> corner_{};
  std::vector<Component> components_;
  std::uint32_t set_mask_ = 0;  ///< the particle set's bit, 0: every particle
};

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription& scene, Simulation<Dim>& sim,
                                   std::vector<std::string>& warnings) {
  const auto& s = std::any_cast<const ProbeSpec&>(h.spec);
  std::vector<const OutputField*> fields;
  for (const auto& name : s.fields) fields.push_back(find_output_field(name));
  std::vector<int> bodies = bodies_defining<Dim>(h, fields, s.body, sim.bodies());
  if (s.set >= 0 && !scene.sets[static_cast<std::size_t>(s.set)].bodies.empty()) {  // only the set's bodies
    const auto& of_set = scene.sets[static_cast<std::size_t>(s.set)].bodies;
    std::erase_if(bodies, [&](int b) { return std::find(of_set.begin(), of_set.end(), b) == of_set.end(); });
    if (bodies.empty())
      fail(h, "set",
           fmt::format("set '{}' has no particle in a body that defines the fields",
                       scene.sets[static_cast<std::size_t>(s.set)].name));
  }
  auto probe = std::make_unique<ProbeHistory<Dim>>(s, std::move(fields), std::move(bodies), sim.grid().geometry);
  if (probe->particle_count(sim) == 0)
    warnings.push_back(
        fmt::format("{}: history '{}': no particle in the probe's region at t = 0 (its rows have no "
                    "data, empty cells, while count is 0)",
                    h.path, h.name));
  return probe;
}

}  // namespace probe
}  // namespace

HistoryKind probe_kind() {
  using namespace probe;
  return history_kind("probe",
                      "output fields at a point (from the particles within a radius, or from the grid) or over the "
                      "particles of a box, a body or a particle set (mean, min, max, sum, where the min and max are)",
                      {"fields", "body", "set", "point", "from", "radius", "box", "statistics"}, parse, make<1>,
                      make<2>, make<3>, fields_of);
}

}  // namespace mpm::history
