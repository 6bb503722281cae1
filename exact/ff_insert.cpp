// Fraction-free knot insertion (exact/ffnet.hpp): A5.1 (one knot, r times) and A5.4 (many knots),
// mirroring spline/insert_impl.hpp step for step, with the same checks, errors and limits. Each
// new point is a blend of two old ones over (knot difference) * E, reduced once; the points that
// do not change are copied as words.
#include <algorithm>

#include "exact/ff_common.hpp"

namespace splinex::ff {

using namespace detail;

namespace {

/// spline/insert_impl.hpp's check_insertable on integer knots (the same errors and texts).
void check_insertable(const FFKnots& U, int p, std::size_t n, int d, const fmpz* x, std::size_t extra,
                      const std::string& field) {
  if (cmp(x, U.k + p) < 0 || cmp(U.k + n, x) < 0)
    throw DomainError(field, "knot lies outside the domain of direction " + std::to_string(d),
                      "insert knots inside [U[p], U[n]]");
  const std::size_t mult = multiplicity(U, x);
  if (mult + extra > static_cast<std::size_t>(p) + 1)
    throw ValidationError(field,
                          "inserting it would give multiplicity " + std::to_string(mult + extra) + " above degree+1 = " +
                              std::to_string(p + 1),
                          "insert it at most " + std::to_string(p + 1 - std::min<std::size_t>(mult, p + 1)) + " more times");
}

/// The net F with direction d's knots replaced by U (the same count of points).
FFNet with_knots(const FFNet& F, int d, FFKnots U, std::size_t new_count) {
  FFNet R;
  R.degrees = F.degrees;
  R.q = F.q;
  R.rational = F.rational;
  R.knots.reserve(F.knots.size());
  for (int e = 0; e < F.dim(); ++e)  // (not a conditional: its const branch would copy U)
    if (e == d) R.knots.push_back(std::move(U));
    else R.knots.push_back(F.knots[e]);
  R.words = ZVec(F.size() / F.count(d) * new_count * F.stride());
  return R;
}

/// A5.1 CurveKnotIns on every fibre of direction d: x (numerator over U.den) inserted r times into
/// span k where it has multiplicity s (s == p: the step from p to p+1, r = 1, repeats P_{k-p}).
FFNet knot_ins(const FFNet& F, int d, const FFKnots& U, const fmpz* x, std::size_t k, int s, int r) {
  const Layout f = layout(F, d);
  const int p = F.degrees[d];
  const std::size_t w = F.stride(), m = F.m(), ps = f.before * w, n = f.n;
  FFKnots V;
  V.k = ZVec(U.size() + r);
  fmpz_set(V.den.data(), U.den.data());
  bool big = init_copy(V.k.data(), U.k.data(), k + 1) || !small(x);
  for (int j = 0; j < r; ++j) fmpz_set(V.k + k + 1 + j, x);
  big = init_copy(V.k + k + 1 + r, U.k + k + 1, U.size() - k - 1) || big;
  if (!big) V.k.mark_small();  // every word was seen: the destructor need not look again
  FFNet R = with_knots(F, d, std::move(V), n + r);
  big = false;
  /// The blend coefficients alpha = s/t of the triangle, the same for every fibre.
  const std::size_t tri = s < p ? static_cast<std::size_t>(p - s) : 0;
  ZVec st(2 * r * tri);
  for (int j = 1; j <= r && s < p; ++j) {
    const std::size_t L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      fmpz* c = st + 2 * ((j - 1) * tri + i);
      sub(c, x, U.k + L + i);
      sub(c + 1, U.k + i + k + 1, U.k + L + i);
    }
  }
  ZVec Rw((p - s + 1) * w);
  Blend blend;
  for (std::size_t b = 0; b < f.after; ++b) {
    const fmpz* src = F.words + b * n * ps;
    fmpz* dst = R.words + b * (n + r) * ps;
    /// Q_i = P_i (i <= k-p) and Q_{i+r} = P_i (i >= k-s): two runs of words per fibre block.
    big = init_copy(dst, src, (k - p + 1) * ps) || big;
    big = init_copy(dst + (k - s + r) * ps, src + (k - s) * ps, (n - (k - s)) * ps) || big;
    if (s == p) continue;
    for (std::size_t a = 0; a < f.before; ++a) {
      auto P = [&](std::size_t i) { return src + i * ps + a * w; };
      auto Q = [&](std::size_t i) { return dst + i * ps + a * w; };
      auto put = [&](std::size_t i, const fmpz* from) {
        for (std::size_t c = 0; c < w; ++c) set(Q(i) + c, from + c);
        reduce_if_long(Q(i), m);
      };
      for (int i = 0; i <= p - s; ++i)
        for (std::size_t c = 0; c < w; ++c) set(Rw + i * w + c, P(k - p + i) + c);
      std::size_t L = 0;
      for (int j = 1; j <= r; ++j) {
        L = k - p + j;
        for (int i = 0; i <= p - j - s; ++i) {
          const fmpz* c = st + 2 * ((j - 1) * tri + i);
          blend(Rw + i * w, Rw + i * w, Rw + (i + 1) * w, c, c + 1, m);
        }
        put(L, Rw.data());
        put(k + r - j - s, Rw + (p - j - s) * w);
      }
      for (std::size_t i = L + 1; i + s < k; ++i) put(i, Rw + (i - L) * w);
    }
    /// The new points, Q_{k-p+1} .. Q_{k-s+r-1}: the only words the copies did not see.
    big = big || any_big(dst + (k - p + 1) * ps, (r - 1 + p - s) * ps);
  }
  if (!big) R.words.mark_small();
  return R;
}

/// One step of A5.4's point loop, the same for every fibre: Q[to..to+len) = P[from..from+len)
/// (copy_p; `to` and `from` are the lowest points of the run), Q[to] = Q[from], or
/// Q[to] = ((t - s) Q[from] + s Q[to]) / t with (s, t) at coef.
struct Step {
  enum Kind { copy_p, copy_q, blend } kind;
  std::size_t to, from, coef, len;
};

}  // namespace

