// Fraction-free degree elevation (exact/ffnet.hpp), two routes to the same exact values:
//   - NURBS Book A5.9 DegreeElevateCurve, line for line as spline/elevate_impl.hpp writes it, on
//     integer knots and integer points over their own denominators. Every "a*P + (1-a)*Q" of A5.9
//     (knot insertion into the Bezier segment, and the knot removal after elevation, where a may
//     lie outside [0, 1]) is one Blend; each elevated Bezier point is sum_j C(p,j) C(t,i-j) P_j over
//     C(p+t,i), one integer combination.
//   - Elevation by one through the blossom (spline/elevate_impl.hpp's LeaveOneOutBlossom, the
//     floating-point default): each new point is the mean of p+1 blossom values of one piece at
//     knots of the elevated vector. A5.9's intermediate points (the segment's Bezier points, the
//     removal's extrapolations) carry denominators far longer than the result's, which at p = 7
//     left FLINT's word range on every other blend; the blossom's triangles at knot arguments stay
//     near the control points (a blend whose argument is one of its knots is a copy), so their
//     integers stay short. Measured (bench_kernel, exact/double, t = 1): p = 3 12.7 -> 7, p = 7
//     n = 10^4 216 -> 45; at p <= 2 A5.9 stays faster, and for t >= 2 repeated steps cost 2-7x
//     A5.9 (each step's result is longer), so the blossom serves t = 1, p >= 3.
#include <flint/fmpz.h>

#include "exact/ff_common.hpp"

namespace splinex::ff {

using namespace detail;

namespace {

/// A curve of `count` contiguous points of w = m+1 words and its knots (integers over the
/// caller's denominator).
struct Curve {
  int p = 0;
  std::vector<Z> U;
  ZVec P;
  std::size_t count = 0;
};

/// out = sum_j c_j P_j / div over homogeneous points (numerators m, denominator last), reduced
/// when long (reduce_if_long: a59 reduces the points it returns).
class Combination {
 public:
  explicit Combination(std::size_t m) : m_(m), acc_(m + 1) { fmpz_one(one_.get()); }
  void start() { first_ = true; }
  void add(const fmpz* c, const fmpz* P) {
    fmpz* a = acc_.data();
    if (!first_ && words(a, c, P)) return;
    if (first_) {
      for (std::size_t k = 0; k < m_; ++k) mul(a + k, c, P + k);
      set(a + m_, P + m_);
      first_ = false;
    } else if (cmp(a + m_, P + m_) == 0) {
      for (std::size_t k = 0; k < m_; ++k) lin2(a + k, one_.get(), a + k, c, P + k);
    } else {
      // Over the lcm, g = gcd(E_a, E_P): a/E_a + c P/E_P = (a (E_P/g) + c (E_a/g) P) / (E_a E_P/g).
      if (small(a + m_) && small(P + m_)) {
        const slong g = static_cast<slong>(binary_gcd(static_cast<std::uint64_t>(a[m_]), static_cast<std::uint64_t>(P[m_])));
        set_small(fp_.get(), P[m_] / g);
        set_small(ce_.get(), a[m_] / g);
      } else {
        fmpz_gcd(g_.get(), a + m_, P + m_);
        fmpz_divexact(fp_.get(), P + m_, g_.get());
        fmpz_divexact(ce_.get(), a + m_, g_.get());
      }
      mul(ce_.get(), c, ce_.get());
      for (std::size_t k = 0; k < m_; ++k) lin2(a + k, fp_.get(), a + k, ce_.get(), P + k);
      mul(a + m_, a + m_, fp_.get());
    }
  }
  void finish(const fmpz* div, fmpz* out) {
    fmpz* a = acc_.data();
    mul(a + m_, a + m_, div);
    reduce_if_long(a, m_);
    for (std::size_t k = 0; k <= m_; ++k) set(out + k, a + k);
  }

