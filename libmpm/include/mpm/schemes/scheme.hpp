#pragma once
/// \file scheme.hpp
/// A time-integration scheme advances every body by one step. The explicit schemes (USL, MUSL, USF and the
/// total-Lagrangian TLMPM, schemes/*.hpp) are templates on dimension and shape function; the scene picks
/// one instantiation once (make_scheme). Every scheme, the core's and the modules', is registered with its traits
/// in scheme_registry.hpp.

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/simulation/module.hpp"

namespace mpm {

template <int Dim>
class Scheme {
 public:
  virtual ~Scheme() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view shape_function() const = 0;
  /// Slab thickness the shape function needs for the race-free scatter.
  virtual int slab_cells() const = 0;
  /// Cells an axis needs at least with this shape function.
  virtual int min_cells() const = 0;
  /// One full step: transfers, grid update, boundary conditions, particle update, stress update.
  virtual void advance(StepContext<Dim>& ctx) = 0;
  /// Called once with the initial state, before the first step and the first snapshot (TLMPM caches
  /// its reference weights here).
  virtual void initialize(std::vector<Body<Dim>>&, Grid<Dim>&) {}
  /// A distributed run moved particles between ranks outside the steps (Simulation::distribute, a new slab
  /// assignment): a scheme that caches per-particle data rebuilds it (TLMPM's stencils and bins).
  virtual void particles_redistributed(std::vector<Body<Dim>>&, Grid<Dim>&) {}
  /// The positions a distributed run assigns particles to ranks by: the current ones (null), or TLMPM's reference
  /// positions (its particles never migrate with their motion).
  virtual const VecU<Dim>* ownership_positions(const ParticleSet<Dim>&) const { return nullptr; }
  /// False when the scheme keeps per-particle data in particle order (TLMPM): no periodic sorting.
  virtual bool reorders_particles() const { return true; }
  /// False when particle positions are not used by the transfers (TLMPM: they may leave the grid).
  virtual bool positions_must_stay_in_grid() const { return true; }
  /// Whether the scheme runs on several ranks (its scatters exchange ghost nodes, tile_halo.hpp).
  virtual bool runs_distributed() const { return false; }
  /// False for a scheme that moves nothing (the thermal module's `heat` analysis): the bodies' wave speeds and
  /// viscosities then bound no time step (Simulation::stable_time_step), only the modules' bounds do.
  virtual bool has_mechanics() const { return true; }
  /// Node layers a slab of cells reaches below its first cell and above its last (tile_halo.hpp).
  virtual std::pair<int, int> slab_reach() const { return {slab_cells(), slab_cells()}; }
  /// The scheme's own table of one row per step (the implicit scheme's solver.csv, written by `mpm run` beside
  /// energy.csv): its file name, or empty when it keeps none; its columns; the row of the last step taken.
  virtual std::string_view step_log_file() const { return {}; }
  virtual std::vector<std::string> step_log_columns() const { return {}; }
  virtual std::vector<double> step_log_row() const { return {}; }
};

/// What every scheme templated on a shape function reports about it.
template <int Dim, class Shape>
class ShapedScheme : public Scheme<Dim> {
 public:
  std::string_view shape_function() const override { return Shape::name; }
  int slab_cells() const override { return Shape::slab_cells; }
  int min_cells() const override { return Shape::min_cells; }
  std::pair<int, int> slab_reach() const override { return {Shape::slab_reach_below, Shape::slab_reach_above}; }
};

/// The registered scheme named `scheme` (scheme_registry.hpp: "musl", "tlmpm", "usf", "usl" and the modules') with
/// a shape function of the table (find_shape_function: "linear", "gimp", "cpgimp", "quadratic_bspline",
/// "cubic_bspline", "bernstein", "lagrange_quadratic", "cpdi_*"); throws std::invalid_argument listing valid names.
/// `coordinates`: axisymmetric in 2D takes the schemes' axisymmetric instantiations (axisymmetric.hpp), on the shape
/// functions that allow it (ShapeFunctionInfo::axisymmetric). A scheme whose maker needs more of the scene (its own
/// `solver:` keys) is made with make_scene_scheme.
template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape_function,
                                         Coordinates coordinates = Coordinates::cartesian);

/// Names accepted as `solver.shape_function`.
std::vector<std::string> shape_function_names();

/// What the scene loader must check about the grid for a shape function.
struct ShapeFunctionInfo {
  std::string name;
  int min_cells = 1;              ///< cells an axis needs at least
  bool even_cells = false;        ///< the number of cells per axis must be even (Bernstein: two cells per element)
  bool particle_domain = false;   ///< weights depend on the particle domain (GIMP): field "domain_half_length0"
  bool tlmpm_only = false;        ///< negative weights: only with the total-Lagrangian scheme (Lagrange quadratic)
  int dimension = 0;              ///< the only dimension the function exists in (CPDI elements), 0 for any
  int domain_corners = 0;         ///< CPDI: corners of the particle element (fields "cpdi_corners"/"..._offsets0")
  bool domain_follows_F = false;  ///< CPDI: domains convect with F unless the scene asks for corner tracking
  bool tracks_corners = false;    ///< CPDI: the corners may be tracked on their own (all but the R4 parallelogram)
  bool stretched_domain = false;  ///< GIMP: the domain follows diag F (cpGIMP, eq. 3.14), drawn so in the output
  bool axisymmetric = false;      ///< usable on an axisymmetric grid (shape_axisymmetric)
  bool multilinear = false;       ///< the multilinear functions of the particle's cell (linear hats, shape_multilinear)
};
/// The entry for `name`, or nullptr.
const ShapeFunctionInfo* find_shape_function(const std::string& name);

}  // namespace mpm
