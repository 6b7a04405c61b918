#pragma once
/// \file verify_command.hpp
/// `mpm verify SCENE --refine K --quantity HISTORY.COLUMN[@TIME] ... [--ratio R] [--finest] [-o DIR]`: solution
/// verification of any scene (docs/verify.md). Runs the scene K times, the grid's cell size divided by R per
/// run (or, with --finest, the scene as the finest run and the others coarser; particles per cell unchanged, so
/// the particle spacing follows; the CFL time step follows by itself, a fixed dt is scaled with h), measures each
/// quantity (a column of one of the scene's output.histories, at a time or at the end), and reports per quantity the
/// observed order, Richardson's extrapolation, the GCI band on the finest run and the wall time of every run
/// (solution_verification.hpp), or why the runs give no number. Writes DIR/verify.md, DIR/verify_runs.csv,
/// DIR/verify.png (plotted by DIR/plot_verify.py with /usr/bin/python3 and matplotlib) and each run's history CSVs in
/// DIR/run_K/.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "mpm/app/verify_report.hpp"

namespace mpm::app {

struct VerifyOptions {
  std::filesystem::path scene;
  int runs = 3;      ///< --refine: number of resolutions (>= 2; two need --order)
  double ratio = 2;  ///< --ratio: refinement factor of the cell size per run (> 1)
  /// --quantity HISTORY.COLUMN (at the end), HISTORY.COLUMN@TIME (s), or HISTORY.COLUMN@START:TIME (its change)
  std::vector<std::string> quantities;
  std::filesystem::path output = "verify";  ///< -o
  std::optional<double> order;              ///< --order: assumed order (needed with two runs)
  bool plot = true;                         ///< --no-plot: skip the PNG
  /// --finest: the scene is the finest run and the others are coarser (cell size times R, R^2, ...); by default
  /// it is the coarsest and the others are finer.
  bool scene_is_finest = false;
};

/// Runs the scene at every resolution and analyses the quantities (progress to `log`); writes each run's
/// history CSVs, not the report. Throws std::invalid_argument for bad options (before any run: a quantity whose
/// history or column the scene does not have), SceneError for a bad scene; a run stopped by the stability guard
/// ends the series (VerifyReport::stopped says why).
VerifyReport run_verification(const VerifyOptions& options, std::ostream& log);

/// `mpm verify`: run_verification, then the report. Exit status (run_scene.hpp): 0 the report was written
/// (whatever it found), 2 bad scene or options (nothing run), 3 the stability guard stopped a run (the report
/// covers the runs before it), 1 I/O error.
int verify_command(const VerifyOptions& options, std::ostream& out, std::ostream& log);

}  // namespace mpm::app