 private:
  /// add() when every operand is a small word and every product fits one (false: nothing
  /// written).
  bool words(fmpz* a, const fmpz* c, const fmpz* P) const {
    if (!fast() || m_ > 7 || !small(c) || any_big(a, m_ + 1) || any_big(P, m_ + 1)) return false;
    const WordLcm L = word_lcm(a[m_], P[m_]);
    const i128 fp = *c * L.fb;  // |c| < 2^62, fb < 2^62: fits
    if (!fits(fp) || !fits(L.lcm)) return false;
    slong v[8] = {};
    for (std::size_t k = 0; k < m_; ++k) {
      const i128 x = L.fa * a[k] + fp * P[k];
      if (!fits(x)) return false;
      v[k] = static_cast<slong>(x);
    }
    for (std::size_t k = 0; k < m_; ++k) a[k] = v[k];
    a[m_] = static_cast<slong>(L.lcm);
    return true;
  }

  std::size_t m_;
  ZVec acc_;
  Z one_, ce_, g_, fp_;
  bool first_ = true;
};

/// P := a P + (1 - a) Q with a = s/t (t != 0, any sign; a may lie outside [0, 1]).
void affine(Blend& blend, fmpz* P, const fmpz* s, const fmpz* t, const fmpz* Q, std::size_t m, Z& ns, Z& nt) {
  if (fmpz_sgn(t) > 0) return blend(P, Q, P, s, t, m);
  fmpz_neg(ns.get(), s);
  fmpz_neg(nt.get(), t);
  blend(P, Q, P, ns.get(), nt.get(), m);
}

/// A5.9 on one clamped curve without C^-1 knots, degree p >= 1 (spline/elevate_impl.hpp's
/// degree_elevate_curve).
Curve a59(int p, const std::vector<Z>& U, const fmpz* Pw, std::size_t count, std::size_t m, int t) {
  const std::size_t w = m + 1;
  const int n = static_cast<int>(count) - 1;
  const int mU = n + p + 1, ph = p + t, ph2 = ph / 2;
  /// bezalfs[i][j] = C(p,j) C(t,i-j) / C(ph,i): numerators coef[i][j], divisors div[i].
  std::vector<std::vector<Z>> coef(ph + 1, std::vector<Z>(p + 1));
  std::vector<Z> div(ph + 1);
  Z b1, b2;
  for (int i = 0; i <= ph; ++i) {
    fmpz_bin_uiui(div[i].get(), ph, i);
    for (int j = std::max(0, i - t); j <= std::min(p, i); ++j) {
      fmpz_bin_uiui(b1.get(), p, j);
      fmpz_bin_uiui(b2.get(), t, i - j);
      fmpz_mul(coef[i][j].get(), b1.get(), b2.get());
    }
  }
  (void)ph2;
  int s_int = -1;  // distinct interior knots of the domain [U[p], U[count]]
  for (int i = p; i <= n + 1; ++i)
    if (i == p || cmp(U[i - 1].get(), U[i].get()) < 0) ++s_int;
  s_int -= 1;
  const int nh_max = n + t * (s_int + 1);
  Curve out;
  out.p = ph;
  out.U.resize(nh_max + ph + 2);
  out.P = ZVec(static_cast<std::size_t>(nh_max + 1) * w);
  std::vector<Z>& Uh = out.U;
  fmpz* Qw = out.P.data();
  ZVec bpts((p + 1) * w), ebpts((ph + 1) * w), Next(std::max(p - 1, 1) * w);
  std::vector<Z> alfs(std::max(p - 1, 1));
  auto bp = [&](int i) { return bpts + static_cast<std::size_t>(i) * w; };
  auto eb = [&](int i) { return ebpts + static_cast<std::size_t>(i) * w; };
  auto qt = [&](int i) { return Qw + static_cast<std::size_t>(i) * w; };
  auto assign = [w](fmpz* dst, const fmpz* src) {
    for (std::size_t c = 0; c < w; ++c) set(dst + c, src + c);
  };
  Blend blend;
  Combination comb(m);
  Z numer, den, sn, tn, ns, nt, bet;

  int mh = ph, kind = ph + 1, r = -1, a = p, b = p + 1, cind = 1;
  Z ua = U[0], ub;
  assign(qt(0), Pw);
  for (int i = 0; i <= ph; ++i) Uh[i] = ua;
  for (int i = 0; i <= p; ++i) assign(bp(i), Pw + static_cast<std::size_t>(i) * w);
  while (b < mU) {
    const int i = b;
    while (b < mU && cmp(U[b].get(), U[b + 1].get()) == 0) ++b;
    const int mul_ = b - i + 1;
    mh += mul_ + t;
    ub = U[b];
    const int oldr = r;
    r = p - mul_;
    const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
    const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
    if (r > 0) {  // insert knot u(b) r times to get the Bezier segment
      sub(numer.get(), ub.get(), ua.get());
      for (int k = p; k > mul_; --k) sub(alfs[k - mul_ - 1].get(), U[a + k].get(), ua.get());
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = mul_ + j;
        for (int k = p; k >= s; --k) affine(blend, bp(k), numer.get(), alfs[k - s].get(), bp(k - 1), m, ns, nt);
        assign(Next + static_cast<std::size_t>(save) * w, bp(p));
      }
    }
    for (int ii = lbz; ii <= ph; ++ii) {  // degree elevate the Bezier segment
      comb.start();
      for (int j = std::max(0, ii - t); j <= std::min(p, ii); ++j) comb.add(coef[ii][j].get(), bp(j));
      comb.finish(div[ii].get(), eb(ii));
    }
    if (oldr > 1) {  // remove knot u = U[a] oldr times
      int first = kind - 2, last = kind;
      sub(den.get(), ub.get(), ua.get());
      sub(bet.get(), ub.get(), Uh[kind - 1].get());
      for (int tr = 1; tr < oldr; ++tr) {
        int ii = first, j = last, kj = j - kind + 1;
        while (j - ii > tr) {
          if (ii < cind) {
            sub(sn.get(), ub.get(), Uh[ii].get());
            sub(tn.get(), ua.get(), Uh[ii].get());
            affine(blend, qt(ii), sn.get(), tn.get(), qt(ii - 1), m, ns, nt);
          }
          if (j >= lbz) {
            if (j - tr <= kind - ph + oldr) {
              sub(sn.get(), ub.get(), Uh[j - tr].get());
              affine(blend, eb(kj), sn.get(), den.get(), eb(kj + 1), m, ns, nt);
            } else {
              affine(blend, eb(kj), bet.get(), den.get(), eb(kj + 1), m, ns, nt);
            }
          }
          ++ii;
          --j;
          --kj;
        }
        --first;
        ++last;
      }
    }
    if (a != p)  // load the knot ua
      for (int ii = 0; ii < ph - oldr; ++ii) Uh[kind++] = ua;
    for (int j = lbz; j <= rbz; ++j) assign(qt(cind++), eb(j));
    if (b < mU) {  // set up for the next pass
      for (int j = 0; j < r; ++j) assign(bp(j), Next + static_cast<std::size_t>(j) * w);
      for (int j = r; j <= p; ++j) assign(bp(j), Pw + static_cast<std::size_t>(b - p + j) * w);
      a = b;
      ++b;
      ua = ub;
    } else {
      for (int ii = 0; ii <= ph; ++ii) Uh[kind + ii] = ub;
    }
  }
  const int nh = mh - ph - 1;
  out.U.resize(nh + ph + 2);
  out.count = static_cast<std::size_t>(nh + 1);
  for (std::size_t i = 0; i < out.count; ++i) reduce_if_long(qt(static_cast<int>(i)), m);
  return out;
}

/// degree_elevate_curve_any: cut at knots of multiplicity p+1 (and every breakpoint at degree 0),
/// elevate each part, join them with the shared knot at multiplicity p+t+1.
Curve elevate_any(int p, const std::vector<Z>& U, const fmpz* Pw, std::size_t count, std::size_t m, int t) {
  const std::size_t w = m + 1, run = static_cast<std::size_t>(p) + 1;
  std::vector<std::size_t> starts{0};
  for (std::size_t i = run; i < count;) {
    std::size_t j = i;
    while (j + 1 < U.size() && cmp(U[j + 1].get(), U[i].get()) == 0) ++j;
    if (j - i + 1 == run) starts.push_back(i);
    i = j + 1;
  }
  if (starts.size() == 1 && p > 0) return a59(p, U, Pw, count, m, t);
  starts.push_back(count);
  std::vector<Curve> parts;
  std::size_t total = 0;
  for (std::size_t part = 0; part + 1 < starts.size(); ++part) {
    const std::size_t first = starts[part], n = starts[part + 1] - first;
    Curve piece;
    if (p == 0) {  // one constant span [U[first], U[first+1]]: t+1 equal points
      piece.p = t;
      piece.U.assign(t + 1, U[first]);
      piece.U.insert(piece.U.end(), t + 1, U[first + 1]);
      piece.P = ZVec((t + 1) * w);
      for (int c = 0; c <= t; ++c) init_copy(piece.P + c * w, Pw + first * w, w);
      piece.count = t + 1;
    } else {
      const std::vector<Z> V(U.begin() + first, U.begin() + first + n + run);
      piece = a59(p, V, Pw + first * w, n, m, t);
    }
    total += piece.count;
    parts.push_back(std::move(piece));
  }
  Curve out;
  out.p = p + t;
  out.count = total;
  out.P = ZVec(total * w);
  std::size_t at = 0;
  for (std::size_t part = 0; part < parts.size(); ++part) {
    const Curve& c = parts[part];
    out.U.insert(out.U.end(), c.U.begin() + (part == 0 ? 0 : p + t + 1), c.U.end());
    init_copy(out.P + at * w, c.P.data(), c.count * w);
    at += c.count;
  }
  return out;
}

/// spline/elevate_impl.hpp's LeaveOneOutBlossom on integers: sum over k of the degree-p blossom
/// of the piece on span s at x[0..p] with x[k] left out, the p+1 triangles sharing their prefixes
/// as there. Every entry is a point over its own denominator; a blend whose argument is one of its
/// two knots is a copy (alpha 0 or 1), which the triangles at knot arguments meet often.
class Blossoms {
 public:
  Blossoms(int p, const std::vector<Z>& U, const fmpz* P, std::size_t m)
      : p_(p), U_(U), P_(P), m_(m), w_(m + 1), prefix_((p + 1) * w_), work_((p + 1) * w_), comb_(m) {
    fmpz_one(one_.get());
  }

