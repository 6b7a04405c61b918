/// \file verification_report.cpp
/// Error against run time: runs the resolution ladder of every case of the verification catalogue
/// (tests/verification/catalogue.hpp, the same cases the tests use) and the CFL-factor search on the bar and
/// the two disks (cfl_limit.hpp), and writes the measurements as CSV for bench/make_verification_report.py,
/// which draws the plots and writes docs/VERIFICATION.md. Run it through `bash bench/run_report.sh [--quick]`.
///
/// This is a program, not a test: its wall times depend on the machine. Runs are sequential, on one thread
/// by default, so that the wall times of different methods compare.

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "catalogue.hpp"
#include "cfl_limit.hpp"
#include "mpm/diagnostics/energy_hints.hpp"
#include "stability_cases.hpp"

namespace {

namespace fs = std::filesystem;
namespace v = mpm::verification;
using Clock = std::chrono::steady_clock;

struct Options {
  bool quick = false;
  fs::path out = "verification_report";
  std::vector<std::string> only;  ///< substrings of case names (empty: all)
  bool cases = true, cfl = true, stability = true;
  double max_run_seconds = 0;  ///< skip a resolution predicted to take longer (0: quick 20 s, full 120 s)
  int threads = 1;
};

void usage(std::ostream& os) {
  os << "usage: verification_report [--quick] [--out DIR] [--only TEXT]... [--no-cases] [--no-cfl] [--no-stability]\n"
        "                           [--max-run-seconds S] [--threads N]\n"
        "  --quick              the catalogue's standard ladders and a coarser CFL search (about 4 minutes\n"
        "                       here); without it every ladder gets one finer resolution (about 30 minutes)\n"
        "  --out DIR            where runs.csv, cfl.csv and stability.csv go (default ./verification_report)\n"
        "  --only TEXT          only cases whose name contains TEXT (repeatable), e.g. --only mms_2d\n"
        "  --no-cases, --no-cfl, --no-stability   leave that part out\n"
        "  --max-run-seconds S  skip a resolution whose predicted wall time (from the previous one, times the\n"
        "                       growth of particles x steps) exceeds S (default 30 quick, 120 full)\n"
        "  --threads N          TBB threads for every run (default 1, so that wall times compare)\n";
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--only") {
      o.only.push_back(value());
    } else if (a == "--no-cases") {
      o.cases = false;
    } else if (a == "--no-cfl") {
      o.cfl = false;
    } else if (a == "--no-stability") {
      o.stability = false;
    } else if (a == "--max-run-seconds") {
      o.max_run_seconds = std::stod(value());
      if (!(o.max_run_seconds > 0)) throw std::invalid_argument("--max-run-seconds must be > 0");
    } else if (a == "--threads") {
      o.threads = std::stoi(value());
      if (o.threads < 1) throw std::invalid_argument("--threads must be >= 1");
    } else if (a == "-h" || a == "--help") {
      usage(std::cout);
      std::exit(0);
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  }
  if (o.max_run_seconds == 0) o.max_run_seconds = o.quick ? 30 : 120;
  return o;
}

/// A CSV field: quoted, with inner quotes doubled (failure messages contain commas).
std::string csv_field(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + '"';
}

/// The 1-minute load average (/proc/loadavg): other processes slow the runs down; the report says how much.
double load_average() {
  std::ifstream in("/proc/loadavg");
  double load = -1;
  in >> load;
  return load;
}

bool selected(const Options& o, const std::string& name) {
  if (o.only.empty()) return true;
  for (const auto& s : o.only)
    if (name.find(s) != std::string::npos) return true;
  return false;
}

void run_cases(const Options& o) {
  std::ofstream csv(o.out / "runs.csv");
  csv << "family,case,dimension,scheme,shape_function,resolution,h,particles,steps,error,wall_seconds,"
         "particle_updates_per_second,status,timed_runs,failure,error_measure,reference\n";
  // --quick: the catalogue's standard ladders (those of the convergence tests); full: one refinement more.
  const auto cases = v::catalogue(false, o.quick ? 0 : 1);
  std::size_t done = 0;
  for (const auto& c : cases) {
    ++done;
    if (!selected(o, c.name)) continue;
    double last_wall = 0, last_work = 0;
    for (int n : c.resolutions) {
      // Work grows like (cells per side)^dimension particles x cells steps.
      const double work = std::pow(static_cast<double>(n), c.dimension + 1);
      const double predicted = last_work > 0 ? last_wall * work / last_work : 0;
      std::string status = "ok";
      v::CaseRun r;
      int repeats = 1;
      if (predicted > o.max_run_seconds) {
        status = fmt::format("skipped: predicted {:.0f} s", predicted);
      } else {
        r = c.run(n);
        // A run of a few milliseconds is timed again until 0.2 s have been spent on it (at most 20 runs), and
        // the fastest counts: single short runs are dominated by noise (page faults, the first use of the
        // thread pool, other processes). The error is the same every time (the runs are deterministic).
        for (double spent = r.wall_seconds; r.failure.empty() && spent < 0.2 && repeats < 20; ++repeats) {
          const double again = c.run(n).wall_seconds;
          spent += again;
          r.wall_seconds = std::min(r.wall_seconds, again);
        }
        if (!r.failure.empty()) status = "unstable";
        last_wall = r.wall_seconds;
        last_work = work;
      }
      const double rate = r.wall_seconds > 0 ? static_cast<double>(r.particles) * r.steps / r.wall_seconds : 0;
      fmt::print(std::cerr, "[{}/{}] {} n = {}: error {:.4g}, {:.3f} s, {}\n", done, cases.size(), c.name, n, r.error,
                 r.wall_seconds, status);
      fmt::print(csv, "{},{},{},{},{},{},", c.family, c.name, c.dimension, c.scheme, c.shape_function, n);
      fmt::print(csv, "{:.9g},{},{},{:.9g},{:.6f},{:.6g},", r.h, r.particles, r.steps, r.error, r.wall_seconds, rate);
      fmt::print(csv, "{},{},{},{},{}\n", status, repeats, csv_field(r.failure), csv_field(c.error_measure),
                 csv_field(c.reference));
      csv.flush();
      if (status == "unstable") break;  // finer resolutions of an unstable method are not informative here
    }
  }
}

