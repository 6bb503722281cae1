// Composition (Bezier, B-spline and trimmed; papers/000) instantiated for double and MPFR.
#include "compose/instantiate.hpp"
#include "float/mpfr.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_COMPOSE(double)
SPLINEX_INSTANTIATE_COMPOSE(Mpfr)
}  // namespace splinex
