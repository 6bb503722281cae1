// Composition (Bezier, B-spline and trimmed; papers/000) instantiated for double and MPFR.
#include "compose/instantiate.hpp"
#include "float/arith_spec.hpp"

namespace splinex {
static_assert(ComposeArithmetics::has<double> && ComposeArithmetics::has<Mpfr>);  // the table's compose list
SPLINEX_INSTANTIATE_COMPOSE(double)
SPLINEX_INSTANTIATE_COMPOSE(Mpfr)
}  // namespace splinex
