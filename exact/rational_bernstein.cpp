// ArithTraits<Rational>'s integer loops (spline/arith.hpp): the Bernstein product
// (tensor_convolve), composition's sum over the outer control points (weighted_sums, and
// product_sums with the sum's last product fused), de Casteljau's algorithm for splits and
// values (de_casteljau, tensor_value), the halving in every direction (halves) and the
// derivative's differences (differences) of bernstein/tensor.hpp.
// Each operand's coefficients are brought onto one
// denominator (the lcm of theirs), the convolution is a sum of integer products (FLINT words:
// 64-bit values stay inline, longer ones go to GMP), and each coefficient of the product is made
// a reduced rational once. The per-term rational products and sums it replaces each ended in a
// gcd: for Algorithm 1 on the teapot they were most of the exact time.
#include <flint/fmpz.h>
#include <flint/fmpz_vec.h>
#include <gmp.h>

#include <algorithm>
#include <vector>

#include "exact/ff_int.hpp"
#include "exact/ffnet.hpp"
#include "exact/rational.hpp"

namespace splinex {

namespace {

using ff::detail::Z;  // an owned FLINT integer (exact/ff_int.hpp)
using ff::ZVec;       // an owned array of FLINT integers, zero at the start (exact/ffnet.hpp)

const __mpq_struct* raw(const Rational& x) { return x.backend().data(); }

/// out[a] = x[a] * mult[a] over one denominator D (returned in D): the lcm of the denominators.
/// No `mult`: every multiplier is 1.
void onto_common(const std::vector<Rational>& x, const std::vector<Rational>* mult, fmpz* out, fmpz_t D) {
  Z t;
  fmpz_one(D);
  for (const Rational& v : x) {
    fmpz_set_mpz(t.v, mpq_denref(raw(v)));
    if (!fmpz_divisible(D, t.v)) fmpz_lcm(D, D, t.v);
  }
  for (std::size_t a = 0; a < x.size(); ++a) {
    if (mpq_sgn(raw(x[a])) == 0) {
      fmpz_zero(out + a);
      continue;
    }
    fmpz_set_mpz(t.v, mpq_denref(raw(x[a])));
    fmpz_divexact(t.v, D, t.v);
    fmpz_set_mpz(out + a, mpq_numref(raw(x[a])));
    fmpz_mul(out + a, out + a, t.v);
    if (!mult) continue;
    fmpz_set_mpz(t.v, mpq_numref(raw((*mult)[a])));  // a positive integer (a binomial product)
    fmpz_mul(out + a, out + a, t.v);
  }
}

/// H[fo[x] + go[y]] += F[x] G[y] over every x < nf, y < ng: the Bernstein product's convolution
/// on the binomial-scaled integers (bern_product's offsets fo, go into the product's tensor).
void convolve(const fmpz* F, std::size_t nf, const fmpz* G, std::size_t ng, const std::vector<std::size_t>& fo,
              const std::vector<std::size_t>& go, fmpz* H) {
  for (std::size_t x = 0; x < nf; ++x) {
    if (fmpz_is_zero(F + x)) continue;
    for (std::size_t y = 0; y < ng; ++y) fmpz_addmul(H + fo[x] + go[y], F + x, G + y);
  }
}

/// t = a / b with b > 0 (canonical mpq parts as FLINT integers).
void parts(const Rational& t, fmpz_t a, fmpz_t b) {
  fmpz_set_mpz(a, mpq_numref(raw(t)));
  fmpz_set_mpz(b, mpq_denref(raw(t)));
}

/// q := n / d in lowest terms (d > 0); n is left divided by the gcd, d untouched.
void store(fmpz* n, const fmpz* d, Z& g, Z& dd, Rational& q) {
  fmpz_gcd(g.v, n, d);
  __mpq_struct* r = q.backend().data();
  if (fmpz_is_one(g.v)) {
    fmpz_get_mpz(mpq_numref(r), n);
    fmpz_get_mpz(mpq_denref(r), d);
    return;
  }
  fmpz_divexact(n, n, g.v);
  fmpz_divexact(dd.v, d, g.v);
  fmpz_get_mpz(mpq_numref(r), n);
  fmpz_get_mpz(mpq_denref(r), dd.v);
}

}  // namespace

void ArithTraits<Rational>::tensor_convolve(const std::vector<Rational>& f, const std::vector<Rational>& fb,
                                            const std::vector<Rational>& g, const std::vector<Rational>& gb,
                                            const std::vector<std::size_t>& fo, const std::vector<std::size_t>& go,
                                            const std::vector<Rational>& hb, std::vector<Rational>& h) {
  ZVec A(f.size()), B(g.size()), H(h.size());
  Z Df, Dg, t, gcd, dd;
  onto_common(f, &fb, A.data(), Df.v);
  onto_common(g, &gb, B.data(), Dg.v);
  convolve(A.data(), f.size(), B.data(), g.size(), fo, go, H.data());
  fmpz_mul(Df.v, Df.v, Dg.v);  // the product's common denominator, before the binomials
  for (std::size_t i = 0; i < h.size(); ++i) {
    fmpz_set_mpz(t.v, mpq_numref(raw(hb[i])));
    fmpz_mul(t.v, t.v, Df.v);
    store(H.data() + i, t.v, gcd, dd, h[i]);  // reduced in integers; the sign stays with the numerator
  }
}

namespace {

/// out[i*cols + c] += sum over t of (V_t[i] / (D_t hbn[i])) a[t] b[t*cols + c], with V the nt
/// arrays of len integers, D their denominators and hbn the per-coefficient divisors (positive
/// integers; none: 1): per column, the terms over their lcm, integer sums, and one reduction per
/// coefficient of out, which may hold a running sum.
void integer_sums(const fmpz* V, const fmpz* D, std::size_t nt, std::size_t len, const fmpz* hbn, const std::vector<Rational>& a,
                  const std::vector<Rational>& b, std::size_t cols, std::vector<Rational>& out) {
  ZVec num(nt), den(nt), Acc(len);
  Z L, f, g, e, dd;
  Rational s;
  for (std::size_t c = 0; c < cols; ++c) {
    // s_t = a_t b_tc = n_t / d_t; column c's denominator L = lcm_t (d_t D_t) over s_t != 0;
    // out[i][c] = sum_t n_t (L / (d_t D_t)) V_t[i] / (L hbn[i]).
    fmpz_one(L.v);
    for (std::size_t t = 0; t < nt; ++t) {
      s = a[t] * b[t * cols + c];
      fmpz_set_mpz(num.data() + t, mpq_numref(raw(s)));
      fmpz_set_mpz(den.data() + t, mpq_denref(raw(s)));
      fmpz_mul(den.data() + t, den.data() + t, D + t);
      if (!fmpz_is_zero(num.data() + t) && !fmpz_divisible(L.v, den.data() + t)) fmpz_lcm(L.v, L.v, den.data() + t);
    }
    _fmpz_vec_zero(Acc.data(), static_cast<slong>(len));
    for (std::size_t t = 0; t < nt; ++t) {
      if (fmpz_is_zero(num.data() + t)) continue;
      fmpz_divexact(f.v, L.v, den.data() + t);
      fmpz_mul(f.v, f.v, num.data() + t);
      _fmpz_vec_scalar_addmul_fmpz(Acc.data(), V + t * len, static_cast<slong>(len), f.v);
    }
    for (std::size_t i = 0; i < len; ++i) {
      // e = L hbn[i], the denominator of Acc[i]
      if (hbn) fmpz_mul(e.v, L.v, hbn + i);
      else fmpz_set(e.v, L.v);
      __mpq_struct* q = out[i * cols + c].backend().data();
      if (mpq_sgn(q) != 0) {  // out += Acc / e, on integers: (o_n e + Acc o_d) / (o_d e)
        fmpz_set_mpz(f.v, mpq_denref(q));
        fmpz_mul(Acc.data() + i, Acc.data() + i, f.v);
        fmpz_set_mpz(f.v, mpq_numref(q));
        fmpz_addmul(Acc.data() + i, f.v, e.v);
        fmpz_set_mpz(f.v, mpq_denref(q));
        fmpz_mul(f.v, f.v, e.v);
      } else {
        fmpz_set(f.v, e.v);
      }
      store(Acc.data() + i, f.v, g, dd, out[i * cols + c]);  // Acc / f in lowest terms (f > 0)
    }
  }
}

}  // namespace

void ArithTraits<Rational>::weighted_sums(const std::vector<const std::vector<Rational>*>& v, const std::vector<Rational>& a,
                                         const std::vector<Rational>& b, std::size_t cols, std::vector<Rational>& out) {
  const std::size_t nt = v.size(), len = out.size() / cols;
  // Each v[t] as integers V_t over its own denominator D_t.
  ZVec V(nt * len), D(nt);
  for (std::size_t t = 0; t < nt; ++t) onto_common(*v[t], nullptr, V.data() + t * len, D.data() + t);
  integer_sums(V.data(), D.data(), nt, len, nullptr, a, b, cols, out);
}

void ArithTraits<Rational>::product_sums(const std::vector<const std::vector<Rational>*>& f, const std::vector<Rational>& fb,
                                        const std::vector<const std::vector<Rational>*>& g, const std::vector<Rational>& gb,
                                        const std::vector<std::size_t>& fo, const std::vector<std::size_t>& go,
                                        const std::vector<Rational>& hb, const std::vector<Rational>& a,
                                        const std::vector<Rational>& b, std::size_t cols, std::vector<Rational>& out) {
  const std::size_t nt = f.size(), len = out.size() / cols;
  if (nt == 0) return;
  const std::size_t nf = f[0]->size(), ng = g[0]->size();
  // Each product h_t = f_t g_t as integers V_t over D_t = Df_t Dg_t times hb: the convolution of
  // tensor_convolve, not reduced; the sums reduce once per coefficient of out.
  ZVec V(nt * len), D(nt), F(nf), G(ng), H(len);
  Z Dg;
  for (std::size_t t = 0; t < nt; ++t) {
    onto_common(*f[t], &fb, F.data(), D.data() + t);
    onto_common(*g[t], &gb, G.data(), Dg.v);
    convolve(F.data(), nf, G.data(), ng, fo, go, V.data() + t * len);
    fmpz_mul(D.data() + t, D.data() + t, Dg.v);
  }
  for (std::size_t i = 0; i < len; ++i) fmpz_set_mpz(H.data() + i, mpq_numref(raw(hb[i])));  // positive integers
  integer_sums(V.data(), D.data(), nt, len, H.data(), a, b, cols, out);
}

void ArithTraits<Rational>::de_casteljau(const std::vector<Rational>& c, std::size_t stride, int p, const Rational& t,
                                         std::vector<Rational>* left, std::vector<Rational>* right) {
  const std::size_t n = c.size(), block = stride * (static_cast<std::size_t>(p) + 1);
  ZVec C(n), w(static_cast<std::size_t>(p) + 1), den(static_cast<std::size_t>(p) + 1);
  Z D, a, b, s, g, dd, x;
  onto_common(c, nullptr, C.data(), D.v);
  parts(t, a.v, b.v);
  fmpz_sub(s.v, b.v, a.v);  // 1 - t = s / b
  const bool half = fmpz_is_one(a.v) && fmpz_equal_si(b.v, 2);
  // Level r of the triangle holds integers over D b^r.
  fmpz_set(den.data(), D.v);
  for (int r = 1; r <= p; ++r) fmpz_mul(den.data() + r, den.data() + r - 1, b.v);
  for (std::size_t hi = 0; hi < n; hi += block)
    for (std::size_t lo = 0; lo < stride; ++lo) {
      const std::size_t base = hi + lo;
      for (int i = 0; i <= p; ++i) fmpz_set(w.data() + i, C.data() + base + static_cast<std::size_t>(i) * stride);
      for (int r = 0; r <= p; ++r) {
        if (left) {
          fmpz_set(x.v, w.data());  // a copy: store divides it
          store(x.v, den.data() + r, g, dd, (*left)[base + static_cast<std::size_t>(r) * stride]);
        }
        if (right) {
          fmpz_set(x.v, w.data() + p - r);
          store(x.v, den.data() + r, g, dd, (*right)[base + static_cast<std::size_t>(p - r) * stride]);
        }
        if (half)
          for (int i = 0; i < p - r; ++i) fmpz_add(w.data() + i, w.data() + i, w.data() + i + 1);
        else
          for (int i = 0; i < p - r; ++i) {
            fmpz_mul(w.data() + i, w.data() + i, s.v);
            fmpz_addmul(w.data() + i, w.data() + i + 1, a.v);
          }
      }
    }
}

Rational ArithTraits<Rational>::tensor_value(const std::vector<Rational>& c, const std::vector<int>& deg,
                                             const std::vector<Rational>& x) {
  // Direction by direction on integers: after direction l the values are integers over
  // D b_0^p_0 ... b_l^p_l (x_l = a_l / b_l), so one reduction at the end.
  std::size_t n = c.size();
  ZVec C(n);
  Z D, a, b, s, g, dd;
  onto_common(c, nullptr, C.data(), D.v);
  for (std::size_t l = 0; l < deg.size(); ++l) {
    const int p = deg[l];
    const std::size_t lines = n / (static_cast<std::size_t>(p) + 1);
    parts(x[l], a.v, b.v);
    fmpz_sub(s.v, b.v, a.v);
    for (std::size_t line = 0; line < lines; ++line) {
      fmpz* w = C.data() + line * (static_cast<std::size_t>(p) + 1);
      for (int r = p; r > 0; --r)
        for (int i = 0; i < r; ++i) {
          fmpz_mul(w + i, w + i, s.v);
          fmpz_addmul(w + i, w + i + 1, a.v);
        }
      fmpz_swap(C.data() + line, w);  // the line's value moves to slot `line` (line <= its start)
    }
    for (int r = 0; r < p; ++r) fmpz_mul(D.v, D.v, b.v);
    n = lines;
  }
  Rational out;
  store(C.data(), D.v, g, dd, out);
  return out;
}

void ArithTraits<Rational>::differences(const std::vector<Rational>& c, std::size_t stride, int p, std::vector<Rational>& out) {
  const std::size_t n = c.size(), in_block = stride * (static_cast<std::size_t>(p) + 1), out_block = stride * static_cast<std::size_t>(p);
  ZVec C(n);
  Z D, x, g, dd;
  onto_common(c, nullptr, C.data(), D.v);  // integers over one denominator: a difference is exact
  for (std::size_t b = 0, ob = 0; b < n; b += in_block, ob += out_block)
    for (std::size_t j = 0; j < out_block; ++j) {
      fmpz_sub(x.v, C.data() + b + j + stride, C.data() + b + j);
      fmpz_mul_ui(x.v, x.v, static_cast<ulong>(p));
      store(x.v, D.v, g, dd, out[ob + j]);
    }
}

void ArithTraits<Rational>::halves(const std::vector<Rational>& c, const std::vector<int>& deg,
                                  std::vector<std::vector<Rational>>& out) {
  // Direction by direction on integers: de Casteljau at 1/2 is sums (level r over 2^r), and each
  // half is put over 2^p (its level-r value times 2^(p-r)), so after direction l every part is
  // integers over D 2^(p_0 + ... + p_l): one denominator for all parts, one reduction at the end.
  const std::size_t n = c.size();
  std::vector<ZVec> cur;
  cur.emplace_back(n);
  Z D, g, dd;
  onto_common(c, nullptr, cur[0].data(), D.v);
  int maxp = 0;
  for (int p : deg) maxp = std::max(maxp, p);
  ZVec w(static_cast<std::size_t>(maxp) + 1);
  std::size_t stride = 1;
  ulong shift = 0;
  for (int p : deg) {
    const std::size_t block = stride * (static_cast<std::size_t>(p) + 1);
    std::vector<ZVec> next;
    next.reserve(2 * cur.size());
    for (ZVec& C : cur) {
      ZVec L(n), R(n);
      for (std::size_t hi = 0; hi < n; hi += block)
        for (std::size_t lo = 0; lo < stride; ++lo) {
          const std::size_t base = hi + lo;
          for (int i = 0; i <= p; ++i) fmpz_set(w + static_cast<std::size_t>(i), C + base + static_cast<std::size_t>(i) * stride);
          for (int r = 0; r <= p; ++r) {
            const ulong up = static_cast<ulong>(p - r);
            fmpz_mul_2exp(L + base + static_cast<std::size_t>(r) * stride, w + 0, up);
            fmpz_mul_2exp(R + base + static_cast<std::size_t>(p - r) * stride, w + static_cast<std::size_t>(p - r), up);
            for (int i = 0; i < p - r; ++i) fmpz_add(w + static_cast<std::size_t>(i), w + static_cast<std::size_t>(i), w + static_cast<std::size_t>(i + 1));
          }
        }
      next.push_back(std::move(L));
      next.push_back(std::move(R));
    }
    cur = std::move(next);
    shift += static_cast<ulong>(p);
    stride = block;
  }
  fmpz_mul_2exp(D.v, D.v, shift);
  for (std::size_t K = 0; K < cur.size(); ++K)
    for (std::size_t i = 0; i < n; ++i) store(cur[K] + i, D.v, g, dd, out[K][i]);
}

}  // namespace splinex
