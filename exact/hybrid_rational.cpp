// The hybrid patch instantiated for exact rationals.
#include "exact/rational.hpp"
#include "spline/hybrid_refine_impl.hpp"

namespace splinex {
template HybridLocal<Rational> hybrid_local(const HybridPatch<Rational>&, const std::array<Rational, 2>&);
template std::vector<Rational> hybrid_evaluate(const HybridPatch<Rational>&, const std::array<Rational, 2>&);
template std::vector<Rational> hybrid_boundary(const HybridPatch<Rational>&, std::size_t, const Rational&);
template std::vector<Rational> hybrid_cross_tangent(const HybridPatch<Rational>&, std::size_t, const Rational&);
template void validate(const HybridPatch<Rational>&);
template HybridJet<Rational> hybrid_jet(const HybridPatch<Rational>&, const std::array<Rational, 2>&, const std::array<Rational, 2>&);
template HybridDerivatives<Rational> hybrid_derivatives(const HybridPatch<Rational>&, const std::array<Rational, 2>&);
template HybridCrossDerivative<Rational> hybrid_cross_derivative(const HybridPatch<Rational>&, std::size_t, const std::array<Rational, 2>&);
template HybridForm<Rational> hybrid_form(const HybridPatch<Rational>&);
template std::vector<Rational> hybrid_form_evaluate(const HybridForm<Rational>&, const std::array<Rational, 2>&);
template std::vector<Rational> hybrid_form_interior(const HybridFormSide<Rational>&, int, const Rational&, const Rational&);
template std::vector<Rational> hybrid_form_ribbon(const HybridFormSide<Rational>&, int, const Rational&, const Rational&);
template std::pair<std::vector<Rational>, std::vector<Rational>> cls_elevate(int, const std::vector<Rational>&, const std::vector<Rational>&, int);
template HybridForm<Rational> hybrid_elevate(const HybridForm<Rational>&);
template HybridForm<Rational> hybrid_insert(const HybridForm<Rational>&, const Rational&, const Rational&, const Rational&);
template HybridPatch<Rational> hybrid_elevate_salvi(const HybridPatch<Rational>&);
}  // namespace splinex
