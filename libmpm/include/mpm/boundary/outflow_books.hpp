#pragma once
/// \file boundary/outflow_books.hpp
/// What left the run through an outflow face (GridBoundary): per face, the audit of the particles removed there
/// (mass, momentum and the energies of energy.hpp, each summed exactly, so the books are the same bits for any
/// thread count, particle order and rank count), and the first departure of each body through each face.

#include <string>

#include "mpm/boundary/face.hpp"
#include "mpm/removal/removed_particles.hpp"
#include "mpm/simulation/energy.hpp"

namespace mpm {

/// The books of one outflow face since t = 0 (removal/removed_particles.hpp).
struct OutflowBook : RemovedBook {
  int face = 0;  ///< the order of face_names
};

/// The first time particles of a body left through a face: the run loop logs message() on that step, once.
struct OutflowNotice {
  std::string body;
  int face = 0;
  Index step = 0;       ///< the step they left in
  Real time = 0;        ///< s, at the end of that step
  Index particles = 0;  ///< how many left in that step
  std::string message() const;
};

}  // namespace mpm
