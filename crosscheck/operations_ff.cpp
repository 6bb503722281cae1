#include "crosscheck/operations_ff.hpp"

namespace splinex {

bool runs_fraction_free(const Operation& op) {
  switch (op.kind) {
    case Operation::Kind::insert_knots: return !op.boehm;
    case Operation::Kind::elevate: return op.method != ElevationMethod::blossom;
    case Operation::Kind::extract_bezier:
    case Operation::Kind::identity: return true;
    default: return false;
  }
}

std::optional<std::vector<ff::FFNet>> run_operation_ff(const Operation& op, const ff::FFNet& F, const Limits& limits) {
  if (!runs_fraction_free(op)) return std::nullopt;
  switch (op.kind) {
    case Operation::Kind::insert_knots: return std::vector<ff::FFNet>{ff::refine_knots(F, op.dir, op.knots, limits)};
    case Operation::Kind::elevate: return std::vector<ff::FFNet>{ff::elevate_degree(F, op.dir, op.by, limits)};
    case Operation::Kind::extract_bezier: return ff::extract_bezier(F, limits);
    default: return std::vector<ff::FFNet>{F};
  }
}

std::vector<BSpline<Rational>> run_operation_exact(const Operation& op, const BSpline<Rational>& S, const Limits& limits) {
  if (!runs_fraction_free(op)) return run_operation(op, S, limits);
  const auto results = run_operation_ff(op, ff::from_bspline(S), limits);  // kept alive: the loop reads it
  std::vector<BSpline<Rational>> out;
  for (const auto& R : *results) out.push_back(ff::to_bspline(R));
  return out;
}

std::vector<BezierPiece<Rational>> extract_bezier_exact(const BSpline<Rational>& S, const Limits& limits) {
  const ff::FFBezierForm B = ff::bezier_form(ff::from_bspline(S), limits);
  const auto breaks = B.break_values();
  std::vector<BezierPiece<Rational>> out;
  const std::size_t k = B.size();
  out.reserve(k);
  for (std::size_t i = 0; i < k; ++i) {
    BezierPiece<Rational> P;
    P.spline = ff::to_bspline(B.piece(i));
    std::size_t rest = i;
    for (std::size_t d = 0; d < breaks.size(); ++d) {
      const std::size_t segs = B.first[d].size(), s = rest % segs;
      rest /= segs;
      P.box.emplace_back(breaks[d][s], breaks[d][s + 1]);
    }
    out.push_back(std::move(P));
  }
  return out;
}

std::vector<Rational> evaluate_exact(const BSpline<Rational>& S, const std::vector<Rational>& x) {
  if (x.size() != static_cast<std::size_t>(S.dim()))
    throw DomainError("at", "has " + std::to_string(x.size()) + " coordinates for a spline of dimension " +
                                std::to_string(S.dim()),
                      "give one parameter per direction");
  for (int d = 0; d < S.dim(); ++d)
    if (x[d] < S.domain_lo(d) || S.domain_hi(d) < x[d])
      throw DomainError("at[" + std::to_string(d) + "]", "lies outside the domain of direction " + std::to_string(d),
                        "give a parameter in [U[p], U[n]] of that direction");
  return ff::to_points(ff::evaluate_points(ff::from_bspline(S), x));
}

}  // namespace splinex
