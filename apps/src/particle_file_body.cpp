#include "particle_file_body.hpp"

namespace mpm::app {

template <int Dim>
void apply_seed_state(Body<Dim>& body, const ParticleSeeds<Dim>& seed) {
  if (!seed.velocity && !seed.stress && !seed.mass && !seed.id) return;
  auto& p = body.particles;
  for (std::size_t i = 0; i < seed.positions.size(); ++i) {
    if (seed.velocity) p.v[i] = (*seed.velocity)[i];
    if (seed.stress) p.stress[i] = (*seed.stress)[i];
    if (seed.mass) p.mass[i] = (*seed.mass)[i];
    if (seed.id) p.id[i] = (*seed.id)[i];
  }
}

template void apply_seed_state<1>(Body<1>&, const ParticleSeeds<1>&);
template void apply_seed_state<2>(Body<2>&, const ParticleSeeds<2>&);
template void apply_seed_state<3>(Body<3>&, const ParticleSeeds<3>&);

}  // namespace mpm::app
