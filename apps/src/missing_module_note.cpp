#include <string_view>

#include "mpm/app/modules.hpp"

namespace mpm::app {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

/// Errors about a name that an optional module registers: a material model, a top-level section, an output field.
bool names_what_a_module_could_define(const SceneError& e) {
  if (starts_with(e.message, "unknown material model")) return true;
  if (starts_with(e.message, "unknown key") && e.key.find_first_of(".[") == std::string::npos) return true;
  return starts_with(e.key, "output.fields") && starts_with(e.message, "invalid value");
}

}  // namespace

std::string missing_module_note(const SceneError& error, const std::vector<std::string>& missing) {
  if (missing.empty() || !names_what_a_module_could_define(error)) return "";
  std::string names, options;
  for (std::size_t k = 0; k < missing.size(); ++k) {
    const std::string separator = k == 0 ? "" : (k + 1 == missing.size() ? " or " : ", ");
    std::string option = "MPM_WITH_";
    for (char c : missing[k]) option += static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    names += separator + missing[k];
    options += (k == 0 ? "" : ", ") + option + "=ON";
  }
  return "; this build has no " + names + " module (CMake option" + (missing.size() > 1 ? "s " : " ") + options +
         "), whose models, sections and output fields are unknown to it";
}

}  // namespace mpm::app
