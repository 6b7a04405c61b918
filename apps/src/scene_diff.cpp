#include "mpm/app/scene_diff.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "mpm/core/units.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::app {
namespace {

/// What a fork may change, from the specs: the sections' keys (KeySpec::run_control, KeySpec::fork_refusal),
/// the materials' parameters (material_fork_rules). Built on each call: the registered kinds are the rules' source.
std::vector<io::ForkRule> all_fork_rules() {
  std::vector<io::ForkRule> rules = io::fork_rules(scene_keys());
  for (auto& rule : material_fork_rules()) rules.push_back(std::move(rule));
  return rules;
}

std::string text_of(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "(absent)";
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

/// The value of a number as SI (`25 us` is 2.5e-5: a bare number is in its key's SI unit), or nothing.
std::optional<double> value_in_si(const std::string& text) {
  const auto x = units::split_number(text);
  if (!x) return std::nullopt;
  try {
    return x->unit.empty() ? x->number : x->number * units::parse_unit(x->unit).size();
  } catch (const units::UnitError&) {
    return std::nullopt;
  }
}

bool same_scalar(const YAML::Node& a, const YAML::Node& b) {
  if (a.Scalar() == b.Scalar()) return true;
  const auto x = value_in_si(a.Scalar()), y = value_in_si(b.Scalar());
  return x && y && (*x == *y || std::abs(*x - *y) <= 1e-15 * std::abs(*x));  // 7.85 g/cm^3 and 7850 alike
}

class Differ {
 public:
  Differ(const std::string& file, std::vector<SceneDifference>& out)
      : file_(file), out_(out), rules_(all_fork_rules()) {}

  void compare(const YAML::Node& saved, const YAML::Node& now, const std::string& path, const YAML::Mark& mark) {
    const bool had = saved.IsDefined() && !saved.IsNull(), has = now.IsDefined() && !now.IsNull();
    if (!had && !has) return;
    if (had && has && saved.Type() == now.Type()) {
      if (now.IsMap()) return compare_maps(saved, now, path, mark);
      if (now.IsSequence() && saved.size() == now.size()) {
        for (std::size_t i = 0; i < now.size(); ++i)
          compare(saved[i], now[i], path + "[" + std::to_string(i) + "]", now[i].Mark());
        return;
      }
      if (now.IsScalar() && same_scalar(saved, now)) return;
    }
    SceneDifference d;
    d.key = path;
    d.was = text_of(saved);
    d.now = text_of(now);
    if (has) {
      d.where = {file_, mark.line + 1, mark.column + 1};
    } else {
      const YAML::Mark m = saved.Mark();
      d.where = {"the checkpoint's scene", m.line + 1, m.column + 1};
    }
    if (const io::ForkRule* rule = io::fork_rule_for(rules_, path)) {
      d.run_control = rule->allowed;
      d.refusal = rule->reason;
    }
    if (!d.run_control && d.refusal.empty()) d.refusal = undeclared_refusal;
    out_.push_back(std::move(d));
  }

 private:
  void compare_maps(const YAML::Node& saved, const YAML::Node& now, const std::string& path, const YAML::Mark& mark) {
    auto key_path = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
    std::vector<std::string> seen;
    for (const auto& entry : now) {  // keys of the new scene, in its order; then the removed ones
      const std::string key = entry.first.as<std::string>();
      seen.push_back(key);
      compare(saved[key], entry.second, key_path(key),
              entry.second.IsNull() ? entry.first.Mark() : entry.second.Mark());
    }
    for (const auto& entry : saved) {
      const std::string key = entry.first.as<std::string>();
      if (std::find(seen.begin(), seen.end(), key) == seen.end())
        compare(entry.second, YAML::Node(), key_path(key), mark);
    }
  }

  std::string file_;
  std::vector<SceneDifference>& out_;
  std::vector<io::ForkRule> rules_;
};

}  // namespace

bool is_run_control_key(const std::string& key) {
  const io::ForkRule* rule = io::fork_rule_for(all_fork_rules(), key);
  return rule && rule->allowed;
}

std::vector<SceneDifference> scene_differences(const std::string& saved, const std::string& current,
                                               const std::string& current_file) {
  YAML::Node before, after;
  try {
    before = YAML::Load(saved);
  } catch (const YAML::Exception& e) {
    throw SceneError({"the checkpoint's scene", e.mark.line + 1, e.mark.column + 1}, "",
                     "the scene stored in the checkpoint is not YAML: " + e.msg);
  }
  try {
    after = YAML::Load(current);
  } catch (const YAML::Exception& e) {
    throw SceneError({current_file, e.mark.line + 1, e.mark.column + 1}, "", "YAML syntax error: " + e.msg);
  }
  std::vector<SceneDifference> out;
  Differ(current_file, out).compare(before, after, "", after.Mark());
  return out;
}

}  // namespace mpm::app
