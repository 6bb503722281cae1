// Exact dense linear systems, solved by FLINT (fmpq_mat_solve_dixon: p-adic lifting with
// rational reconstruction; far faster than Gauss-Jordan on mpq for the hundreds
// of unknowns of a KKT system).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "exact/rational.hpp"

namespace splinex {

/// X with A X = B: A is n x n (row-major), B n x k (row-major); X n x k. nullopt when A is singular.
std::optional<std::vector<Rational>> solve_linear_exact(const std::vector<Rational>& A, std::size_t n, const std::vector<Rational>& B,
                                                        std::size_t k);

/// The rank of the r x c matrix A (row-major), exactly (FLINT).
std::size_t exact_rank(const std::vector<Rational>& A, std::size_t r, std::size_t c);

}  // namespace splinex
