#include "mpm/app/plausibility.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "mpm/app/key_location.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"

namespace mpm::app {
namespace {

// Rule 1: densities, kg/m^3.
/// The densest element, osmium: 22,590 kg/m^3 (CRC Handbook); no solid or liquid is denser.
constexpr double densest_matter = 25e3;
/// Below this a solid is a foam, snow, balsa or aerogel, or a density in g/cm^3 (0.9-22.6 for solids).
constexpr double lightest_dense_solid = 500;
/// The fastest dilatational wave in any solid, diamond's: about 1.8e4 m/s. A light solid whose waves run faster
/// has a density out of scale with its moduli.
constexpr double fastest_solid_wave = 2e4;
/// Liquids: liquefied gases aside, from about 600 (petrol, LNG 450) to mercury's 13,534 and molten metals'.
constexpr double lightest_liquid = 500;
/// Gases: air at 1 % of an atmosphere (about 31 km up) to air at about 85 bar, beyond which an ideal gas misstates
/// the pressure by more than a few per cent.
constexpr double lightest_gas = 0.01, densest_gas = 100;

// Rule 2.
/// Soft clays have a Young's modulus of about 1e6 Pa, polymers 1e8-1e10, metals 1e10-4.1e11 (tungsten); a modulus
/// in MPa or GPa written as Pa gives at most 4.1e5.
constexpr double softest_plastic_solid = 1e6;
/// Diamond's Young's modulus, about 1.2e12 Pa: none is stiffer.
constexpr double stiffest_solid = 1.2e12;

// Rule 3.
/// Particles closer than this fraction of the particle spacing belong to bodies that overlap.
constexpr double overlap_fraction = 0.5;
/// A tangency brings a few particles that close; an overlap of even one row of particles brings at least 1 % of the
/// body's.
constexpr std::size_t overlap_least_count = 10;
constexpr double overlap_least_share = 0.01;

// Rule 4.
/// A run shorter than the time a wave takes to cross this share of the body (and one cell) shows no wave at all.
constexpr double least_transit_share = 0.01;
/// A run longer than this many crossings of every body is millions of steps (crossings x cells across / CFL).
constexpr double most_transits = 1e5;

/// A unit a density was probably written in, and its size in kg/m^3.
struct Slip {
  const char* unit;
  double factor;
};
constexpr std::array density_slips{Slip{"g/cm^3", 1e3}, Slip{"t/mm^3", 1e12}, Slip{"g/mm^3", 1e6}, Slip{"g/m^3", 1e-3}};

/// ": g/cm^3? (7830 kg/m^3: write `7.83 g/cm^3`)" for the first slip that brings `value` into [low, high], or "".
std::string density_slip(double value, double low, double high) {
  for (const Slip& s : density_slips)
    if (const double si = value * s.factor; si >= low && si <= high)
      return fmt::format(": {}? ({:.6g} kg/m^3: write `{} {}`)", s.unit, si, value, s.unit);
  return "";
}

template <int Dim>
Real spacing(const SceneDescription& scene, const Simulation<Dim>& sim, int body, int axis) {
  return sim.grid().geometry.h[axis] / scene.bodies[static_cast<std::size_t>(body)].particles_per_cell[axis];
}

/// The smallest particle spacing of a body, h / particles_per_cell over the axes.
template <int Dim>
Real spacing(const SceneDescription& scene, const Simulation<Dim>& sim, int body) {
  Real s = std::numeric_limits<Real>::infinity();
  for (int d = 0; d < Dim; ++d) s = std::min(s, spacing(scene, sim, body, d));
  return s;
}

/// The dilatational wave speed of a body's material at t = 0 (uniform then): the CFL bound's c + |v| less |v|.
template <int Dim>
Real wave_speed_at_rest(const Body<Dim>& body) {
  if (body.particles.size() == 0) return 0;
  const auto bound = body.material->wave_speed_bound(body.particles);
  Vec<Dim> v = Vec<Dim>::Zero();
  for (const auto& vp : body.particles.v) v = v.cwiseMax(Vec<Dim>(vp.cwiseAbs()));
  Real c = 0;
  for (int d = 0; d < Dim; ++d) c = std::max(c, bound.max_speed[d] - v[d]);
  return c;
}

template <int Dim>
struct Bounds {
  Vec<Dim> lo = Vec<Dim>::Constant(std::numeric_limits<Real>::infinity());
  Vec<Dim> hi = Vec<Dim>::Constant(-std::numeric_limits<Real>::infinity());

