// The checks a trivariate passes before it is a cell of a freeform solid (vrep/freeform/freeform.hpp,
// "Validity"): the numbers' length against Limits::max_input_bits, the kernel's Jacobian input
// rules, clamped knots, positive weights, and det J of one sign - a fold seen on a 5 x 5 x 5 grid
// per piece (two exact values), then in exact arithmetic the certificate certify_cell_shape.
// Private to vrep/freeform/ (included by freeform.cpp).
#pragma once
#include <algorithm>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "base/errors.hpp"
#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "spline/bezier.hpp"
#include "spline/knots.hpp"
#include "vrep/model/regularity_impl.hpp"
#include "vrep/model/validate.hpp"

namespace splinex::vrep_detail {

/// A cell that folds (det J takes both strict signs) is not a solid whose boundary is its faces:
/// det J's numerator is evaluated exactly on a 5 x 5 x 5 grid of every Bezier piece (the piece's
/// corners among them) and two values of opposite strict signs are a certified fold. A fold
/// between the grid points is not excluded (injectivity is assumed, as papers/002 assumes valid
/// V-cells); det J = 0 alone (a face collapsed to a curve or a point) is allowed.
template <class T>
void require_no_fold(const BSpline<T>& V, const std::string& name, const Limits& limits) {
  const BezierForm<T> F = bezier_form(V, limits);
  int seen = 0;  // bit 0: a positive value, bit 1: a negative one
  std::vector<T> first[2];
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    const Bernstein<T> N = vrep_detail::jacobian_numerator(pc.spline);
    for (int i = 0; i < 125; ++i) {
      const std::vector<T> x{T(i % 5) / T(4), T((i / 5) % 5) / T(4), T(i / 25) / T(4)};
      const T v = bern_value(N, x);
      const int sg = T(0) < v ? 1 : v < T(0) ? 2 : 0;
      if (!sg) continue;
      if (first[sg - 1].empty())
        for (int d = 0; d < 3; ++d) first[sg - 1].push_back(pc.box[d].first + x[d] * (pc.box[d].second - pc.box[d].first));
      seen |= sg;
    }
  }
  if (seen == 3) {
    auto text = [](const std::vector<T>& p) {
      std::ostringstream o;
      o << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
      return o.str();
    };
    throw DomainError(name, "folds: det J is positive at " + text(first[0]) + " and negative at " + text(first[1]) +
                                " (exact values), so its faces are not its boundary",
                      "give a valid trivariate (det J of one sign)");
  }
}

/// Every number of V against Limits::max_input_bits (exact arithmetic: the work below grows with
/// the numbers' length); called for every cell of a solid before any cell's work.
template <class T>
void require_short_numbers(const BSpline<T>& V, const std::string& name, const Limits& limits) {
  if constexpr (std::is_same_v<T, Rational>) {
    auto bits = [&](const std::vector<T>& v, const std::string& field) {
      for (const auto& x : v) limits.check_bits(bit_size(x), name + "." + field);
    };
    for (std::size_t d = 0; d < V.knots.size(); ++d) bits(V.knots[d], "knots[" + std::to_string(d) + "]");
    bits(V.points, "points");
    bits(V.weights, "weights");
  }
}

/// The rest of the checks, on numbers require_short_numbers has passed.
template <class T>
void require_valid_shape(const BSpline<T>& V, const std::string& name, const Limits& limits) {
  try {
    vrep_detail::require_jacobian_input(V, limits);
  } catch (const ValidationError& e) {
    throw ValidationError(name, e.what(), "");
  }
  for (int d = 0; d < 3; ++d)
    if (!is_clamped(V.knots[d], V.degrees[d], V.count(d)))
      throw ValidationError(name + ".knots[" + std::to_string(d) + "]", "is not clamped: its faces are not layers of the net",
                            "clamp the trivariate first");
  if (V.is_rational())
    for (const auto& w : V.weights)
      if (!(T(0) < w)) throw DomainError(name + ".weights", "has a weight that is not positive", "give positive weights");
  if constexpr (!std::is_floating_point_v<T>) require_no_fold(V, name, limits);  // in double a rounded 0 would fake a fold
  if constexpr (std::is_same_v<T, Rational>) {
    // The grid refutes folds it happens to see; the certificate covers the rest: det J of one
    // sign everywhere (regular, or degenerate with zeros on the domain's boundary only: collapsed
    // faces), a fold or a zero inside refuted (DomainError, as the grid's), or undecided within its levels,
    // which is refused too: the cells' kinds and enclosures below assume a valid cell.
    CellShape shape;
    try {
      shape = certify_cell_shape(V, name, ValidityOptions{}.levels, limits);
    } catch (const ValidationError& e) {  // a fold or a zero inside: the grid's error type (DomainError)
      const std::string text = e.what();
      throw DomainError(e.field(), text.substr(std::min(text.size(), e.field().size() + 2)), "");
    }
    if (!shape.valid.is_proved())
      throw DomainError(name, "det J's sign is not certified within " + std::to_string(ValidityOptions{}.levels) +
                                  " subdivision levels (" + shape.valid.reason() + "), so the cell may fold",
                        "give a valid trivariate (det J of one sign; `splinex vrep certify` shows its sign by boxes)");
  }
}

/// Every check, for a single trivariate (freeform_cell, freeform_edges).
template <class T>
void require_cell(const BSpline<T>& V, const std::string& name, const Limits& limits) {
  require_short_numbers(V, name, limits);
  require_valid_shape(V, name, limits);
}

}  // namespace splinex::vrep_detail
