#include "exact/linear_solve.hpp"

#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include <stdexcept>

namespace splinex {

namespace {

struct Mat {
  fmpq_mat_t m;
  Mat(std::size_t r, std::size_t c) { fmpq_mat_init(m, static_cast<slong>(r), static_cast<slong>(c)); }
  ~Mat() { fmpq_mat_clear(m); }
  Mat(const Mat&) = delete;
  Mat& operator=(const Mat&) = delete;
};

void fill(Mat& M, const std::vector<Rational>& v, std::size_t rows, std::size_t cols) {
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) fmpq_set_mpq(fmpq_mat_entry(M.m, i, j), v[i * cols + j].backend().data());
}

}  // namespace

std::optional<std::vector<Rational>> solve_linear_exact(const std::vector<Rational>& A, std::size_t n, const std::vector<Rational>& B,
                                                        std::size_t k) {
  if (A.size() != n * n || B.size() != n * k) throw std::logic_error("solve_linear_exact: sizes");
  if (n == 0) return std::vector<Rational>{};
  Mat a(n, n), b(n, k), x(n, k);
  fill(a, A, n, n);
  fill(b, B, n, k);
  if (!fmpq_mat_solve_dixon(x.m, a.m, b.m)) return std::nullopt;
  std::vector<Rational> X(n * k);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j) fmpq_get_mpq(X[i * k + j].backend().data(), fmpq_mat_entry(x.m, i, j));
  return X;
}

std::size_t exact_rank(const std::vector<Rational>& A, std::size_t r, std::size_t c) {
  if (A.size() != r * c) throw std::logic_error("exact_rank: sizes");
  if (r == 0 || c == 0) return 0;
  Mat a(r, c);
  fill(a, A, r, c);
  // every row times its denominators' lcm: the same rank, in integers
  fmpz_mat_t z;
  fmpz_mat_init(z, static_cast<slong>(r), static_cast<slong>(c));
  fmpz* den = _fmpz_vec_init(static_cast<slong>(r));
  fmpq_mat_get_fmpz_mat_rowwise(z, den, a.m);
  const slong k = fmpz_mat_rank(z);
  _fmpz_vec_clear(den, static_cast<slong>(r));
  fmpz_mat_clear(z);
  return static_cast<std::size_t>(k);
}

}  // namespace splinex