  /// out = (sum_k blossom(x without x[k])) / div on span s.
  void sum(std::size_t s, const fmpz* x, const fmpz* div, fmpz* out) {
    span_ = s;
    const std::size_t all = static_cast<std::size_t>(p_ + 1) * w_;
    copy_block(prefix_.data(), P_ + (s - p_) * w_, all);
    comb_.start();
    for (int k = 0; k <= p_; ++k) {
      if (k == p_) {
        comb_.add(one_.get(), prefix_ + static_cast<std::size_t>(p_) * w_);
        break;
      }
      fmpz* e = work_.data();
      apply(prefix_.data(), e, k, x + k + 1);
      for (int r = k + 2; r <= p_; ++r) apply(e, e, r - 1, x + r);
      comb_.add(one_.get(), e + static_cast<std::size_t>(p_) * w_);
      apply(prefix_.data(), prefix_.data(), k, x + k);
    }
    comb_.finish(div, out);
  }

 private:
  /// Level `level` + 1 of de Boor's triangle at argument x (src may be dst: last entry first).
  void apply(const fmpz* src, fmpz* dst, int level, const fmpz* x) {
    const int r = level + 1;
    for (int i = p_; i >= r; --i) {
      const std::size_t idx = span_ - p_ + i;
      const fmpz* lo = U_[idx].get();
      const fmpz* hi = U_[idx + p_ - r + 1].get();
      const fmpz* sm = src + (i - 1) * w_;
      const fmpz* si = src + i * w_;
      fmpz* di = dst + i * w_;
      if (cmp(x, lo) == 0) {
        if (di != sm) copy_block(di, sm, w_);
      } else if (cmp(x, hi) == 0) {
        if (di != si) copy_block(di, si, w_);
      } else {
        sub(s_.get(), x, lo);
        sub(t_.get(), hi, lo);
        blend_(di, sm, si, s_.get(), t_.get(), m_);
      }
    }
  }

