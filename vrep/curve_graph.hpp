// The certified graph of a curve given by N - 1 polynomial equations in N unknowns (N = 2: a
// trimming surface's trace on a face of a trivariate's domain; N = 3: two trimming surfaces
// meeting inside it), restricted to where a region's formula depends on all of them: its arcs and
// closed loops, cut at the points where a further leaf crosses (vrep/trimmed.hpp: trimmed_curves
// describes the method; vrep/trimmed_curves.cpp implements it). Internal to vrep.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "spline/tensor_bernstein.hpp"
#include "vrep/trimmed.hpp"

namespace splinex::vrep_detail {

/// The leaves of a region in Bernstein form on one box of the domain (a Bezier piece of V, or its
/// face), with the box.
template <class T, std::size_t N>
struct CurvePiece {
  std::vector<detail::Bern<T>> G;  // per leaf (collect order)
  std::array<T, N> lo, hi;
};

template <class T, std::size_t N>
struct CurveProblem {
  const Region<T>* trim = nullptr;
  std::vector<CurvePiece<T, N>> pieces;        // together they tile the domain [dom_lo, dom_hi]
  std::array<T, N> dom_lo, dom_hi;
  std::array<std::array<bool, 2>, N> identified{};  // facets of the domain V identifies with others or collapses
  std::vector<std::size_t> curve;              // the N - 1 leaves whose common zero set is the curve
  CurveOptions options;
};

/// The counts, or the reason they are undecided.
struct CurveCount {
  bool decided = false;
  std::size_t arcs = 0, loops = 0;
  std::size_t ends_on_facets = 0, ends_at_points = 0, ends_on_identified = 0;
  std::size_t boxes = 0, crossings = 0;  // of the deciding attempt
  std::size_t spent = 0;                  // boxes over all attempts
  int split_fraction = 0;                 // index for split_fraction<T>() below
  std::string undecided_reason;
};

/// The split fractions tried in turn: 1/2, 7/16, 13/32 (index 0, 1, 2).
template <class T>
T split_fraction(int index) {
  return index == 0 ? T(1) / T(2) : index == 1 ? T(7) / T(16) : T(13) / T(32);
}

/// Runs the subdivision at the split fractions 1/2, 7/16, 13/32 until one decides.
template <class T, std::size_t N>
CurveCount count_curve(const CurveProblem<T, N>& problem);

/// G / t_d (side 0) or G / (1 - t_d) (side 1), for G vanishing identically on that facet: the
/// same signs inside the box.
template <class T>
detail::Bern<T> divide_facet(const detail::Bern<T>& G, int d, int side);

}  // namespace splinex::vrep_detail
