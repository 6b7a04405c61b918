// make_scheme for 3D: every (scheme, shape function) instantiation of this dimension.
#include "make_scheme_impl.hpp"

namespace mpm {
template std::unique_ptr<Scheme<3>> make_scheme<3>(const std::string&, const std::string&);
}  // namespace mpm
