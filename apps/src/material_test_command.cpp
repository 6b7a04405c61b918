// `mpm material-test` (material_test_command.hpp): the options checked, the scene's material built in 3D, the path
// driven (material_test.hpp) and the CSV written whole.
#include "mpm/app/material_test_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <ostream>

#include "mpm/app/material_test.hpp"
#ifdef MPM_WITH_USER_MATERIAL
#include "mpm/user_material/umat_tangent_check.hpp"
#endif
#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/core/closest_name.hpp"
#include "mpm/io/atomic_file.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::app {
namespace {

/// The plot of --plot (matplotlib): q against the axial strain, the shear stress against the shear strain (the loops
/// of a cyclic path), the volumetric against the axial strain, and the stress path q against p.
constexpr const char* plot_script =
    R"PY(# Plot of `mpm material-test` (written by mpm): python3 SCRIPT PATH.csv PLOT.png
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
col = lambda name: [float(r[name]) for r in rows]
fig, ax = plt.subplots(2, 2, figsize=(10, 7.5))
panels = [("strain_xx", "q", "axial log strain", "q (Pa)"), ("strain_xy", "stress_xy", "shear strain xy", "shear stress xy (Pa)"),
          ("strain_xx", "volumetric_strain", "axial log strain", "volumetric strain ln J"), ("p", "q", "p (Pa)", "q (Pa)")]
for a, (x, y, xl, yl) in zip(ax.flat, panels):
    a.plot(col(x), col(y), "-")
    a.set_xlabel(xl)
    a.set_ylabel(yl)
    a.grid(True, alpha=0.3)
fig.suptitle(sys.argv[3], fontsize=10)
fig.tight_layout()
tmp = sys.argv[2] + ".tmp.png"
fig.savefig(tmp, dpi=110)
os.replace(tmp, sys.argv[2])
)PY";

/// Draws `csv` into `png` with /usr/bin/python3 and matplotlib; a message when it could not.
std::string draw_plot(const std::string& csv, const std::filesystem::path& png, const std::string& title) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpm_material_test_{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "path.csv") << csv;
  std::ofstream(dir / "plot.py") << plot_script;
  const std::string command =
      fmt::format("/usr/bin/python3 '{}' '{}' '{}' '{}' > '{}' 2>&1", (dir / "plot.py").string(),
                  (dir / "path.csv").string(), png.string(), title, (dir / "plot.log").string());
  const bool drawn = ::access("/usr/bin/python3", X_OK) == 0 && std::system(command.c_str()) == 0 && fs::exists(png);
  std::string log;
  if (!drawn) {
    std::ifstream in(dir / "plot.log");
    std::getline(in, log);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  return drawn ? "" : fmt::format("no plot: /usr/bin/python3 with matplotlib failed ({})", log);
}

/// The driver's options from the command's, or a MaterialTestError for a bad combination.
MaterialTestOptions driver_options(const MaterialTestCommandOptions& c) {
  const auto path = load_path_named(c.path);
  if (!path) {
    const std::vector<std::string> names = load_path_names();
    throw MaterialTestError(fmt::format("unknown path '{}'{}; valid paths: {}", c.path, did_you_mean(c.path, names),
                                        fmt::join(names, ", ")));
  }
  MaterialTestOptions o;
  o.path = *path;
  o.strain = c.strain;
  o.steps = c.steps;
  o.duration = c.duration;
  o.confining_pressure = c.confining_pressure;
  o.consolidation_steps = c.consolidation_steps;
  o.amplitude = c.amplitude;
  o.cycles = c.cycles;
  if (o.path == LoadPath::deformation_csv) {
    if (c.csv.empty()) throw MaterialTestError("path deformation_csv needs --csv FILE (time,F11,...,F33 per row)");
    if (c.confining_pressure != 0)
      throw MaterialTestError("--confining-pressure does not apply to path deformation_csv (F(t) is prescribed whole)");
    o.samples = read_deformation_csv(c.csv);
  } else if (!c.csv.empty()) {
    throw MaterialTestError(fmt::format("--csv only applies to path deformation_csv, not {}", c.path));
  }
  if (!(o.strain >= 0) || !(o.duration > 0) || o.steps < 1 || o.consolidation_steps < 1 || o.cycles < 1 ||
      !(o.confining_pressure >= 0))
    throw MaterialTestError(
        "expected --strain >= 0, --duration > 0, --steps >= 1, --consolidation-steps >= 1, --cycles >= 1 and "
        "--confining-pressure >= 0");
  return o;
}

