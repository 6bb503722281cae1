// Composition (Bezier, B-spline and trimmed; papers/000) instantiated for the exact arithmetics.
#include "compose/instantiate.hpp"
#include "exact/flint_rational.hpp"
#include "exact/rational.hpp"

namespace splinex {
SPLINEX_INSTANTIATE_COMPOSE(Rational)
SPLINEX_INSTANTIATE_COMPOSE(FlintRational)
}  // namespace splinex
