#include "mpm/app/verify_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>

#include "mpm/app/commit_id.hpp"
#include "mpm/io/atomic_file.hpp"

namespace mpm::app {
namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
  io::write_atomically(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  });
}

std::string when(const VerifyQuantity& q) {
  const std::string end = q.time ? fmt::format("t = {:g} s", *q.time) : "the end";
  return q.start ? fmt::format("the change from t = {:g} s to {}", *q.start, end) : "at " + end;
}

/// The plot: per quantity, the value against h (with the extrapolated value and the GCI band on the finest run)
/// and the estimated error against wall time (the work-precision line).
constexpr const char* plot_script =
    R"PY(# Plot of `mpm verify` (written by mpm): python3 plot_verify.py verify_runs.csv verify.png
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
names = list(dict.fromkeys(r["quantity"] for r in rows))
fig, axes = plt.subplots(len(names), 2, figsize=(10, 3.6 * len(names)), squeeze=False)
for (value_ax, work_ax), name in zip(axes, names):
    runs = [r for r in rows if r["quantity"] == name]
    h = [float(r["h"]) for r in runs]
    value = [float(r["value"]) for r in runs]
    value_ax.plot(h, value, "o-", label="runs")
    value_ax.set_xscale("log")
    value_ax.set_xlabel("cell size h (m)")
    value_ax.set_ylabel(runs[0]["column"])
    value_ax.set_title(name, fontsize=10)
    if runs[0]["asymptotic"] == "yes":
        ext, gci = float(runs[0]["extrapolated"]), float(runs[0]["gci"])
        finest = min(range(len(h)), key=lambda k: h[k])
        value_ax.axhline(ext, color="gray", ls="--", label="Richardson extrapolation")
        value_ax.errorbar([h[finest]], [value[finest]], yerr=[gci], color="C3", capsize=4,
                          label="GCI band (p = %.2f)" % float(runs[0]["order"]))
        error = [float(r["estimated_error"]) for r in runs]
        seconds = [float(r["seconds"]) for r in runs]
        work_ax.loglog(seconds, error, "o-")
        work_ax.set_xlabel("wall time (s)")
        work_ax.set_ylabel("|value - extrapolated|")
        work_ax.set_title("work-precision", fontsize=10)
    else:
        work_ax.text(0.5, 0.5, "not in the asymptotic range:\nno error estimate", ha="center", va="center",
                     transform=work_ax.transAxes)
        work_ax.set_axis_off()
    value_ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
)PY";

std::string runs_csv(const VerifyReport& r) {
  std::string text = "quantity,column,level,h,value,seconds,estimated_error,asymptotic,order,extrapolated,gci\n";
  for (std::size_t qi = 0; qi < r.quantities.size(); ++qi)
    for (std::size_t k = 0; k < r.runs.size(); ++k) {
      const auto& q = r.quantities[qi];
      const auto& res = q.result;
      const bool numbers = res.asymptotic;
      // estimated_error is finest first in the result; the runs here are coarsest first
      const double error = numbers ? res.estimated_error[r.runs.size() - 1 - k] : 0;
      text += fmt::format("{},{},{},{:.17g},{:.17g},{:.6g},{:.17g},{},{:.17g},{:.17g},{:.17g}\n", q.name, q.column, k,
                          r.runs[k].h, r.runs[k].values[qi], r.runs[k].seconds, error, numbers ? "yes" : "no",
                          res.order, res.extrapolated, res.gci);
    }
  return text;
}

