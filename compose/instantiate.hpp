// Explicit instantiation of composition for one scalar type (compose/instances_*.cpp).
#pragma once
#include "compose/compose_impl.hpp"
#include "compose/trimmed_compose_impl.hpp"

#define SPLINEX_INSTANTIATE_COMPOSE(T)                                                                            \
  template std::vector<int> composed_degrees(const BSpline<T>&, const BSpline<T>&);                              \
  template BSpline<T> compose_bezier(const BSpline<T>&, const BSpline<T>&, CompositionMethod, const Limits&);     \
  template std::vector<T> evaluate_bezier_anywhere(const BSpline<T>&, const std::vector<T>&);                    \
  template BSpline<T> compose(const BSpline<T>&, const BSpline<T>&, const CompositionOptions&, const Limits&);    \
  template std::size_t compose_least_size(const BSpline<T>&, const BSpline<T>&, const Limits&);                  \
  template Homogeneous<T> compose_bezier_homogeneous(const BSpline<T>&, const BSpline<T>&, CompositionMethod,      \
                                                     const Limits&);                                               \
  template std::vector<T> evaluate_patch(const TrimmedPatch<T>&, const std::vector<T>&);                          \
  template struct TrimmedComposition<T>;                                                                          \
  template TrimmedComposition<T> compose_trimmed(const BSpline<T>&, const BSpline<T>&, const TrimmedOptions&,     \
                                                 const Limits&);
