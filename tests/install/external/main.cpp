// Ten lines against an installed mpm: a 2D scene run for 10 steps, printing its total energy.
#include <iostream>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/io/number_format.hpp"
#include "mpm/scene/scene_loader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  mpm::app::register_modules();
  auto sim = mpm::app::build_simulation<2>(mpm::load_scene(argv[1]));
  sim->run({}, 10);
  std::cout << "step " << sim->step() << " total_energy " << mpm::io::format_double(sim->energy().total()) << '\n';
}