FFNet detail::insert_on(const FFNet& F, int d, const FFKnots& U, const fmpz* xk, int times, const Limits& limits) {
  const int p = F.degrees[d];
  check_insertable(U, p, F.count(d), d, xk, times, "knots");
  limits.check_count(F.size() / F.count(d) * (F.count(d) + times), "knots");
  const std::size_t k = upper(U, xk) - 1;
  const int s = static_cast<int>(multiplicity(U, xk));
  const int r1 = std::min(times, p - s);
  if (r1 == 0) return knot_ins(F, d, U, xk, k, p, 1);
  FFNet R = knot_ins(F, d, U, xk, k, s, r1);
  if (times > r1) return knot_ins(R, d, R.knots[d], xk, k + r1, p, 1);
  return R;
}

FFNet insert_knot(const FFNet& F, int d, const Rational& x, int times, const Limits& limits) {
  check_direction(F, d);
  if (times < 0) throw UsageError("times", "is negative", "insert a knot 0 or more times");
  if (times == 0) return F;
  /// The knots are copied only when x's denominator does not divide theirs.
  FFKnots scaled;
  const std::vector<Z> xs = onto_knots(F.knots[d], scaled, {x});
  return insert_on(F, d, scaled.size() ? scaled : F.knots[d], xs[0].get(), times, limits);
}

FFNet refine_knots(const FFNet& F, int d, std::vector<Rational> X, const Limits& limits) {
  check_direction(F, d);
  FFKnots scaled;
  std::vector<Z> xs = onto_knots(F.knots[d], scaled, X);
  std::sort(xs.begin(), xs.end(), [](const Z& a, const Z& b) { return cmp(a.get(), b.get()) < 0; });
  return refine_on(F, d, scaled.size() ? scaled : F.knots[d], xs, limits);
}

