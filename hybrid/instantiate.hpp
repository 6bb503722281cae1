// Explicit instantiation of the hybrid patch and its form for one scalar type
// (hybrid/instances.cpp; tests/spline/test_arith_concept.cpp).
#pragma once
#include "hybrid/form_impl.hpp"

#define SPLINEX_INSTANTIATE_HYBRID(T)                                                                              \
  template HybridLocal<T> hybrid_local(const HybridPatch<T>&, const Point2<T>&);                            \
  template std::vector<T> hybrid_evaluate(const HybridPatch<T>&, const Point2<T>&);                         \
  template std::vector<T> hybrid_boundary(const HybridPatch<T>&, std::size_t, const T&);                           \
  template std::vector<T> hybrid_cross_tangent(const HybridPatch<T>&, std::size_t, const T&);                      \
  template void validate(const HybridPatch<T>&);                                                                   \
  template HybridJet<T> hybrid_jet(const HybridPatch<T>&, const Point2<T>&, const Point2<T>&);         \
  template HybridDerivatives<T> hybrid_derivatives(const HybridPatch<T>&, const Point2<T>&);                 \
  template HybridCrossDerivative<T> hybrid_cross_derivative(const HybridPatch<T>&, std::size_t,                    \
                                                            const Point2<T>&);                              \
  template HybridForm<T> hybrid_form(const HybridPatch<T>&);                                                       \
  template std::vector<T> hybrid_form_evaluate(const HybridForm<T>&, const Point2<T>&);                    \
  template std::vector<T> hybrid_form_interior(const HybridFormSide<T>&, int, const T&, const T&);                 \
  template std::vector<T> hybrid_form_ribbon(const HybridFormSide<T>&, int, const T&, const T&);                   \
  template std::pair<std::vector<T>, std::vector<T>> cls_elevate(int, const std::vector<T>&, const std::vector<T>&, \
                                                                 int);                                             \
  template HybridForm<T> hybrid_elevate(const HybridForm<T>&);                                                     \
  template HybridForm<T> hybrid_insert(const HybridForm<T>&, const T&, const T&, const T&);                        \
  template HybridPatch<T> hybrid_elevate_salvi(const HybridPatch<T>&);
