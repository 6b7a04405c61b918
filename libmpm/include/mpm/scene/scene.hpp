#pragma once
/// \file scene.hpp
/// Plain-data description of a simulation as read from a YAML scene file (see docs/scene-reference.md).
/// The loader (scene_loader.hpp) fills it and validates every value; build_simulation() turns it into
/// a running Simulation. Nothing here allocates particle or grid storage.

#include <any>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mpm/boundary/face_names.hpp"
#include "mpm/core/coordinates.hpp"
#include "mpm/failure/failure_criteria.hpp"
#include "mpm/simulation/solver_options.hpp"

namespace mpm {

/// Where a value came from in the scene file (1-based line and column; 0 when unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// A face's condition as the scene gives it (`grid.boundary.FACE`): the name of its kind (the registry of
/// boundary/face_condition_kind.hpp, whose entry gives its traits and makes its grid condition) and what the
/// kind's parser read.
struct FaceDescription {
  std::string kind = "free";  ///< no condition: a particle that leaves the grid stops the run
  std::any spec;
  SourceLocation where;
};

struct GridDescription {
  std::array<double, 3> origin{0, 0, 0};     ///< m, lower corner
  std::array<double, 3> extent{0, 0, 0};     ///< m, box lengths
  std::array<double, 3> cell_size{0, 0, 0};  ///< m, per axis
  std::array<int, 3> cells{1, 1, 1};         ///< derived: extent / cell_size (checked to divide evenly)
  /// `grid.coordinates`: axisymmetric only in 2D, with origin x = 0 and the face x_min the axis (slip, set by
  /// the loader).
  Coordinates coordinates = Coordinates::cartesian;
  /// Faces in the order of face_names.
  std::array<FaceDescription, 6> boundary;

  /// The scene's names of the box faces (`grid.boundary`, `thermal.boundary`), in the order of `boundary`.
  static constexpr std::array<const char*, 6> face_names = mpm::face_names;
};

/// A named material: its model key (a registry name such as "linear_elastic") and its parameters, in SI
/// units, already checked against the model's parameter specification.
struct MaterialDescription {
  std::string name;
  std::string model;
  std::map<std::string, double> parameters;
  SourceLocation where;
  /// `failure:` (failure/failure_criteria.hpp): when its particles fail and what they become; absent: never.
  std::optional<FailureCriteria> failure;
  SourceLocation failure_where;  ///< the `failure:` key
  /// What the model's keys that are not numbers read (MaterialModel::keys and read_keys: a file, a list, a word;
  /// the user_material module's `library`, `properties`, ...), in the model's own plain type; empty for the others.
  std::any model_keys{};
};

/// The shape a body is filled from (docs/scene-reference.md, bodies[].shape): the name of its kind (the registry
/// of body_shape/shape_kind.hpp, whose entry reads, bounds and fills it) and what the kind's parser read (its own
/// plain description: BoxShape, DiskShape, ... of body_shape/primitive_shapes.hpp, geometry's MeshShape, ...).
struct ShapeDescription {
  std::string kind;
  std::any spec;
  SourceLocation where;  ///< of the shape, for errors found while filling it

