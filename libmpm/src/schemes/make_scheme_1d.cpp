// make_scheme for 1D: every (scheme, shape function) instantiation of this dimension.
#include "make_scheme_impl.hpp"

namespace mpm {
template std::unique_ptr<Scheme<1>> make_scheme<1>(const std::string&, const std::string&);
}  // namespace mpm
