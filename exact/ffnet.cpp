// The fraction-free net's storage and its exact conversions (exact/ffnet.hpp).
#include "exact/ffnet.hpp"

#include <gmp.h>

#include <cstdlib>
#include <cstring>
#include <new>

#include "exact/ff_int.hpp"

namespace splinex::ff {

using detail::small;

namespace {
fmpz* allocate(std::size_t n) {
  if (n == 0) return nullptr;
  void* p = std::calloc(n, sizeof(fmpz));  // zero words are the value 0
  if (!p) throw std::bad_alloc();
  return static_cast<fmpz*>(p);
}
void release(fmpz* p, std::size_t n, bool known_small) {
  if (!p) return;
  if (!known_small && detail::any_big(p, n))
    for (std::size_t i = 0; i < n; ++i)
      if (!small(p + i)) fmpz_clear(p + i);
  std::free(p);
}
}  // namespace

ZVec::ZVec(std::size_t n) : p_(allocate(n)), n_(n) {}

ZVec::ZVec(const ZVec& o) : n_(o.n_) {
  if (n_ == 0) return;
  p_ = static_cast<fmpz*>(std::malloc(n_ * sizeof(fmpz)));
  if (!p_) throw std::bad_alloc();
  try {
    known_small_ = !detail::init_copy(p_, o.p_, n_);
  } catch (...) {
    release(p_, n_, false);  // every word is 0 or a valid value (init_copy)
    throw;
  }
}

ZVec& ZVec::operator=(const ZVec& o) {
  if (this != &o) {
    ZVec t(o);
    *this = std::move(t);
  }
  return *this;
}

ZVec& ZVec::operator=(ZVec&& o) noexcept {
  if (this != &o) {
    release(p_, n_, known_small_);
    p_ = o.p_;
    n_ = o.n_;
    known_small_ = o.known_small_;
    o.p_ = nullptr;
    o.n_ = 0;
  }
  return *this;
}

ZVec::~ZVec() { release(p_, n_, known_small_); }

std::size_t ZVec::heap_bytes() const {
  std::size_t b = n_ * sizeof(fmpz);
  for (std::size_t i = 0; i < n_; ++i)
    if (!small(p_ + i)) b += sizeof(__mpz_struct) + fmpz_size(p_ + i) * sizeof(mp_limb_t);
  return b;
}

bool ZVec::operator==(const ZVec& o) const {
  if (n_ != o.n_) return false;
  for (std::size_t i = 0; i < n_; ++i)
    if (detail::cmp(p_ + i, o.p_ + i) != 0) return false;
  return true;
}

std::size_t FFNet::size() const {
  std::size_t s = 1;
  for (int d = 0; d < dim(); ++d) s *= count(d);
  return s;
}

namespace {

const __mpq_struct* mpq(const Rational& x) { return x.backend().data(); }

/// num/den as a canonical Rational (den != 0).
Rational quotient(const fmpz* num, const fmpz* den) {
  Rational r;
  mpq_ptr q = r.backend().data();
  fmpz_get_mpz(mpq_numref(q), num);
  fmpz_get_mpz(mpq_denref(q), den);
  mpq_canonicalize(q);
  return r;
}

FFKnots knots_from(const std::vector<Rational>& U) {
  FFKnots K;
  K.k = ZVec(U.size());
  detail::Z num, t;
  fmpz_one(K.den.data());
  for (const Rational& u : U) {
    fmpz_set_mpz(t.get(), mpq_denref(mpq(u)));
    fmpz_lcm(K.den.data(), K.den.data(), t.get());
  }
  for (std::size_t j = 0; j < U.size(); ++j) {
    fmpz_set_mpz(t.get(), mpq_denref(mpq(U[j])));
    fmpz_divexact(t.get(), K.den.data(), t.get());
    fmpz_set_mpz(num.get(), mpq_numref(mpq(U[j])));
    fmpz_mul(K.k + j, num.get(), t.get());
  }
  return K;
}

}  // namespace

FFNet from_bspline(const BSpline<Rational>& S) {
  FFNet F;
  F.degrees = S.degrees;
  F.q = S.q;
  F.rational = S.is_rational();
  for (const auto& U : S.knots) F.knots.push_back(knots_from(U));
  const std::size_t n = S.size(), m = F.m(), w = F.stride();
  F.words = ZVec(n * w);
  std::vector<Rational> h(m);
  detail::Z tz;
  fmpz* t = tz.get();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < static_cast<std::size_t>(S.q); ++c)
      h[c] = F.rational ? Rational(S.points[i * S.q + c] * S.weights[i]) : S.points[i * S.q + c];
    if (F.rational) h[m - 1] = S.weights[i];
    fmpz* p = F.words + i * w;
    fmpz_one(p + m);
    for (const Rational& v : h) {
      fmpz_set_mpz(t, mpq_denref(mpq(v)));
      fmpz_lcm(p + m, p + m, t);
    }
    for (std::size_t c = 0; c < m; ++c) {
      fmpz_set_mpz(t, mpq_denref(mpq(h[c])));
      fmpz_divexact(t, p + m, t);
      fmpz_set_mpz(p + c, mpq_numref(mpq(h[c])));
      fmpz_mul(p + c, p + c, t);
    }
  }
  return F;
}

