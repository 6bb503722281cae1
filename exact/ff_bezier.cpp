// Fraction-free clamping, slicing and Bezier form (exact/ffnet.hpp), mirroring
// spline/insert_impl.hpp's clamp and spline/bezier_impl.hpp step for step.
#include "exact/ff_common.hpp"

namespace splinex::ff {

using namespace detail;

bool detail::is_clamped(const FFKnots& U, int p, std::size_t n) {
  for (int i = 0; i < p; ++i)
    if (cmp(U.k + i, U.k + p) != 0 || cmp(U.k + n + 1 + i, U.k + n) != 0) return false;
  return true;
}

std::vector<std::size_t> detail::breakpoints(const FFKnots& U, int p, std::size_t n) {
  std::vector<std::size_t> b;
  for (std::size_t i = p; i <= n; ++i)
    if (b.empty() || cmp(U.k + b.back(), U.k + i) < 0) b.push_back(i);
  return b;
}

FFNet detail::slice_direction(const FFNet& F, int d, std::size_t first, std::size_t n_new, FFKnots V) {
  const Layout f = layout(F, d);
  const std::size_t ps = f.before * F.stride();
  FFNet R;
  R.degrees = F.degrees;
  R.q = F.q;
  R.rational = F.rational;
  normalize(V);  // the knots cut away may have carried the denominator's factors
  for (int e = 0; e < F.dim(); ++e)  // (not a conditional: its const branch would copy V)
    if (e == d) R.knots.push_back(std::move(V));
    else R.knots.push_back(F.knots[e]);
  R.words = ZVec(f.after * n_new * ps);
  for (std::size_t b = 0; b < f.after; ++b)
    init_copy(R.words + b * n_new * ps, F.words + (b * f.n + first) * ps, n_new * ps);
  return R;
}

FFNet clamp(const FFNet& F, int d, const Limits& limits) {
  check_direction(F, d);
  const int p = F.degrees[d];
  if (is_clamped(F.knots[d], p, F.count(d))) return F;
  /// Raise the multiplicity of both domain ends to p+1 by insertion, then cut.
  Z lo, hi;
  fmpz_set(lo.get(), F.knots[d].k + p);
  fmpz_set(hi.get(), F.knots[d].k + F.count(d));
  FFNet R = F;
  for (const Z* e : {&lo, &hi}) {
    const std::size_t mult = multiplicity(R.knots[d], e->get());
    if (mult < static_cast<std::size_t>(p) + 1)
      R = insert_on(R, d, R.knots[d], e->get(), static_cast<int>(p + 1 - mult), limits);
  }
  const FFKnots& U = R.knots[d];
  std::size_t first = 0;
  while (cmp(U.k + first, lo.get()) < 0) ++first;  // first index of lo's run
  std::size_t last = U.size() - 1;
  while (cmp(hi.get(), U.k + last) < 0) --last;    // last index of hi's run
  const std::size_t n_new = (last - first + 1) - p - 1;
  FFKnots V;
  V.k = ZVec(last - first + 1);
  init_copy(V.k.data(), U.k + first, last - first + 1);
  fmpz_set(V.den.data(), U.den.data());
  return slice_direction(R, d, first, n_new, std::move(V));
}

namespace {

/// Every interior breakpoint of direction d raised to multiplicity p (clamped first).
FFNet to_bezier_form(const FFNet& S, int d, const Limits& limits) {
  if (!is_clamped(S.knots[d], S.degrees[d], S.count(d))) return to_bezier_form(clamp(S, d, limits), d, limits);
  const int p = S.degrees[d];
  const FFKnots& U = S.knots[d];
  const std::size_t n = S.count(d);
  std::vector<Z> X;
  for (std::size_t i = static_cast<std::size_t>(p) + 1; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && cmp(U.k + j + 1, U.k + i) == 0) ++j;
    for (std::size_t r = j - i + 1; r < static_cast<std::size_t>(p); ++r) {
      X.emplace_back();
      fmpz_set(X.back().get(), U.k + i);
    }
    i = j + 1;
  }
  if (X.empty()) return S;
  return refine_on(S, d, U, X, limits);
}

}  // namespace

