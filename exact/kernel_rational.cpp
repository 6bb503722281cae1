#include "exact/rational.hpp"
#include "spline/instantiate.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_KERNEL(Rational)
}
