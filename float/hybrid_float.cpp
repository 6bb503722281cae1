// The hybrid patch instantiated for double and MPFR.
#include "float/mpfr.hpp"
#include "spline/hybrid_refine_impl.hpp"

namespace splinex {
#define SPLINEX_INSTANTIATE_HYBRID(T)                                                                       \
  template HybridLocal<T> hybrid_local(const HybridPatch<T>&, const std::array<T, 2>&);                     \
  template std::vector<T> hybrid_evaluate(const HybridPatch<T>&, const std::array<T, 2>&);                  \
  template std::vector<T> hybrid_boundary(const HybridPatch<T>&, std::size_t, const T&);                    \
  template std::vector<T> hybrid_cross_tangent(const HybridPatch<T>&, std::size_t, const T&);               \
  template void validate(const HybridPatch<T>&);                                                            \
  template HybridJet<T> hybrid_jet(const HybridPatch<T>&, const std::array<T, 2>&, const std::array<T, 2>&);  \
  template HybridDerivatives<T> hybrid_derivatives(const HybridPatch<T>&, const std::array<T, 2>&);          \
  template HybridCrossDerivative<T> hybrid_cross_derivative(const HybridPatch<T>&, std::size_t, const std::array<T, 2>&); \
  template HybridForm<T> hybrid_form(const HybridPatch<T>&);                                                \
  template std::vector<T> hybrid_form_evaluate(const HybridForm<T>&, const std::array<T, 2>&);             \
  template HybridForm<T> hybrid_elevate(const HybridForm<T>&);                                              \
  template HybridForm<T> hybrid_insert(const HybridForm<T>&, const T&, const T&, const T&);                 \
  template HybridPatch<T> hybrid_elevate_salvi(const HybridPatch<T>&);
SPLINEX_INSTANTIATE_HYBRID(double)
SPLINEX_INSTANTIATE_HYBRID(Mpfr)
}  // namespace splinex