  /// The kind's description (std::bad_any_cast when it is another type).
  template <class Spec>
  const Spec& as() const {
    return std::any_cast<const Spec&>(spec);
  }
  template <class Spec>
  Spec& as() {
    return std::any_cast<Spec&>(spec);
  }
};

/// A body: a set of particles with one material.
struct BodyDescription {
  std::string name;
  std::string material;  ///< key into SceneDescription::materials
  ShapeDescription shape;
  std::array<int, 3> particles_per_cell{2, 2, 2};  ///< per axis
  /// Initial velocity per component: muparser expressions of x, y, z (constants are expressions too).
  std::array<std::string, 3> velocity{"0", "0", "0"};
  /// CPDI particle elements: "lattice" (every particle sub-cell split into elements) or "conforming" (a CGAL
  /// triangle or tetrahedron mesh of the shape, cpdi_t3 / cpdi_tet4 only).
  std::string domains = "lattice";
  /// `volume: exact`: the particles share the shape's exact volume (ShapeTraits::exact_volume) instead of each
  /// having its lattice sub-cell's; the default is the kind's (ShapeTraits::exact_by_default).
  bool exact_volume = false;
  SourceLocation where;
};

/// A named particle set (`sets.NAME`, docs/scene-reference.md#sets): the particles of its bodies whose initial
/// position lies in its region and whose id is in its list; each criterion the scene omits takes every particle.
/// Membership is decided once, at t = 0, and kept in the particle field `particle_sets` (sets/particle_sets.hpp).
struct SetDescription {
  std::string name;
  std::vector<int> bodies;                 ///< indices into SceneDescription::bodies; empty: every body
  std::optional<ShapeDescription> region;  ///< the initial positions' region (any body shape kind)
  /// Inclusive id ranges [first, last] (the `id` field of the frames); empty: every id.
  std::vector<std::array<std::uint32_t, 2>> ids;
  SourceLocation where;
};

/// One entry of `conditions:` (docs/scene-reference.md#conditions): what is prescribed on a particle set. Each
/// component is absent (not prescribed) or a muparser expression.
struct SetConditionDescription {
  int set = 0;  ///< index into SceneDescription::sets
  /// The held velocity components, m/s, expressions of x, y, z (the node's position) and t: the grid nodes the
  /// set's particles reach move with it (sets/set_conditions.hpp).
  std::array<std::optional<std::string>, 3> velocity;
  /// N (per metre in 2D, per radian axisymmetric): the total force on the set, expressions of t, shared by the
  /// particles in proportion to their mass.
  std::array<std::optional<std::string>, 3> force;
  /// The initial velocity of the set's particles, m/s, expressions of x, y, z (replaces the body's).
  std::array<std::optional<std::string>, 3> initial_velocity;
  /// The initial Cauchy stress of the set's particles, Pa, expressions of x, y, z, in the stress field's component
  /// order (xx, yy, zz, xy, yz, xz; the first 3, 4 or 6 in 1D, 2D, 3D): the state a hypoelastic model starts from.
  std::array<std::optional<std::string>, 6> initial_stress;
  /// `initial_stress: geostatic`: the stress of the set at rest under gravity (sets/geostatic_stress.hpp,
  /// docs/theory.md eqs 20.1-20.2) instead of expressions.
  bool geostatic = false;
  /// K0 = sigma_h / sigma_v of the geostatic stress; absent: each body's model's (MaterialModel::at_rest_coefficient).
  std::optional<double> k0;
  SourceLocation where;
  std::string path;  ///< its key path for messages, e.g. "conditions[1]"
};

/// `solver.gravity_stage` (simulation/gravity_stage.hpp, docs/theory.md §20): before t = 0 the bodies settle under
/// gravity with local damping until the unbalanced force is small; the run then starts from that state at rest.
struct GravityStageDescription {
  double damping = 0.8;     ///< alpha of eq. 2.74 during the stage, in (0, 1)
  double tolerance = 1e-4;  ///< the unbalanced force ratio (eq. 20.3) at which the bodies count as at rest
  int max_steps = 100000;   ///< the stage gives up after this many steps
  NoEquilibriumAction on_no_equilibrium = NoEquilibriumAction::stop;
  SourceLocation where;
};

struct SolverDescription {
  /// The name of a registered scheme (scheme_registry.hpp: the core's musl, tlmpm, usf, usl, or a module's, e.g.
  /// implicit); its traits say what it works with (scheme_of(solver).traits).
  std::string scheme = "musl";
  /// What that scheme's parser returned (its own `solver:` keys), empty when it has none.
  std::any scheme_options;
  std::string shape_function = "linear";  ///< a name of shape_function_names() (scheme.hpp)
  VelocityTransfer velocity_transfer = VelocityTransfer::flip;
  double flip_fraction = 1.0;  ///< PIC/FLIP blend alpha of eq. 2.53 (1 = FLIP, 0 = PIC)
  /// The scene gives `velocity_transfer` or `flip_fraction`; if not, a module's section may choose the transfer
  /// its physics needs (SceneExtension::complete: `contact:` takes `apic`).
  bool velocity_transfer_given = false;
  /// Local non-viscous damping coefficient alpha of eq. 2.74, in [0, 1) (0: off)
  double damping = 0;
  /// CPDI shape functions only (empty otherwise): corners from F (eq. 3.27) or tracked (eq. 3.38)
  std::optional<CpdiDomainUpdate> cpdi_domain_update;
  std::optional<double> dt;                ///< s, fixed time step (exclusive with cfl)
  std::optional<double> cfl;               ///< CFL factor of eq. 2.73, in (0, 1]
  double end_time = 0;                     ///< s
  double mass_cutoff = 1e-12;              ///< relative small-nodal-mass cut-off (x max nodal mass)
  std::array<double, 3> gravity{0, 0, 0};  ///< m/s^2, body force per unit mass
  int snapshot_interval = 20;              ///< steps between in-memory snapshots used by the stability guard
  int sort_interval = 20;                  ///< steps between particle reorderings by cell
  /// The energy sentinel's tolerance, a fraction of the largest energy of the run so far (energy_sentinel.hpp)
  double energy_tolerance = 0.05;
  EnergyDriftAction on_energy_drift = EnergyDriftAction::warn;
  std::optional<GravityStageDescription> gravity_stage;  ///< `gravity_stage`: settle under gravity before t = 0
  SourceLocation dt_where;

