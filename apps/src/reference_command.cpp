#include "mpm/app/reference_command.hpp"

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/io/atomic_file.hpp"
#include "mpm/material_reference.hpp"

namespace mpm::app {

int reference_command(const std::optional<std::filesystem::path>& file, std::ostream& out, std::ostream& err) {
  register_modules();  // every model compiled in
  if (!file) {
    out << material_reference();
    return exit_ok;
  }
  std::ifstream in(*file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) {
    err << "error: " << file->string() << ": cannot read the file\n";
    return exit_runtime_error;
  }
  MaterialReferenceUpdate update;
  try {
    update = update_material_reference(text.str());
  } catch (const std::invalid_argument& e) {
    err << "error: " << file->string() << ": " << e.what() << '\n';
    return exit_bad_input;
  }
  for (const auto& block : update.skipped)
    err << "warning: " << file->string() << ": left '" << block << "' as it was (a model is not compiled in)\n";
  if (update.text == text.str()) {
    out << file->string() << ": current (" << update.blocks << " generated blocks)\n";
    return exit_ok;
  }
  try {
    io::write_atomically(*file, [&](const std::filesystem::path& tmp) {
      std::ofstream o(tmp, std::ios::binary);
      o << update.text;
      if (!o) throw std::runtime_error("cannot write " + tmp.string());
    });
  } catch (const std::exception& e) {
    err << "error: " << file->string() << ": " << e.what() << '\n';
    return exit_runtime_error;
  }
  out << file->string() << ": rewrote " << update.blocks << " generated blocks\n";
  return exit_ok;
}

}  // namespace mpm::app
