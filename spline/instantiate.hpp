// Explicit instantiation of the B-spline kernel for one scalar type. Included once per standard
// arithmetic by exact/ and float/, so client code compiles against declarations only
// (composition instantiates itself in compose/instances_exact.cpp and instances_float.cpp).
#pragma once
#include "spline/bezier_impl.hpp"
#include "spline/elevate_impl.hpp"
#include "spline/evaluate_impl.hpp"
#include "spline/insert_impl.hpp"
#include "spline/integrate_impl.hpp"

#define SPLINEX_INSTANTIATE_KERNEL(T)                                                                           \
  template std::vector<T> evaluate(const BSpline<T>&, const std::vector<T>&);                                  \
  template std::vector<T> evaluate_de_boor(const BSpline<T>&, const std::vector<T>&);                         \
  template std::vector<T> evaluate_points(const BSpline<T>&, const std::vector<T>&);                          \
  template std::vector<T> evaluate_homogeneous(const BSpline<T>&, const std::vector<T>&);                      \
  template std::vector<T> basis_sum(const BSpline<T>&, const std::vector<std::size_t>&,                        \
                                    const std::vector<const std::vector<T>*>&);                                \
  template std::vector<T> derivative(const BSpline<T>&, const std::vector<T>&, const std::vector<int>&);        \
  template BSpline<T> insert_knot(const BSpline<T>&, int, const T&, int, const Limits&);                       \
  template BSpline<T> refine_knots(const BSpline<T>&, int, std::vector<T>, const Limits&);                     \
  template BSpline<T> insert_knots_boehm(const BSpline<T>&, int, const std::vector<T>&, const Limits&);        \
  template BSpline<T> clamp(const BSpline<T>&, int, const Limits&);                                            \
  template BSpline<T> clamp_all(const BSpline<T>&, const Limits&);                                             \
  template BSpline<T> elevate_degree(const BSpline<T>&, int, int, ElevationMethod, const Limits&);             \
  template std::size_t elevated_count(const BSpline<T>&, int, int);                                            \
  template std::vector<BezierPiece<T>> extract_bezier(const BSpline<T>&, const Limits&);                       \
  template struct BezierForm<T>;                                                                                \
  template BezierForm<T> bezier_form(const BSpline<T>&, const Limits&);                                        \
  template std::size_t bezier_pieces_size(const BSpline<T>&, const Limits&);                                   \
  template std::pair<BSpline<T>, BSpline<T>> split_at(const BSpline<T>&, int, const T&, const Limits&);        \
  template BSpline<T> reparametrize(const BSpline<T>&, int, const T&, const T&);                               \
  template BSpline<T> reverse(const BSpline<T>&, int);                                                         \
  template std::vector<T> integrate(const BSpline<T>&);                                                         \
  template BSpline<T> difference(const BSpline<T>&, const BSpline<T>&, const Limits&);                          \
  template std::pair<BSpline<T>, BSpline<T>> make_compatible(const BSpline<T>&, const BSpline<T>&, const Limits&); \
  template struct AbsIntegral<T>;                                                                               \
  template AbsIntegral<T> integrate_abs(const BSpline<T>&, int, const T&);