  bool contains(const Vec<Dim>& x) const { return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all(); }
  bool empty() const { return (hi.array() < lo.array()).any(); }
};

template <int Dim>
Bounds<Dim> bounds_of(const ParticleSet<Dim>& p) {
  Bounds<Dim> b;
  for (const auto& x : p.x) {
    b.lo = b.lo.cwiseMin(Vec<Dim>(x));
    b.hi = b.hi.cwiseMax(Vec<Dim>(x));
  }
  return b;
}

/// The material's Young's modulus: given, or from the bulk and shear moduli E = 9 K G / (3 K + G); nothing without.
std::optional<double> youngs_modulus(const MaterialDescription& m) {
  const auto& p = m.parameters;
  if (const auto e = p.find("youngs_modulus"); e != p.end()) return e->second;
  const auto k = p.find("bulk_modulus"), g = p.find("shear_modulus");
  if (k != p.end() && g != p.end()) return 9 * k->second * g->second / (3 * k->second + g->second);
  return std::nullopt;
}

/// The key that gives a material's stiffness: youngs_modulus, else shear_modulus.
std::string modulus_key(const MaterialDescription& m) {
  return m.parameters.count("youngs_modulus") ? "youngs_modulus" : "shear_modulus";
}

/// A material's warning at its key `key`.
std::string material_warning(const SceneDescription& scene, const std::string& name, const std::string& key,
                             const std::string& message) {
  return SceneError::format(locate_key(scene, {"materials", name, key}), fmt::format("materials.{}.{}", name, key),
                            message);
}

/// The cells of side `r` a particle set's points fall in, sorted, for neighbour look-ups (rule 3).
template <int Dim>
class CellIndex {
 public:
  using Cell = std::array<std::int64_t, Dim>;

  CellIndex(const ParticleSet<Dim>& p, const Bounds<Dim>& region, Real r) : p_(p), origin_(region.lo), r_(r) {
    for (Index i = 0; i < p.size(); ++i)
      if (region.contains(p.x[i])) entries_.push_back({cell(p.x[i]), i});
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.cell < b.cell; });
  }

  /// Whether a point of the set lies closer than r to `x`.
  bool has_point_near(const Vec<Dim>& x) const {
    const Cell home = cell(x);
    std::array<int, Dim> offset;
    offset.fill(-1);
    for (;;) {
      Cell c = home;
      for (int d = 0; d < Dim; ++d) c[d] += offset[d];
      const auto [first, last] = std::equal_range(entries_.begin(), entries_.end(), Entry{c, 0},
                                                  [](const Entry& a, const Entry& b) { return a.cell < b.cell; });
      for (auto it = first; it != last; ++it)
        if ((Vec<Dim>(p_.x[it->index]) - x).squaredNorm() < r_ * r_) return true;
      int d = 0;  // the next of the 3^Dim neighbouring cells
      while (d < Dim && offset[d] == 1) offset[d++] = -1;
      if (d == Dim) return false;
      ++offset[d];
    }
  }

 private:
  struct Entry {
    Cell cell;
    Index index;
  };

  Cell cell(const Vec<Dim>& x) const {
    Cell c;
    for (int d = 0; d < Dim; ++d) c[d] = static_cast<std::int64_t>(std::floor((x[d] - origin_[d]) / r_));
    return c;
  }

  const ParticleSet<Dim>& p_;
  Vec<Dim> origin_;
  Real r_;
  std::vector<Entry> entries_;
};

}  // namespace

template <int Dim>
void check_density(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings) {
  for (const auto& [name, material] : scene.materials) {
    const MaterialModel* model = find_material_model(material.model);
    const auto density = material.parameters.find("density");
    if (!model || density == material.parameters.end()) continue;
    const double rho = density->second;
    std::string message;
    switch (model->phase) {
      case MaterialPhase::solid:
        if (rho > densest_matter) {
          message = fmt::format("density {} kg/m^3 is above any solid's (the densest, osmium, has 22,590 kg/m^3){}",
                                rho, density_slip(rho, lightest_dense_solid, densest_matter));
        } else if (rho < lightest_dense_solid) {
          Real c = 0;  // its bodies' wave speed at rest
          for (const auto& b : sim.bodies())
            if (scene.bodies[static_cast<std::size_t>(b.index)].material == name)
              c = std::max(c, wave_speed_at_rest(b));
          if (c > fastest_solid_wave)
            message = fmt::format(
                "density {} kg/m^3 is far below any solid's: with its moduli its waves would run at {:.3g} m/s, "
                "faster than in any solid (diamond: about 1.8e4 m/s){}",
                rho, c, density_slip(rho, lightest_dense_solid, densest_matter));
        }
        break;
      case MaterialPhase::liquid:
        if (rho < lightest_liquid || rho > densest_matter)
          message = fmt::format(
              "density {} kg/m^3 is outside any liquid's (500 to 25,000 kg/m^3: water 1000, "
              "mercury 13,534){}",
              rho, density_slip(rho, lightest_liquid, densest_matter));
        break;
      case MaterialPhase::gas:
        if (rho < lightest_gas || rho > densest_gas)
          message = fmt::format(
              "density {} kg/m^3 is outside what a gas has at ordinary pressures (0.01 to 100 "
              "kg/m^3: air at 1 atm and 20 C has 1.2){}",
              rho, density_slip(rho, lightest_gas, densest_gas));
        break;
      case MaterialPhase::rigid:  // its density only gives its particles a mass
        break;
    }
    if (!message.empty()) warnings.push_back(material_warning(scene, name, "density", message));
  }
}

