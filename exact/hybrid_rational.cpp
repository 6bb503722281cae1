// The hybrid patch instantiated for exact rationals.
#include "exact/rational.hpp"
#include "spline/hybrid_impl.hpp"

namespace splinex {
template HybridLocal<Rational> hybrid_local(const HybridPatch<Rational>&, const std::array<Rational, 2>&);
template std::vector<Rational> hybrid_evaluate(const HybridPatch<Rational>&, const std::array<Rational, 2>&);
template std::vector<Rational> hybrid_boundary(const HybridPatch<Rational>&, std::size_t, const Rational&);
template std::vector<Rational> hybrid_cross_tangent(const HybridPatch<Rational>&, std::size_t, const Rational&);
template void validate(const HybridPatch<Rational>&);
}  // namespace splinex