/// The status of a failed `--check`.
constexpr int exit_check_failed = 3;

/// `--check` (material_test_command.hpp): each check's line on `err`; false when one fails.
bool checks_pass(Material<3>& material, const MaterialTestResult& path, std::ostream& err) {
  bool pass = true;
  const ObjectivityCheck objectivity = check_objectivity(material, path);
  const bool objective = objectivity.difference <= objectivity_tolerance;
  pass = pass && objective;
  err << fmt::format(
      "check: objectivity (the path with a rigid rotation superposed, principal stresses): largest "
      "difference {:.3g} of the largest stress at t = {:.6g} s (tolerance {:.0e}): {}\n",
      objectivity.difference, objectivity.time, objectivity_tolerance, objective ? "passed" : "FAILED");
#ifdef MPM_WITH_USER_MATERIAL
  if (auto* user = dynamic_cast<user_material::UserMaterial<3>*>(&material);
      user && user->plugin().spec.interface == user_material::Interface::umat) {
    std::vector<std::pair<double, Mat3>> F;
    for (std::size_t k = 1; k < path.rows.size(); ++k) F.emplace_back(path.rows[k].time, path.rows[k].F);
    const user_material::TangentCheck t = user_material::check_umat_tangent(*user, F);
    const bool good = t.difference <= tangent_tolerance;
    pass = pass && good;
    err << fmt::format(
        "check: tangent (DDSDDE against finite differences of STRESS, {} steps): largest difference "
        "{:.3g} of the largest entry, DDSDDE({}, {}) at t = {:.6g} s (tolerance {:.0e}): {}\n",
        t.steps, t.difference, t.row, t.column, t.time, tangent_tolerance, good ? "passed" : "FAILED");
    return pass;
  }
#endif
  err << "check: tangent: not applicable (only a UMAT gives one)\n";
  return pass;
}

}  // namespace

int material_test_command(const MaterialTestCommandOptions& options, std::ostream& out, std::ostream& err) {
  try {
    register_modules();
    const MaterialTestOptions driver = driver_options(options);
    const SceneDescription scene = load_scene(options.scene);
    const auto it = scene.materials.find(options.material);
    if (it == scene.materials.end()) {
      std::vector<std::string> names;
      names.reserve(scene.materials.size());
      for (const auto& [name, m] : scene.materials) names.push_back(name);
      throw MaterialTestError(fmt::format("no material '{}' in {}{}; its materials: {}", options.material,
                                          options.scene, did_you_mean(options.material, names),
                                          fmt::join(names, ", ")));
    }
    if (const MaterialModel* model = find_material_model(it->second.model);
        model && model->phase == MaterialPhase::rigid)
      throw MaterialTestError(fmt::format("material '{}' is rigid (model {}): it has no stress to drive along a path",
                                          options.material, it->second.model));
    const std::unique_ptr<Material<3>> material = make_material<3>(it->second);
    if (!material->tracks_deformation())
      throw MaterialTestError(fmt::format(
          "material '{}' (model {}) keeps its volume: its pressure is the multiplier of div v = 0 that the grid's "
          "projection finds for the whole flow, not a response of one point, so no path can drive it (its viscous "
          "stress is 2 mu dev D; docs/theory.md §21)",
          options.material, it->second.model));
    const MaterialTestResult result = run_material_test(*material, driver);
    const std::string csv = material_test_csv(result);
    if (options.output.empty()) {
      out << csv;
    } else {
      io::write_atomically(options.output, [&](const std::filesystem::path& tmp) {
        std::ofstream file(tmp);
        file << csv;
        if (!file.flush()) throw std::runtime_error("cannot write " + options.output);
      });
    }
    if (!options.plot.empty())
      if (const std::string problem = draw_plot(
              csv, options.plot, fmt::format("{} ({}), {}", options.material, it->second.model, options.path));
          !problem.empty())
        err << "warning: " << problem << '\n';
    if (options.check && !checks_pass(*material, result, err)) return exit_check_failed;
    return exit_ok;
  } catch (const SceneError& e) {
    err << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const MaterialTestError& e) {
    err << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const std::exception& e) {
    err << "error: " << e.what() << '\n';
    return exit_runtime_error;
  }
}

}  // namespace mpm::app