void check_yield_stress(const SceneDescription& scene, std::vector<std::string>& warnings) {
  for (const auto& [name, material] : scene.materials) {
    const auto yield = material.parameters.find("yield_stress");
    const auto E = youngs_modulus(material);
    if (yield == material.parameters.end() || !(yield->second > 0) || !E) continue;
    const double sy = yield->second;
    const std::string key = modulus_key(material);
    const std::string modulus =
        key == "youngs_modulus"
            ? fmt::format("the Young's modulus ({:.6g} Pa)", *E)
            : fmt::format("the Young's modulus 9KG/(3K+G) of its bulk and shear moduli ({:.4g} Pa)", *E);
    if (sy >= *E) {
      // The unit the modulus was probably written in: one that gives a solid's modulus and a yield strain of
      // 0.01-5 %.
      std::string slip;
      for (const auto& [unit, factor] : {std::pair{"MPa", 1e6}, std::pair{"GPa", 1e9}, std::pair{"kPa", 1e3}})
        if (const double e = *E * factor; e <= stiffest_solid && sy / e >= 1e-4 && sy / e <= 0.05) {
          slip = fmt::format(": {}? ({} {} = {:.4g} Pa: write `{} {}`)", unit, *E, unit, e, material.parameters.at(key),
                             unit);
          break;
        }
      warnings.push_back(material_warning(
          scene, name, key,
          fmt::format(
              "a yield stress ({:.6g} Pa) above {}: the material can never yield (a yield strain of {:.3g}; metals "
              "yield at 0.1-2 %){}",
              sy, modulus, sy / *E, slip)));
      continue;
    }
    const auto density = material.parameters.find("density");
    if (*E < softest_plastic_solid && density != material.parameters.end() && density->second >= lightest_dense_solid) {
      std::string slip;
      if (*E * 1e9 <= stiffest_solid && *E * 1e9 >= 1e9)
        slip = fmt::format(": GPa? ({:.4g} Pa: write `{} GPa`)", *E * 1e9, material.parameters.at(key));
      else if (*E * 1e6 <= stiffest_solid)
        slip = fmt::format(": MPa? ({:.4g} Pa: write `{} MPa`)", *E * 1e6, material.parameters.at(key));
      warnings.push_back(material_warning(
          scene, name, key,
          fmt::format("{} is far below any elastic-plastic solid's (soft clays about 1e6 Pa, metals 1e10 to 4e11 Pa) "
                      "while the density {} kg/m^3 is a solid's{}",
                      modulus, density->second, slip)));
    }
  }
}

template <int Dim>
void check_overlap(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings) {
  const auto& bodies = sim.bodies();
  std::vector<Bounds<Dim>> boxes;
  for (const auto& b : bodies) boxes.push_back(bounds_of(b.particles));
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      if (bodies[i].particles.size() == 0 || bodies[j].particles.size() == 0) continue;
      // The smaller body's particles are looked up among the larger one's, within r.
      const bool i_smaller = bodies[i].particles.size() <= bodies[j].particles.size();
      const Body<Dim>& small = bodies[i_smaller ? i : j];
      const Body<Dim>& large = bodies[i_smaller ? j : i];
      const Real r = overlap_fraction * std::min(spacing(scene, sim, small.index), spacing(scene, sim, large.index));
      Bounds<Dim> region;  // where both bodies' boxes, widened by r, meet
      region.lo = boxes[i].lo.cwiseMax(boxes[j].lo) - Vec<Dim>::Constant(r);
      region.hi = boxes[i].hi.cwiseMin(boxes[j].hi) + Vec<Dim>::Constant(r);
      if (region.empty()) continue;
      const CellIndex<Dim> index(large.particles, region, r);
      std::size_t close = 0;
      for (Index p = 0; p < small.particles.size(); ++p)
        if (region.contains(small.particles.x[p]) && index.has_point_near(small.particles.x[p])) ++close;
      const auto n = static_cast<std::size_t>(small.particles.size());
      if (close < std::max(overlap_least_count, static_cast<std::size_t>(overlap_least_share * static_cast<double>(n))))
        continue;
      const auto& later = scene.bodies[std::max(i, j)];
      warnings.push_back(SceneError::format(
          later.where, fmt::format("bodies[{}]", std::max(i, j)),
          fmt::format(
              "bodies '{}' and '{}' overlap at t = 0: {} of the {} particles of '{}' ({:.3g} %) lie closer than "
              "half a particle spacing ({:.3g} m) to particles of '{}' (bodies that only touch keep a spacing "
              "between their particles); move or shrink one",
              bodies[i].name, bodies[j].name, close, n, small.name,
              100.0 * static_cast<double>(close) / static_cast<double>(n), r, large.name)));
    }
}

