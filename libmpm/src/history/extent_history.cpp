// `type: extent` (docs/scene-reference.md#histories): the smallest and largest coordinate of the particle
// centres along an axis and their difference (a front, a bar's length), or their smallest and largest distance
// from an axis line (a foot's radius), over one body or all, optionally only the particles inside a box.
#include <limits>

#include "history_support.hpp"
#include "mpm/io/csv_log.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace extent {

struct ExtentSpec {
  int body = -1;  ///< -1: all bodies
  int axis = 0;
  bool radial = false;                     ///< distance from the line through `through` along `axis`
  std::array<double, 3> through{0, 0, 0};  ///< m
  std::optional<Box> box;
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  ExtentSpec s;
  if (const auto body = entry.find("body")) s.body = read_body(reader, *body, scene);
  const auto axis = entry.find("axis"), radial = entry.find("radial");
  if (axis && radial) reader.fail(*radial, "give either axis (coordinates along it) or radial (distance from a line)");
  if (axis) {
    s.axis = read_axis(reader, *axis, scene.dimension);
  } else if (radial) {
    if (scene.dimension == 1) reader.fail(*radial, "a 1D run has no distance from an axis; use axis: x");
    const YamlMap line = reader.map(*radial);
    line.allow({"axis", "through"});
    s.radial = true;
    s.axis = read_axis(reader, line.required("axis"), scene.dimension);
    if (const auto through = line.find("through"))
      s.through = reader.vector(*through, scene.dimension, io::Range::any(), "m");
  } else {
    reader.fail(entry.self().mark, entry.self().path,
                "missing 'axis' (extent along x, y or z) or 'radial' (distance from a line: {axis, through})");
  }
  if (const auto box = entry.find("box")) s.box = read_box(reader, *box, scene);
  return s;
}

template <int Dim>
class ExtentHistory final : public History<Dim> {
 public:
  explicit ExtentHistory(const ExtentSpec& s) : s_(s) {}

  std::vector<std::string> columns() const override {
    if (s_.radial) return {column_name("radius_min", "m"), column_name("radius_max", "m"), column_name("count", "-")};
    const std::string name(1, "xyz"[s_.axis]);
    return {column_name(name + "_min", "m"), column_name(name + "_max", "m"), column_name(name + "_span", "m"),
            column_name("count", "-")};
  }

  void sample(const Simulation<Dim>& sim, OutputFieldCache<Dim>&, std::vector<double>& row) override {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    Index count = 0;
    for (int b = 0; b < static_cast<int>(sim.bodies().size()); ++b) {
      if (s_.body >= 0 && b != s_.body) continue;
      const auto& p = sim.bodies()[static_cast<std::size_t>(b)].particles;
      for (Index i = 0; i < p.size(); ++i) {
        if (s_.box && !s_.box->contains<Dim>(p.x[i])) continue;
        ++count;
        const double v = measure(p.x[i]);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    if (Communicator* comm = sim.communicator()) {  // every rank's particles
      double low[] = {lo}, high[] = {hi};
      std::int64_t n[] = {static_cast<std::int64_t>(count)};
      comm->min(low);
      comm->max(high);
      comm->sum(n);
      lo = low[0], hi = high[0], count = static_cast<Index>(n[0]);
    }
    row.push_back(count ? lo : io::no_data());  // no particle: no data (empty cells), not a 0 that reads as a length
    row.push_back(count ? hi : io::no_data());
    if (!s_.radial) row.push_back(count ? hi - lo : io::no_data());  // the length along the axis
    row.push_back(static_cast<double>(count));
  }

 private:
  double measure(const VecU<Dim>& x) const {
    if (!s_.radial) return x[s_.axis];
    double r2 = 0;
    for (int d = 0; d < Dim; ++d)
      if (d != s_.axis) r2 += (x[d] - s_.through[d]) * (x[d] - s_.through[d]);
    return std::sqrt(r2);
  }

  ExtentSpec s_;
};

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription&, Simulation<Dim>& sim,
                                   std::vector<std::string>& warnings) {
  auto history = std::make_unique<ExtentHistory<Dim>>(std::any_cast<const ExtentSpec&>(h.spec));
  OutputFieldCache<Dim> cache(sim);
  std::vector<double> row;
  history->sample(sim, cache, row);
  if (row.back() == 0)
    warnings.push_back(h.path + ": history '" + h.name +
                       "': no particle in its box at t = 0 (its rows have no data, empty cells, while count is 0)");
  return history;
}

}  // namespace extent
}  // namespace

HistoryKind extent_kind() {
  using namespace extent;
  return history_kind("extent",
                      "smallest and largest coordinate of the particles along an axis (a front, a length), or distance "
                      "from an axis line (a radius), of one body or all, optionally within a box",
                      {"body", "axis", "radial", "box"}, parse, make<1>, make<2>, make<3>);
}

}  // namespace mpm::history
