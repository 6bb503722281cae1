#include "spline/instantiate.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_KERNEL(double)
}
