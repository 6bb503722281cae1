// The kernel operations in the arithmetic "exact" (float/arith_spec.hpp): on the fraction-free net
// (exact/ffnet.hpp) where the operation is written for it, on GMP mpq otherwise. The values are the
// same either way; only the cost differs. Converted at the boundary, so the results are the GMP
// kernel's types and print as its documents do.
#pragma once
#include <optional>
#include <vector>

#include "crosscheck/operations.hpp"
#include "exact/ffnet.hpp"

namespace splinex {

/// Whether `op` runs on the fraction-free net: insert-knots by A5.4, elevate by A5.9 (method
/// auto or a59), extract-bezier and identity. Boehm's insertion, the blossom elevation, split,
/// reparametrize, reverse and derivative run on GMP mpq (not written fraction-free yet).
bool runs_fraction_free(const Operation& op);

/// The operation on the fraction-free net; nullopt where !runs_fraction_free(op).
std::optional<std::vector<ff::FFNet>> run_operation_ff(const Operation& op, const ff::FFNet& F, const Limits& limits);

/// run_operation in "exact": the same results, errors and limits as run_operation<Rational>.
std::vector<BSpline<Rational>> run_operation_exact(const Operation& op, const BSpline<Rational>& S, const Limits& limits);

/// extract_bezier in "exact", with the pieces' boxes.
std::vector<BezierPiece<Rational>> extract_bezier_exact(const BSpline<Rational>& S, const Limits& limits);

/// evaluate (values; basis functions or de Boor alike, the values are exact) in "exact": the
/// kernel's checks and fields ("at").
std::vector<Rational> evaluate_exact(const BSpline<Rational>& S, const std::vector<Rational>& x);

}  // namespace splinex
