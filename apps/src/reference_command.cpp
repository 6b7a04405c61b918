#include "mpm/app/reference_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mpm/app/material_reference.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/app/scene_reference.hpp"
#include "mpm/diagnostics/energy_hints.hpp"
#include "mpm/io/atomic_file.hpp"

namespace mpm::app {
namespace {

/// Rewrites the generated blocks of `file`.
int rewrite(const std::filesystem::path& file, std::ostream& out, std::ostream& err) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) {
    err << "error: " << file.string() << ": cannot read the file\n";
    return exit_runtime_error;
  }
  SceneReferenceUpdate update;
  try {
    update = update_scene_reference(text.str());
  } catch (const std::invalid_argument& e) {
    err << "error: " << file.string() << ": " << e.what() << '\n';
    return exit_bad_input;
  }
  for (const auto& block : update.skipped)
    err << "warning: " << file.string() << ": left '" << block << "' as it was (a module is not compiled in)\n";
  if (update.text == text.str()) {
    out << file.string() << ": current (" << update.blocks << " generated blocks)\n";
    return exit_ok;
  }
  try {
    io::write_atomically(file, [&](const std::filesystem::path& tmp) {
      std::ofstream o(tmp, std::ios::binary);
      o << update.text;
      if (!o) throw std::runtime_error("cannot write " + tmp.string());
    });
  } catch (const std::exception& e) {
    err << "error: " << file.string() << ": " << e.what() << '\n';
    return exit_runtime_error;
  }
  out << file.string() << ": rewrote " << update.blocks << " generated blocks\n";
  return exit_ok;
}

}  // namespace

int reference_command(const ReferenceOptions& options, std::ostream& out, std::ostream& err) {
  register_modules();  // every model and section compiled in
  if (options.file) return rewrite(*options.file, out, err);
  std::vector<std::pair<std::string, std::string>> tables;  // title, text
  if (!options.section.empty()) {
    const auto table = section_key_table(options.section);
    if (!table) {
      std::vector<std::string> sections = sections_with_keys();
      sections.erase(sections.begin());  // the top level
      err << "error: no section '" << options.section
          << "' declares its keys; sections that do: " << fmt::format("{}", fmt::join(sections, ", ")) << '\n';
      return exit_bad_input;
    }
    tables.emplace_back("Keys of " + options.section, *table);
  }
  const bool all = !options.materials && !options.keys && options.section.empty() && !options.output_fields &&
                   !options.history_kinds && !options.energy_hints;
  if (all || options.keys) tables.emplace_back("Scene keys", key_reference());
  if (all || options.output_fields) tables.emplace_back("Output fields", output_field_table());
  if (all || options.history_kinds) tables.emplace_back("History kinds", history_kind_table());
  if (all || options.materials) tables.emplace_back("Material models", material_reference());
  if (all || options.energy_hints) tables.emplace_back("Energy hints", energy_hint_table());
  if (tables.size() == 1) {
    out << tables.front().second;
    return exit_ok;
  }
  for (const auto& [title, text] : tables) out << "## " << title << "\n\n" << text << '\n';
  return exit_ok;
}

}  // namespace mpm::app