std::string markdown(const VerifyReport& r, const std::string& plot_note) {
  std::ostringstream md;
  fmt::print(md, "# Solution verification: {}\n\n", r.scene_file);
  fmt::print(md, "`{}`  \nmpm {} (commit {}), {} thread(s). Written by `mpm verify` (method: docs/verify.md).\n\n",
             r.command, MPM_VERSION, commit_id(),
             tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  fmt::print(md,
             "Each run divides the previous run's cell size by {:g} (rounded to whole cells per axis); the particles "
             "per cell stay, so the particle spacing follows, and the time step follows the CFL condition (a fixed "
             "`dt` is scaled with h). h is the geometric mean of the cell sizes. The estimated errors are "
             "|value − extrapolated| when the runs are in the asymptotic range.\n\n",
             r.ratio);
  fmt::print(md, "## Runs\n\n| run | cells | h (m) | particles | steps | wall time (s) |\n|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    const auto& run = r.runs[k];
    fmt::print(md, "| {} | {} | {:.6g} | {} | {} | {:.3f} |\n", k + 1,
               fmt::join(run.cells.begin(), run.cells.begin() + r.dimension, " × "), run.h, run.particles, run.steps,
               run.seconds);
  }
  if (!r.stopped.empty()) fmt::print(md, "\n**Stopped:** {}\n", r.stopped);
  for (const auto& w : r.warnings) fmt::print(md, "\n**Warning:** {}\n", w);
  for (std::size_t qi = 0; qi < r.quantities.size(); ++qi) {
    const auto& q = r.quantities[qi];
    const auto& res = q.result;
    fmt::print(md, "\n## {} ({}, {})\n\n", q.name, q.column, when(q));
    fmt::print(md,
               "| run | h (m) | value | estimated error \\|value − extrapolated\\| | wall time (s) "
               "|\n|---|---|---|---|---|\n");
    for (std::size_t k = 0; k < r.runs.size(); ++k)
      fmt::print(md, "| {} | {:.6g} | {:.10g} | {} | {:.3f} |\n", k + 1, r.runs[k].h, r.runs[k].values[qi],
                 res.asymptotic ? fmt::format("{:.3g}", res.estimated_error[r.runs.size() - 1 - k]) : "–",
                 r.runs[k].seconds);
    if (!res.triple_orders.empty()) {
      std::vector<std::string> orders;
      for (double p : res.triple_orders) orders.push_back(std::isnan(p) ? "none" : fmt::format("{:.2f}", p));
      fmt::print(md, "\nObserved order of each three consecutive runs (coarsest first): {}.\n",
                 fmt::join(orders, ", "));
    }
    if (!res.asymptotic) {
      fmt::print(md,
                 "\n**Not in the asymptotic range:** {}. No order, extrapolation or error band is given; refine "
                 "further, or check that the quantity converges at all.\n",
                 res.verdict);
      continue;
    }
    const double finest = r.runs.back().values[qi];
    fmt::print(md, "\n- {}.\n", res.verdict);
    fmt::print(md, "- Richardson extrapolation: **{:.10g}**.\n", res.extrapolated);
    fmt::print(md,
               "- GCI (safety factor {:g}): **{:.3g}** ({:.3g}% of the finest value): the finest run's {:.10g} "
               "± {:.3g}.\n",
               res.safety_factor, res.gci, 100 * res.gci_relative, finest, res.gci);
    fmt::print(md, "- One more refinement (h = {:.6g} m): predicted error {:.3g}, about {:.3g} s.\n", res.next_h,
               res.next_error, res.next_seconds);
  }
  fmt::print(md, "\n{}\n", plot_note);
  return md.str();
}

}  // namespace

void write_verify_report(const fs::path& dir, const VerifyReport& r, bool plot, std::ostream& out) {
  fs::create_directories(dir);
  write_text(dir / "verify_runs.csv", runs_csv(r));
  std::string plot_note = "Plot skipped (--no-plot).";
  if (plot) {
    write_text(dir / "plot_verify.py", plot_script);
    const fs::path png = dir / "verify.png";
    const std::string python = "/usr/bin/python3";
    std::error_code ec;
    fs::remove(png, ec);
    const std::string command = python + " '" + (dir / "plot_verify.py").string() + "' '" +
                                (dir / "verify_runs.csv").string() + "' '" + png.string() + "' > '" +
                                (dir / "plot_verify.log").string() + "' 2>&1";
    if (::access(python.c_str(), X_OK) == 0 && r.runs.size() >= 2 && std::system(command.c_str()) == 0 &&
        fs::exists(png))
      plot_note = "![value against h, and the work-precision line](verify.png)";
    else
      plot_note = "No plot: `" + python +
                  " plot_verify.py verify_runs.csv verify.png` failed (needs matplotlib; see "
                  "plot_verify.log).";
  }
  write_text(dir / "verify.md", markdown(r, plot_note));
  for (std::size_t qi = 0; qi < r.quantities.size(); ++qi) {
    const auto& q = r.quantities[qi];
    if (q.result.asymptotic)
      fmt::print(out, "{}: {:.10g} ± {:.3g} (GCI, Fs {:g}); order {:.2f}, extrapolated {:.10g}\n", q.name,
                 r.runs.back().values[qi], q.result.gci, q.result.safety_factor, q.result.order, q.result.extrapolated);
    else
      fmt::print(out, "{}: not in the asymptotic range: {}\n", q.name, q.result.verdict);
  }
  // r.warnings are not repeated here: run_verification printed them on the log (stderr) and verify.md holds them.
  fmt::print(out, "report: {}\n", (dir / "verify.md").string());
}

}  // namespace mpm::app