  int p_;
  const std::vector<Z>& U_;
  const fmpz* P_;
  std::size_t m_, w_;
  ZVec prefix_, work_;
  Combination comb_;
  Blend blend_;
  Z s_, t_, one_;
  std::size_t span_ = 0;
};

/// Elevation by one through the blossom (spline/elevate_impl.hpp's elevate_by_one_blossom_fixed)
/// on a clamped curve: every distinct knot once more, each new point the symmetrized blossom of a
/// piece in its support over p+1.
Curve by_one_blossom(int p, const std::vector<Z>& U, const fmpz* P, std::size_t count, std::size_t m) {
  const std::size_t w = m + 1;
  Curve out;
  out.p = p + 1;
  out.U.reserve(U.size() + U.size() / 2 + 2);
  for (std::size_t i = 0; i < U.size(); ++i) {
    out.U.push_back(U[i]);
    if (i + 1 == U.size() || cmp(U[i].get(), U[i + 1].get()) < 0) out.U.push_back(U[i]);
  }
  const std::vector<Z>& V = out.U;
  const std::size_t nbar = V.size() - (p + 1) - 1;
  out.count = nbar;
  out.P = ZVec(nbar * w);
  ZVec x(static_cast<std::size_t>(p) + 1);
  Z div;
  fmpz_set_ui(div.get(), static_cast<ulong>(p) + 1);
  Blossoms sum(p, U, P, m);
  std::size_t s = p;
  for (std::size_t j = 0; j < nbar; ++j) {
    std::size_t l = j + p + 1;
    while (l > std::max<std::size_t>(j, p + 1) && !(cmp(V[l].get(), V[l + 1].get()) < 0)) --l;
    while (s + 1 < count && !(cmp(V[l].get(), U[s + 1].get()) < 0)) ++s;
    for (int k = 0; k <= p; ++k) set(x + k, V[j + 1 + k].get());
    sum.sum(s, x.data(), div.get(), out.P + j * w);
  }
  return out;
}

}  // namespace

