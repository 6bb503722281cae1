#include "float/mpfr.hpp"  // ArithTraits<double>
#include "spline/instantiate.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_KERNEL(double)
}