  /// The scheme's scene name.
  const std::string& scheme_name() const { return scheme; }
};

/// One entry of `output.histories` (docs/scene-reference.md#histories): a quantity written to its own CSV,
/// one row per `interval`. `type` names a kind of the history registry (history/history_kind.hpp); `spec` is
/// what that kind's parser returned.
struct HistoryDescription {
  std::string name;     ///< the CSV is NAME.csv in the output directory
  std::string type;     ///< probe, reaction, energy, extent, ...
  double interval = 0;  ///< s between rows (0: every output frame of `output.interval`, or only first and last)
  std::any spec;
  SourceLocation where;
  std::string path;  ///< its key path for messages, e.g. "output.histories[2]"
};

/// `output.checkpoint`: when a run writes checkpoints (docs/scene-reference.md). Without it a run writes one
/// only when a signal stops it.
struct CheckpointDescription {
  bool enabled = false;                 ///< the scene has the section
  std::optional<double> interval;       ///< s of simulated time between checkpoints
  std::optional<double> wall_interval;  ///< s of wall-clock time between checkpoints
  int keep = 2;                         ///< newest checkpoints kept (older ones are removed)
  std::string directory;                ///< empty: OUTPUT_DIRECTORY/checkpoints
  SourceLocation where;
};

struct OutputDescription {
  std::string directory = "output";
  std::string prefix = "particles";
  double interval = 0;  ///< s between output frames (0 = only first and last)
  std::vector<std::string> fields{"velocity", "stress", "mass", "volume", "body"};
  bool grid = false;                          ///< also write the grid (.vti) at each frame
  std::vector<HistoryDescription> histories;  ///< probes, reactions, energies, extents (one CSV each)
  CheckpointDescription checkpoint;
  SourceLocation where;
};

struct SceneDescription {
  std::string file;    ///< path of the scene file
  std::string source;  ///< the file's YAML text as read (written into every output file's field data)
  int dimension = 2;
  /// `units:`, the unit system of the scene's bare numbers (core/units.hpp); every value here is SI.
  std::string units = "m-s-kg";
  GridDescription grid;
  std::map<std::string, MaterialDescription> materials;
  std::vector<BodyDescription> bodies;
  std::vector<SetDescription> sets;                 ///< `sets:`, in the scene's order (a set's bit is its index)
  std::vector<SetConditionDescription> conditions;  ///< `conditions:`
  SolverDescription solver;
  OutputDescription output;
  /// Sections of optional modules (scene_extension.hpp), by top-level key, as their parsers returned them.
  std::map<std::string, std::any> extensions;
};

}  // namespace mpm