FFNet elevate_degree(const FFNet& F, int d, int t, const Limits& limits) {
  check_direction(F, d);
  if (t < 0) throw UsageError("by", "elevation amount " + std::to_string(t) + " is negative", "elevate by t >= 0");
  limits.check_degree(static_cast<long>(F.degrees[d]) + t, "by");
  if (t == 0) return F;
  const std::size_t per = F.size() / F.count(d);
  const std::size_t segments = breakpoints(F.knots[d], F.degrees[d], F.count(d)).size() - 1;
  limits.check_count(checked_product(per, F.count(d) + static_cast<std::size_t>(t) * segments, limits, "by"), "by");
  const FFNet C = clamp(F, d, limits);
  const Layout f = layout(C, d);
  const std::size_t w = C.stride(), m = C.m(), ps = f.before * w;
  const int p = C.degrees[d];
  std::vector<Z> U(C.knots[d].size());
  for (std::size_t j = 0; j < U.size(); ++j) fmpz_set(U[j].get(), C.knots[d].k + j);
  FFNet R;
  ZVec fibre(f.n * w);
  for (std::size_t b = 0; b < f.after; ++b)
    for (std::size_t a = 0; a < f.before; ++a) {
      for (std::size_t i = 0; i < f.n; ++i)
        for (std::size_t c = 0; c < w; ++c) set(fibre + i * w + c, C.words + (b * f.n + i) * ps + a * w + c);
      const Curve e = t == 1 && p >= 3 ? by_one_blossom(p, U, fibre.data(), f.n, m) : elevate_any(p, U, fibre.data(), f.n, m, t);
      if (b == 0 && a == 0) {
        R.degrees = C.degrees;
        R.degrees[d] = e.p;
        R.q = C.q;
        R.rational = C.rational;
        for (int k = 0; k < C.dim(); ++k)
          if (k != d) {
            R.knots.push_back(C.knots[k]);
          } else {
            FFKnots V;
            V.k = ZVec(e.U.size());
            for (std::size_t j = 0; j < e.U.size(); ++j) fmpz_set(V.k + j, e.U[j].get());
            fmpz_set(V.den.data(), C.knots[d].den.data());
            R.knots.push_back(std::move(V));
          }
        R.words = ZVec(f.before * e.count * f.after * w);
      }
      const std::size_t n2 = e.count, ps2 = ps;
      for (std::size_t i = 0; i < n2; ++i)
        for (std::size_t c = 0; c < w; ++c) set(R.words + (b * n2 + i) * ps2 + a * w + c, e.P + i * w + c);
    }
  return R;
}

}  // namespace splinex::ff