FFNet detail::refine_on(const FFNet& F, int d, const FFKnots& U, const std::vector<Z>& xs, const Limits& limits) {
  const int p = F.degrees[d];
  const std::size_t count = F.count(d);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    std::size_t same = 1;
    while (i + same < xs.size() && fmpz_equal(xs[i + same].get(), xs[i].get())) ++same;
    check_insertable(U, p, count, d, xs[i].get(), same, "knots[" + std::to_string(i) + "]");
    i += same - 1;
  }
  limits.check_count(F.size() / count * (count + xs.size()), "knots");
  if (xs.empty()) return F;
  /// The new knot vector is the merge of U and X; A5.4's point loop reads only entries of it that
  /// it has already set, so it is built first, once.
  const std::size_t nn = count - 1, r = xs.size() - 1;
  FFKnots V;
  V.k = ZVec(U.size() + xs.size());
  fmpz_set(V.den.data(), U.den.data());
  {
    std::size_t i = 0, j = 0, o = 0;
    while (i < U.size() || j < xs.size())
      if (j == xs.size() || (i < U.size() && cmp(U.k + i, xs[j].get()) <= 0)) set(V.k + o++, U.k + i++);
      else set(V.k + o++, xs[j++].get());
  }
  /// A5.4 RefineKnotVectCurve (spline/insert_impl.hpp) as a program of steps on the points.
  auto span = [&](const fmpz* x) {  // A2.1 FindSpan on the integers
    if (cmp(x, U.k + count) >= 0) {
      std::size_t s = count - 1;
      while (s > static_cast<std::size_t>(p) && cmp(U.k + s, U.k + s + 1) >= 0) --s;
      return s;
    }
    return std::max<std::size_t>(upper(U, x), p + 1) - 1;
  };
  const std::size_t sa = span(xs.front().get()), sb = span(xs.back().get()) + 1;
  std::vector<Step> prog;
  std::vector<Z> coef;
  std::size_t i = sb + p - 1, k = sb + p + r;
  for (std::size_t jj = r + 1; jj-- > 0;) {
    while (!(cmp(U.k + i, xs[jj].get()) < 0) && i > sa) {
      // Runs of these copies (each one point lower than the last) become one block copy.
      if (!prog.empty() && prog.back().kind == Step::copy_p && prog.back().to == k - p && prog.back().from == i - p) {
        --prog.back().to;
        --prog.back().from;
        ++prog.back().len;
      } else {
        prog.push_back({Step::copy_p, k - p - 1, i - p - 1, 0, 1});
      }
      --k;
      --i;
    }
    prog.push_back({Step::copy_q, k - p - 1, k - p, 0, 1});
    for (int l = 1; l <= p; ++l) {
      const std::size_t ind = k - p + l;
      Z s, t;
      sub(s.get(), V.k + k + l, xs[jj].get());
      if (fmpz_is_zero(s.get())) {
        prog.push_back({Step::copy_q, ind - 1, ind, 0, 1});
      } else {
        sub(t.get(), V.k + k + l, U.k + i - p + l);
        prog.push_back({Step::blend, ind - 1, ind, coef.size(), 1});
        coef.push_back(std::move(s));
        coef.push_back(std::move(t));
      }
    }
    --k;
  }
  const Layout f = layout(F, d);
  const std::size_t w = F.stride(), m = F.m(), ps = f.before * w, n = f.n, n2 = n + r + 1;
  FFNet R = with_knots(F, d, std::move(V), n2);
  Blend blend;
  /// The points a blend wrote (or a copy of one): reduced, where long, once after the walk.
  std::vector<std::size_t> touched;
  for (const Step& st : prog)
    if (st.kind != Step::copy_p) touched.push_back(st.to);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (std::size_t b = 0; b < f.after; ++b) {
    const fmpz* src = F.words + b * n * ps;
    fmpz* dst = R.words + b * n2 * ps;
    init_copy(dst, src, (sa - p + 1) * ps);
    init_copy(dst + (sb - 1 + r + 1) * ps, src + (sb - 1) * ps, (nn + 2 - sb) * ps);
    /// The steps in order; copies move whole points (every fibre point a at once), blends one a.
    for (const Step& st : prog) {
      if (st.kind == Step::copy_p) {
        copy_block(dst + st.to * ps, src + st.from * ps, st.len * ps);
      } else if (st.kind == Step::copy_q) {
        copy_block(dst + st.to * ps, dst + st.from * ps, ps);
      } else {
        // dst = alfa dst + (1 - alfa) src with alfa = s/t: ((t - s) src + s dst) / t.
        for (std::size_t a = 0; a < f.before; ++a) {
          fmpz* to = dst + st.to * ps + a * w;
          blend(to, dst + st.from * ps + a * w, to, coef[st.coef].get(), coef[st.coef + 1].get(), m);
        }
      }
    }
    for (std::size_t a = 0; a < f.before; ++a)
      for (const std::size_t i : touched) reduce_if_long(dst + i * ps + a * w, m);
  }
  return R;
}

}  // namespace splinex::ff
