#include "exact/flint_rational.hpp"
#include "spline/instantiate.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_KERNEL(FlintRational)
}
