// The hybrid patch and its form (papers/003) instantiated for the hybrid package's arithmetics
// (SPLINEX_HYBRID_ARITHMETICS, float/arith_spec.hpp), so client code compiles against declarations only.
#include "float/arith_spec.hpp"
#include "hybrid/instantiate.hpp"

namespace splinex {

SPLINEX_HYBRID_ARITHMETICS(SPLINEX_INSTANTIATE_HYBRID)

}  // namespace splinex
