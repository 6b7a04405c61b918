#pragma once
/// \file bench_options.hpp
/// The command line of the benchmark programs (bench_taylor, bench_taylor_bar, bench_hertz, bench_necking):
/// `--name VALUE` options read into variables, `--name` flags, `-h`/`--help`, and `--threads N` (>= 1). A bad
/// command line prints `PROGRAM: message` and gives exit status 2, as every program of the project does.
///
///   int threads = 1;
///   mpm::bench::BenchOptions cli("bench_x", "[--h M] [--threads N]");
///   cli.option("--h", spec.h).threads(threads);
///   if (const auto status = cli.parse(argc, argv)) return *status;

#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mpm::bench {

class BenchOptions {
 public:
  BenchOptions(std::string program, std::string usage) : program_(std::move(program)), usage_(std::move(usage)) {}

  /// `name VALUE` sets `target` (std::string, int or double; a number must be one to its last character).
  template <class T>
  BenchOptions& option(const std::string& name, T& target) {
    options_.push_back({name, true, [&target, name](const std::string& text) { target = convert<T>(name, text); }});
    return *this;
  }
  /// `name` alone sets `target` to true.
  BenchOptions& flag(const std::string& name, bool& target) {
    options_.push_back({name, false, [&target](const std::string&) { target = true; }});
    return *this;
  }
  /// `--threads N`, checked to be >= 1.
  BenchOptions& threads(int& target) {
    threads_ = &target;
    return option("--threads", target);
  }
  /// A condition on the values, checked after reading them: `message` when it does not hold.
  BenchOptions& require(std::function<bool()> condition, std::string message) {
    checks_.emplace_back(std::move(condition), std::move(message));
    return *this;
  }

  /// Reads the command line. Empty: go on; otherwise the exit status to end with (0 after --help, 2 for a
  /// bad command line, with the message on stderr).
  std::optional<int> parse(int argc, char** argv) const {
    try {
      for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-h" || a == "--help") {
          std::cout << "usage: " << program_ << " " << usage_ << "\n";
          return 0;
        }
        const Option* o = find(a);
        if (!o) throw std::invalid_argument("unknown option " + a);
        if (o->takes_value && i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        o->set(o->takes_value ? std::string(argv[++i]) : std::string());
      }
      if (threads_ && *threads_ < 1) throw std::invalid_argument("--threads must be >= 1");
      for (const auto& [condition, message] : checks_)
        if (!condition()) throw std::invalid_argument(message);
    } catch (const std::exception& e) {
      std::cerr << program_ << ": " << e.what() << "\n";
      return 2;
    }
    return std::nullopt;
  }

 private:
  struct Option {
    std::string name;
    bool takes_value;
    std::function<void(const std::string&)> set;
  };

  const Option* find(const std::string& name) const {
    for (const auto& o : options_)
      if (o.name == name) return &o;
    return nullptr;
  }

  template <class T>
  static T convert(const std::string& name, const std::string& text) {
    if constexpr (std::is_same_v<T, std::string>) {
      return text;
    } else {
      std::size_t used = 0;
      T value{};
      try {
        if constexpr (std::is_same_v<T, int>)
          value = std::stoi(text, &used);
        else
          value = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size()) throw std::invalid_argument(name + ": '" + text + "' is not a number");
      return value;
    }
  }

  std::string program_, usage_;
  std::vector<Option> options_;
  std::vector<std::pair<std::function<bool()>, std::string>> checks_;
  int* threads_ = nullptr;
};

/// The options of the method and the resolution that the Taylor runners' specs (TaylorSpec, TaylorBarSpec)
/// share: --scheme, --shape, --h (m), --ppc (per axis), --cfl, --output (a directory for the frames).
template <class Spec>
BenchOptions& method_options(BenchOptions& cli, Spec& spec) {
  return cli.option("--scheme", spec.scheme)
      .option("--shape", spec.shape_function)
      .option("--h", spec.h)
      .option("--ppc", spec.particles_per_cell)
      .option("--cfl", spec.cfl)
      .option("--output", spec.output_directory);
}

}  // namespace mpm::bench
