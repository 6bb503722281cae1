// The hybrid patch and its form (papers/003) instantiated for every standard arithmetic, so client
// code compiles against declarations only.
#include "exact/rational.hpp"
#include "float/mpfr.hpp"
#include "hybrid/instantiate.hpp"

namespace splinex {

SPLINEX_INSTANTIATE_HYBRID(Rational)
SPLINEX_INSTANTIATE_HYBRID(double)
SPLINEX_INSTANTIATE_HYBRID(Mpfr)

}  // namespace splinex