template <int Dim>
void check_wave_transit(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings) {
  if (!sim.scheme().has_mechanics() || sim.time_step_limiter().rfind("CFL", 0) != 0) return;
  struct Transit {
    const Body<Dim>* body;
    Real speed, length, time;
    bool too_short;
  };
  const double end = scene.solver.end_time;
  const Real h_min = sim.grid().geometry.h.minCoeff();
  std::vector<Transit> transits;
  for (const auto& b : sim.bodies()) {
    const Real c = wave_speed_at_rest(b);
    // Rigid (no waves), or waves faster than in any matter: then the material is the slip (rule 1), not the end time.
    if (!(c > 0) || c > fastest_solid_wave) continue;
    const Bounds<Dim> box = bounds_of(b.particles);
    Real length = 0;  // the box of the particles, widened by half a spacing on each side
    for (int d = 0; d < Dim; ++d) length = std::max(length, box.hi[d] - box.lo[d] + spacing(scene, sim, b.index, d));
    transits.push_back({&b, c, length, length / c, end * c < std::min(least_transit_share * length, h_min)});
  }
  if (transits.empty()) return;
  const SourceLocation where = locate_key(scene, {"solver", "end_time"});
  if (std::all_of(transits.begin(), transits.end(), [](const Transit& t) { return t.too_short; })) {
    const Transit& t = *std::min_element(transits.begin(), transits.end(),
                                         [](const Transit& a, const Transit& b) { return a.time < b.time; });
    warnings.push_back(SceneError::format(
        where, "solver.end_time",
        fmt::format("end_time = {} s ends before any wave crosses a cell ({:.3g} m) or 1 % of a body: the quickest "
                    "to cross, body '{}' ({:.3g} m at {:.4g} m/s), takes {:.3g} s, {:.3g} times the run; a time unit "
                    "slipped?",
                    end, h_min, t.body->name, t.length, t.speed, t.time, t.time / end)));
    return;
  }
  const Transit& slowest = *std::max_element(transits.begin(), transits.end(),
                                             [](const Transit& a, const Transit& b) { return a.time < b.time; });
  if (end > most_transits * slowest.time)
    warnings.push_back(SceneError::format(
        where, "solver.end_time",
        fmt::format("end_time = {} s is {:.3g} times the {:.3g} s a wave takes to cross body '{}' ({:.3g} m at {:.4g} "
                    "m/s), the slowest to cross: every body is crossed more than 1e5 times in the run; a time in ms or "
                    "us written as s? (write `end_time: {} us` for microseconds)",
                    end, end / slowest.time, slowest.time, slowest.body->name, slowest.length, slowest.speed, end)));
}

template <int Dim>
std::vector<std::string> plausibility_warnings(const SceneDescription& scene, const Simulation<Dim>& sim) {
  std::vector<std::string> warnings;
  check_density(scene, sim, warnings);
  check_yield_stress(scene, warnings);
  check_overlap(scene, sim, warnings);
  check_wave_transit(scene, sim, warnings);
  return warnings;
}

#define MPM_PLAUSIBILITY(D)                                                                                      \
  template void check_density<D>(const SceneDescription&, const Simulation<D>&, std::vector<std::string>&);      \
  template void check_overlap<D>(const SceneDescription&, const Simulation<D>&, std::vector<std::string>&);      \
  template void check_wave_transit<D>(const SceneDescription&, const Simulation<D>&, std::vector<std::string>&); \
  template std::vector<std::string> plausibility_warnings<D>(const SceneDescription&, const Simulation<D>&);
MPM_PLAUSIBILITY(1)
MPM_PLAUSIBILITY(2)
MPM_PLAUSIBILITY(3)
#undef MPM_PLAUSIBILITY

}  // namespace mpm::app