FFBezierForm bezier_form(const FFNet& F, const Limits& limits) {
  /// The whole result's size, checked before any work (spline/bezier_impl.hpp).
  std::size_t total = 1;
  for (int d = 0; d < F.dim(); ++d) {
    const std::size_t segs = breakpoints(F.knots[d], F.degrees[d], F.count(d)).size() - 1;
    total = checked_product(total, checked_product(segs, static_cast<std::size_t>(F.degrees[d]) + 1, limits, "pieces"),
                            limits, "pieces");
  }
  FFBezierForm B;
  B.spline = to_bezier_form(F, 0, limits);
  for (int d = 1; d < F.dim(); ++d) B.spline = to_bezier_form(B.spline, d, limits);
  for (int d = 0; d < F.dim(); ++d) {
    const FFKnots& U = B.spline.knots[d];
    const int p = B.spline.degrees[d];
    const std::size_t n = B.spline.count(d);
    const std::vector<std::size_t> bp = breakpoints(U, p, n);
    ZVec br(bp.size());
    for (std::size_t s = 0; s < bp.size(); ++s) fmpz_set(br + s, U.k + bp[s]);
    /// segment_starts: the first control point of the piece on [bp[s], bp[s+1]).
    std::vector<std::size_t> first;
    std::size_t span = static_cast<std::size_t>(p);
    for (std::size_t s = 0; s + 1 < bp.size(); ++s) {
      while (span + 1 < n && !(cmp(br + s, U.k + span + 1) < 0)) ++span;
      first.push_back(span - static_cast<std::size_t>(p));
    }
    B.breaks.push_back(std::move(br));
    B.first.push_back(std::move(first));
  }
  return B;
}

std::size_t FFBezierForm::size() const {
  std::size_t k = 1;
  for (const auto& f : first) k *= f.size();
  return k;
}

std::vector<std::vector<Rational>> FFBezierForm::break_values() const {
  std::vector<std::vector<Rational>> out;
  for (std::size_t d = 0; d < breaks.size(); ++d) {
    std::vector<Rational> v;
    Rational den;
    fmpz_get_mpz(mpq_numref(den.backend().data()), spline.knots[d].den.data());
    for (std::size_t s = 0; s < breaks[d].size(); ++s) {
      Rational x;
      fmpz_get_mpz(mpq_numref(x.backend().data()), breaks[d] + s);
      v.push_back(x / den);
    }
    out.push_back(std::move(v));
  }
  return out;
}

FFNet FFBezierForm::piece(std::size_t k) const {
  const int dim = spline.dim();
  FFNet R;
  R.degrees = spline.degrees;
  R.q = spline.q;
  R.rational = spline.rational;
  R.knots.resize(static_cast<std::size_t>(dim));
  std::size_t rest = k, offset = 0, stride = 1, local = 1;
  std::vector<std::size_t> strides(static_cast<std::size_t>(dim));
  for (int d = 0; d < dim; ++d) {
    const std::size_t segs = first[d].size(), s = rest % segs;
    rest /= segs;
    const std::size_t p1 = static_cast<std::size_t>(spline.degrees[d]) + 1;
    FFKnots& V = R.knots[d];
    V.k = ZVec(2 * p1);
    for (std::size_t j = 0; j < p1; ++j) {
      fmpz_set(V.k + j, breaks[d] + s);
      fmpz_set(V.k + p1 + j, breaks[d] + s + 1);
    }
    fmpz_set(V.den.data(), spline.knots[d].den.data());
    normalize(V);
    strides[d] = stride;
    offset += first[d][s] * stride;
    stride *= spline.count(d);
    local *= p1;
  }
  const std::size_t w = spline.stride(), row = static_cast<std::size_t>(spline.degrees[0] + 1), rows = local / row;
  R.words = ZVec(local * w);
  for (std::size_t r = 0; r < rows; ++r) {
    std::size_t at = offset, rr = r;
    for (int d = 1; d < dim; ++d) {
      const std::size_t m = static_cast<std::size_t>(spline.degrees[d] + 1);
      at += (rr % m) * strides[d];
      rr /= m;
    }
    init_copy(R.words + r * row * w, spline.words + at * w, row * w);
  }
  return R;
}

std::vector<FFNet> extract_bezier(const FFNet& F, const Limits& limits) {
  const FFBezierForm B = bezier_form(F, limits);
  std::vector<FFNet> pieces;
  const std::size_t k = B.size();
  pieces.reserve(k);
  for (std::size_t i = 0; i < k; ++i) pieces.push_back(B.piece(i));
  return pieces;
}

}  // namespace splinex::ff
