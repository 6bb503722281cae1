#pragma once
#include "crosscheck/operations.hpp"
#include "float/rounding.hpp"
#include "spline/hodograph.hpp"

namespace splinex {

template <class T>
std::vector<BSpline<T>> run_operation(const Operation& op, const BSpline<T>& S, const Limits& limits) {
  switch (op.kind) {
    case Operation::Kind::insert_knots: {
      const std::vector<T> X = round_values<T>(op.knots, "knots");
      if (!op.boehm) return {refine_knots(S, op.dir, X, limits)};
      return {insert_knots_boehm(S, op.dir, X, limits)};
    }
    case Operation::Kind::elevate: {
      return {elevate_degree(S, op.dir, op.by, op.method, limits)};
    }
    case Operation::Kind::extract_bezier: {
      std::vector<BSpline<T>> out;
      for (auto& pc : extract_bezier(S, limits)) out.push_back(std::move(pc.spline));
      return out;
    }
    case Operation::Kind::split: {
      auto [L, R] = split_at(S, op.dir, round_checked<T>(op.at, "at"), limits);
      return {L, R};
    }
    case Operation::Kind::reparametrize: return {reparametrize(S, op.dir, round_checked<T>(op.lo, "interval[0]"), round_checked<T>(op.hi, "interval[1]"))};
    case Operation::Kind::reverse: return {reverse(S, op.dir)};
    case Operation::Kind::derivative: {  // the derivative as a spline (hodograph), `by` times
      if (op.by < 1) throw UsageError("by", "the order of the derivative must be at least 1", "give --by 1, 2, ...");
      BSpline<T> D = S;
      for (int k = 0; k < op.by; ++k) D = hodograph(D, op.dir);
      return {D};
    }
    case Operation::Kind::identity: break;
  }
  return {S};
}

}  // namespace splinex