void run_cfl(const Options& o) {
  std::ofstream csv(o.out / "cfl.csv");
  csv << "problem,scheme,shape_function,largest_stable_cfl,smallest_unstable_cfl,probes,failure\n";
  const std::vector<std::string> shapes = {"linear",        "gimp",     "cpgimp", "quadratic_bspline",
                                           "cubic_bspline", "bernstein"};
  for (const auto& problem : v::cfl_problems())
    for (const char* scheme : {"usl", "musl", "usf", "tlmpm"})
      for (const auto& shape : shapes) {
        if (!selected(o, problem + "/" + scheme + "/" + shape)) continue;
        if (problem == "two_disks" && std::string(scheme) == "tlmpm") continue;  // no contact: see cfl_limit.hpp
        const auto t0 = Clock::now();
        const v::CflLimit l = o.quick ? v::largest_stable_cfl(problem, scheme, shape, 0.2, 2.0, 3)
                                      : v::largest_stable_cfl(problem, scheme, shape);
        fmt::print(std::cerr, "CFL {}/{}/{}: stable up to {:.3f}, unstable at {:.3f} ({} probes, {:.1f} s)\n", problem,
                   scheme, shape, l.largest_stable, l.smallest_unstable, l.probes.size(),
                   std::chrono::duration<double>(Clock::now() - t0).count());
        fmt::print(csv, "{},{},{},{:.4f},{:.4f},{},{}\n", problem, scheme, shape, l.largest_stable, l.smallest_unstable,
                   l.probes.size(), csv_field(l.failure));
        csv.flush();
      }
}

const char* outcome(const v::StabilityOutcome& r) {
  switch (r.status) {
    case v::StabilityOutcome::Status::completed:
      return "completed";
    case v::StabilityOutcome::Status::stopped_by_guard:
      return "stopped by the stability guard";
    default:
      return "refused by the scene loader";
  }
}

void run_stability(const Options& o) {
  std::ofstream(o.out / "energy_hints.md") << mpm::energy_hint_table();  // docs/VERIFICATION.md's hint table
  std::ofstream csv(o.out / "stability.csv");
  csv << "case,description,outcome,measured,all_output_finite,wall_seconds,summary\n";
  for (const auto& s : v::stability_cases()) {
    if (!selected(o, s.name)) continue;
    const v::StabilityOutcome r = s.run(o.out / "stability_output" / s.name);
    fmt::print(std::cerr, "stability {}: {} ({:.2f} s)\n", s.name, outcome(r), r.wall_seconds);
    fmt::print(csv, "{},{},{},{:.6g},{},{:.3f},{}\n", s.name, csv_field(s.description), outcome(r), r.measured,
               r.output.all_finite() ? "yes" : "NO", r.wall_seconds, csv_field(r.summary));
    csv.flush();
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "verification_report: " << e.what() << '\n';
    usage(std::cerr);
    return 2;
  }
  try {
    fs::create_directories(o.out);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(o.threads));
    const auto t0 = Clock::now();
    const double load_start = load_average();
    if (o.cases) run_cases(o);
    if (o.cfl) run_cfl(o);
    if (o.stability) run_stability(o);
    const double total = std::chrono::duration<double>(Clock::now() - t0).count();
    std::ofstream(o.out / "meta.csv") << "quick,threads,total_wall_seconds,load_average_start,load_average_end\n"
                                      << (o.quick ? 1 : 0) << ',' << o.threads << ',' << total << ',' << load_start
                                      << ',' << load_average() << '\n';
    fmt::print(std::cerr, "verification_report: done in {:.1f} s; CSV in {}\n", total, o.out.string());
  } catch (const std::exception& e) {
    std::cerr << "verification_report: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