BSpline<Rational> to_bspline(const FFNet& F) {
  BSpline<Rational> S;
  S.degrees = F.degrees;
  S.q = F.q;
  for (const auto& K : F.knots) {
    std::vector<Rational> U;
    U.reserve(K.size());
    for (std::size_t j = 0; j < K.size(); ++j) U.push_back(quotient(K.k + j, K.den.data()));
    S.knots.push_back(std::move(U));
  }
  const std::size_t n = F.size(), m = F.m(), w = F.stride(), q = F.q;
  S.points.reserve(n * q);
  if (F.rational) S.weights.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const fmpz* p = F.words + i * w;
    if (F.rational && fmpz_sgn(p + q) <= 0)
      throw ValidationError("weights[" + std::to_string(i) + "]", "became non-positive in the homogeneous form",
                            "use positive weights");
    for (std::size_t c = 0; c < q; ++c) S.points.push_back(quotient(p + c, F.rational ? p + q : p + m));
    if (F.rational) S.weights.push_back(quotient(p + q, p + m));
  }
  return S;
}

std::vector<Rational> to_points(const FFPoints& P) {
  const std::size_t q = P.q, m = q + (P.rational ? 1 : 0), w = m + 1;
  const std::size_t n = P.words.size() / w;
  std::vector<Rational> out;
  out.reserve(n * q);
  for (std::size_t i = 0; i < n; ++i) {
    const fmpz* p = P.words + i * w;
    for (std::size_t c = 0; c < q; ++c) out.push_back(quotient(p + c, P.rational ? p + q : p + m));
  }
  return out;
}

bool same_value(const FFNet& A, const FFNet& B) {
  if (A.degrees != B.degrees || A.q != B.q || A.rational != B.rational || A.knots.size() != B.knots.size()) return false;
  for (std::size_t d = 0; d < A.knots.size(); ++d)
    if (!(A.knots[d].k == B.knots[d].k) || !(A.knots[d].den == B.knots[d].den)) return false;
  if (A.words.size() != B.words.size()) return false;
  /// Points are not stored reduced: N_A / E_A == N_B / E_B by cross-multiplication.
  const std::size_t m = A.m(), w = A.stride();
  detail::Z xz, yz;
  fmpz* x = xz.get();
  fmpz* y = yz.get();
  bool same = true;
  for (std::size_t i = 0; same && i < A.size(); ++i) {
    const fmpz* a = A.words + i * w;
    const fmpz* b = B.words + i * w;
    for (std::size_t c = 0; same && c < m; ++c) {
      fmpz_mul(x, a + c, b + m);
      fmpz_mul(y, b + c, a + m);
      same = fmpz_equal(x, y);
    }
  }
  return same;
}

std::size_t heap_bytes(const FFNet& F) {
  std::size_t b = F.words.heap_bytes();
  for (const auto& K : F.knots) b += K.k.heap_bytes() + K.den.heap_bytes();
  return b;
}

}  // namespace splinex::ff
