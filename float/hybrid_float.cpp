// The hybrid patch instantiated for double and MPFR.
#include "float/mpfr.hpp"
#include "spline/hybrid_impl.hpp"

namespace splinex {
#define SPLINEX_INSTANTIATE_HYBRID(T)                                                                       \
  template HybridLocal<T> hybrid_local(const HybridPatch<T>&, const std::array<T, 2>&);                     \
  template std::vector<T> hybrid_evaluate(const HybridPatch<T>&, const std::array<T, 2>&);                  \
  template std::vector<T> hybrid_boundary(const HybridPatch<T>&, std::size_t, const T&);                    \
  template std::vector<T> hybrid_cross_tangent(const HybridPatch<T>&, std::size_t, const T&);               \
  template void validate(const HybridPatch<T>&);
SPLINEX_INSTANTIATE_HYBRID(double)
SPLINEX_INSTANTIATE_HYBRID(Mpfr)
}  // namespace splinex
