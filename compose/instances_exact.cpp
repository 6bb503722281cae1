// Composition (Bezier, B-spline and trimmed; papers/000) instantiated for the exact arithmetics.
#include "compose/instantiate.hpp"
#include "float/arith_spec.hpp"

namespace splinex {
static_assert(ComposeArithmetics::has<Rational> && ComposeArithmetics::has<FlintRational>);  // the table's compose list
SPLINEX_INSTANTIATE_COMPOSE(Rational)
SPLINEX_INSTANTIATE_COMPOSE(FlintRational)
}  // namespace splinex
