// make_scheme for 2D: every (scheme, shape function) instantiation of this dimension.
#include "make_scheme_impl.hpp"

namespace mpm {
template std::unique_ptr<Scheme<2>> make_scheme<2>(const std::string&, const std::string&);
}  // namespace mpm
