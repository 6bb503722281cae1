// The Bernstein product (bernstein/tensor.hpp's bern_product). For Rational it runs fraction-free
// (ArithTraits<Rational>::tensor_convolve, exact/rational_bernstein.cpp); it is proved right by
// identity: a tensor polynomial of degrees h is fixed by its values on a grid of h_l + 1 points
// per direction, so h(x) == f(x) g(x) on that grid is h == f g. FlintRational runs the generic
// per-term loop, an independent route that must give the same coefficients.
#include <catch2/catch.hpp>

#include <gmp.h>

#include <random>
#include <vector>

#include "bernstein/tensor.hpp"
#include "exact/flint_rational.hpp"
#include "exact/rational.hpp"

using namespace splinex;

namespace {

/// Coefficients of every kind the engines meet: zeros, small and long numerators (past 2^64),
/// odd, dyadic and shared denominators, both signs.
Rational coefficient(std::mt19937_64& rng) {
  const int kind = static_cast<int>(rng() % 6);
  const long a = static_cast<long>(rng() % 2001) - 1000;
  const long b = static_cast<long>(rng() % 97) + 1;
  switch (kind) {
    case 0: return Rational(0);
    case 1: return Rational(a, b);
    case 2: return Rational(a, 1L << (rng() % 40));
    case 3: return Rational(a, 360);  // a denominator shared by many coefficients
    case 4: {
      Rational big(1);
      for (int i = 0; i < 3; ++i) big *= Rational(static_cast<long>(rng() >> 2) + 1, 1);
      return (rng() % 2 ? big : -big) / Rational(b * 7 + 3);
    }
    default: return Rational(a) / Rational(static_cast<long>(rng() % 100000) + 1);
  }
}

Bernstein<Rational> random_poly(std::mt19937_64& rng, const std::vector<int>& deg) {
  Bernstein<Rational> p;
  p.deg = deg;
  p.c.resize(detail::tensor_size(deg));
  for (auto& c : p.c) c = coefficient(rng);
  return p;
}

/// h == f g, checked on a grid of deg(h)_l + 1 distinct points per direction (which proves it).
bool product_identity(const Bernstein<Rational>& f, const Bernstein<Rational>& g, const Bernstein<Rational>& h) {
  const std::size_t n = h.deg.size();
  std::vector<int> idx(n, 0);
  std::vector<Rational> x(n);
  while (true) {
    for (std::size_t l = 0; l < n; ++l) x[l] = Rational(2 * idx[l] + 1, 2 * h.deg[l] + 3);  // distinct, inside (0, 1)
    if (bern_value(h, x) != bern_value(f, x) * bern_value(g, x)) return false;
    std::size_t l = 0;
    while (l < n && ++idx[l] > h.deg[l]) idx[l++] = 0;
    if (l == n) return true;
  }
}

bool canonical(const Rational& x) {
  const __mpq_struct* q = x.backend().data();
  mpz_t g;
  mpz_init(g);
  mpz_gcd(g, mpq_numref(q), mpq_denref(q));
  const bool ok = mpz_sgn(mpq_denref(q)) > 0 && mpz_cmp_ui(g, 1) == 0;
  mpz_clear(g);
  return ok;
}

}  // namespace

TEST_CASE("bern_product: the fraction-free product is f g (identity on a grid), canonical, and equal to the per-term route") {
  std::mt19937_64 rng(49150);
  int cases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 1 + rng() % 3;
    std::vector<int> df(n), dg(n);
    for (std::size_t l = 0; l < n; ++l) {
      df[l] = static_cast<int>(rng() % (n == 3 ? 3 : 5));
      dg[l] = static_cast<int>(rng() % (n == 3 ? 3 : 5));
    }
    const Bernstein<Rational> f = random_poly(rng, df), g = random_poly(rng, dg);
    const Bernstein<Rational> h = bern_product(f, g);
    REQUIRE(product_identity(f, g, h));
    for (const Rational& c : h.c) REQUIRE(canonical(c));
    // The generic loop on FLINT's rationals: the same coefficients.
    Bernstein<FlintRational> F, G;
    F.deg = f.deg;
    G.deg = g.deg;
    for (const Rational& c : f.c) F.c.emplace_back(c);
    for (const Rational& c : g.c) G.c.emplace_back(c);
    const Bernstein<FlintRational> H = bern_product(F, G);
    REQUIRE(H.deg == h.deg);
    for (std::size_t i = 0; i < h.c.size(); ++i) REQUIRE(H.c[i].to_rational() == h.c[i]);
    ++cases;
  }
  CHECK(cases == 300);
}

TEST_CASE("bern_product: the identity check refutes a product one coefficient off") {
  std::mt19937_64 rng(49151);
  const Bernstein<Rational> f = random_poly(rng, {2, 1}), g = random_poly(rng, {3, 2});
  Bernstein<Rational> h = bern_product(f, g);
  REQUIRE(product_identity(f, g, h));
  for (std::size_t k = 0; k < h.c.size(); ++k) {
    Bernstein<Rational> wrong = h;
    wrong.c[k] += Rational(1, 7);  // a planted slip in one term of the convolution
    CHECK_FALSE(product_identity(f, g, wrong));
  }
}

TEST_CASE("weighted_sums: the integer sums equal the per-term route, added to what out holds") {
  std::mt19937_64 rng(49152);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t nt = 1 + rng() % 70, len = 1 + rng() % 12, cols = 1 + rng() % 4;
    std::vector<std::vector<Rational>> v(nt, std::vector<Rational>(len));
    std::vector<Rational> a(nt), b(nt * cols), out(len * cols);
    for (auto& x : v)
      for (auto& y : x) y = coefficient(rng);
    for (auto& x : a) x = coefficient(rng);
    for (auto& x : b) x = coefficient(rng);
    for (auto& x : out) x = rng() % 2 ? coefficient(rng) : Rational(0);  // a running sum, or none
    std::vector<const std::vector<Rational>*> pv;
    for (const auto& x : v) pv.push_back(&x);
    // The reference: the plain sum in GMP rationals, written here.
    std::vector<Rational> want = out;
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t i = 0; i < len; ++i)
        for (std::size_t c = 0; c < cols; ++c) want[i * cols + c] += v[t][i] * a[t] * b[t * cols + c];
    weighted_sums(pv, a, b, cols, out);
    for (std::size_t i = 0; i < out.size(); ++i) {
      REQUIRE(out[i] == want[i]);
      REQUIRE(canonical(out[i]));
    }
    // FLINT's rationals take the generic loop: the same values.
    std::vector<std::vector<FlintRational>> fv(nt);
    for (std::size_t t = 0; t < nt; ++t)
      for (const auto& y : v[t]) fv[t].emplace_back(y);
    std::vector<const std::vector<FlintRational>*> pf;
    for (const auto& x : fv) pf.push_back(&x);
    std::vector<FlintRational> fa, fb, fout(len * cols, FlintRational(0));
    for (const auto& x : a) fa.emplace_back(x);
    for (const auto& x : b) fb.emplace_back(x);
    weighted_sums(pf, fa, fb, cols, fout);
    std::vector<Rational> zero(len * cols, Rational(0));
    weighted_sums(pv, a, b, cols, zero);
    for (std::size_t i = 0; i < zero.size(); ++i) REQUIRE(fout[i].to_rational() == zero[i]);
  }
}

TEST_CASE("product_sums: the fused products and sums equal the products summed term by term, and FLINT's route") {
  std::mt19937_64 rng(49153);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t dim = 1 + rng() % 2, nt = 1 + rng() % 20, cols = 1 + rng() % 4;
    std::vector<int> fd(dim), gd(dim), hd(dim);
    for (std::size_t l = 0; l < dim; ++l) {
      fd[l] = static_cast<int>(rng() % 5);
      gd[l] = static_cast<int>(rng() % 5);
      hd[l] = fd[l] + gd[l];
    }
    const std::size_t len = detail::tensor_size(hd);
    std::vector<Bernstein<Rational>> f, g;
    for (std::size_t t = 0; t < nt; ++t) {
      f.push_back(random_poly(rng, fd));
      g.push_back(random_poly(rng, gd));
    }
    std::vector<Rational> a(nt), b(nt * cols), out(len * cols);
    for (auto& x : a) x = coefficient(rng);
    for (auto& x : b) x = coefficient(rng);
    for (auto& x : out) x = rng() % 2 ? coefficient(rng) : Rational(0);  // a running sum, or none
    // The reference: each product (proved by identity in the first test case), then the plain sum.
    std::vector<Rational> want = out;
    for (std::size_t t = 0; t < nt; ++t) {
      const Bernstein<Rational> h = bern_product(f[t], g[t]);
      REQUIRE(product_identity(f[t], g[t], h));
      for (std::size_t i = 0; i < len; ++i)
        for (std::size_t c = 0; c < cols; ++c) want[i * cols + c] += h.c[i] * a[t] * b[t * cols + c];
    }
    std::vector<const Bernstein<Rational>*> pf, pg;
    for (std::size_t t = 0; t < nt; ++t) {
      pf.push_back(&f[t]);
      pg.push_back(&g[t]);
    }
    std::vector<Rational> got = out;
    product_sums(pf, pg, a, b, cols, got);
    for (std::size_t i = 0; i < got.size(); ++i) {
      REQUIRE(got[i] == want[i]);
      REQUIRE(canonical(got[i]));
    }
    // FLINT's rationals take the generic route (bern_product, then weighted_sums): the same values.
    std::vector<Bernstein<FlintRational>> ff, fg;
    for (std::size_t t = 0; t < nt; ++t) {
      Bernstein<FlintRational> x{fd, {}}, y{gd, {}};
      for (const auto& c : f[t].c) x.c.emplace_back(c);
      for (const auto& c : g[t].c) y.c.emplace_back(c);
      ff.push_back(std::move(x));
      fg.push_back(std::move(y));
    }
    std::vector<const Bernstein<FlintRational>*> qf, qg;
    for (std::size_t t = 0; t < nt; ++t) {
      qf.push_back(&ff[t]);
      qg.push_back(&fg[t]);
    }
    std::vector<FlintRational> fa, fb, fout;
    for (const auto& x : a) fa.emplace_back(x);
    for (const auto& x : b) fb.emplace_back(x);
    for (const auto& x : out) fout.emplace_back(x);
    product_sums(qf, qg, fa, fb, cols, fout);
    for (std::size_t i = 0; i < got.size(); ++i) REQUIRE(fout[i].to_rational() == got[i]);
  }
  // One product alone, weights 1: exactly the product's coefficients.
  std::vector<int> d{2};
  Bernstein<Rational> f{d, {Rational(1), Rational(2, 3), Rational(-5, 7)}}, g{d, {Rational(3), Rational(0), Rational(1, 9)}};
  std::vector<const Bernstein<Rational>*> pf{&f}, pg{&g};
  std::vector<Rational> one{Rational(1)}, got(5, Rational(0));
  product_sums(pf, pg, one, one, 1, got);
  REQUIRE(got == bern_product(f, g).c);
}

namespace {

Bernstein<FlintRational> to_flint(const Bernstein<Rational>& b) {
  Bernstein<FlintRational> f;
  f.deg = b.deg;
  for (const Rational& c : b.c) f.c.emplace_back(c);
  return f;
}

Rational parameter(std::mt19937_64& rng) {
  switch (rng() % 4) {
    case 0: return Rational(1, 2);
    case 1: return Rational(static_cast<long>(rng() % 1023) + 1, 1024);
    case 2: return Rational(static_cast<long>(rng() % 6) + 1, 7);
    default: {
      const long b = static_cast<long>(rng() % 100000) + 2;
      return Rational(static_cast<long>(rng() % static_cast<std::uint64_t>(b - 1)) + 1, b);
    }
  }
}

}  // namespace

TEST_CASE("bern_split and bern_value: de Casteljau on integers equals the per-term route, and the parts agree with the whole") {
  std::mt19937_64 rng(49153);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 1 + rng() % 3;
    std::vector<int> deg(n);
    for (auto& d : deg) d = static_cast<int>(rng() % (n == 3 ? 4 : 7));
    const Bernstein<Rational> b = random_poly(rng, deg);
    const Bernstein<FlintRational> B = to_flint(b);
    const int l = static_cast<int>(rng() % n);
    const Rational t = parameter(rng);
    const auto [L, R] = bern_split(b, l, t);
    const auto [FL, FR] = bern_split(B, l, FlintRational(t));
    for (std::size_t i = 0; i < b.c.size(); ++i) {
      REQUIRE(L.c[i] == FL.c[i].to_rational());
      REQUIRE(R.c[i] == FR.c[i].to_rational());
      REQUIRE(canonical(L.c[i]));
      REQUIRE(canonical(R.c[i]));
    }
    // Values: the integer route against FLINT's per-term one, at parameters of every kind
    // (0 and 1 included), and the parts against the whole: L(u) = b(t u) in direction l.
    std::vector<Rational> x(n), y(n);
    std::vector<FlintRational> fx(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = rng() % 5 == 0 ? Rational(static_cast<long>(rng() % 2)) : parameter(rng);
      fx[k] = FlintRational(x[k]);
    }
    const Rational v = bern_value(b, x);
    REQUIRE(v == bern_value(B, fx).to_rational());
    REQUIRE(canonical(v));
    y = x;
    y[l] = t * x[l];
    REQUIRE(bern_value(L, x) == bern_value(b, y));
    y[l] = t + (1 - t) * x[l];
    REQUIRE(bern_value(R, x) == bern_value(b, y));
  }
}

TEST_CASE("bern_derivative: the differences on integers equal FLINT's per-term route, canonical, and the derivative's identity") {
  // Rational differences on integers (ArithTraits<Rational>::differences); FlintRational takes the
  // generic per-term loop, an independent route. And the coefficients are the derivative's:
  // summed back along every line of direction l (b_{i+1} = b_i + D_i / deg_l) they give b.
  std::mt19937_64 rng(49157);
  int lines = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 1 + rng() % 3;
    std::vector<int> deg(n);
    for (auto& d : deg) d = static_cast<int>(rng() % (n == 3 ? 4 : 7));
    const int l = static_cast<int>(rng() % n);
    deg[l] = std::max(deg[l], 1);
    const Bernstein<Rational> b = random_poly(rng, deg);
    const Bernstein<Rational> D = bern_derivative(b, l);
    const Bernstein<FlintRational> FD = bern_derivative(to_flint(b), l);
    REQUIRE(D.deg == FD.deg);
    for (std::size_t i = 0; i < D.c.size(); ++i) {
      REQUIRE(D.c[i] == FD.c[i].to_rational());
      REQUIRE(canonical(D.c[i]));
    }
    // The antiderivative along every line of direction l gives b back.
    const std::size_t stride = detail::tensor_stride(b.deg, l), p = static_cast<std::size_t>(deg[l]);
    for (std::size_t blk = 0; blk < b.c.size(); blk += stride * (p + 1))
      for (std::size_t j = 0; j < stride; ++j, ++lines) {
        Rational acc = b.c[blk + j];
        for (std::size_t i = 0; i < p; ++i) {
          acc += D.c[blk / (p + 1) * p + j + i * stride] / Rational(static_cast<long>(p));
          REQUIRE(acc == b.c[blk + j + (i + 1) * stride]);
        }
      }
  }
  CHECK(lines > 300);
}

TEST_CASE("bern_halves: the halves in every direction on integers equal FLINT's splits in turn, canonical, and agree with the whole") {
  // Rational halves on integers (ArithTraits<Rational>::halves, one reduction per coefficient);
  // FlintRational runs bern_split at 1/2 direction by direction, an independent route. And each
  // part is the whole on its sub-box: part K at x is b at x_l / 2 (+ 1/2 on the upper side).
  std::mt19937_64 rng(49159);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + rng() % 4;
    std::vector<int> deg(n);
    for (auto& d : deg) d = static_cast<int>(rng() % (n >= 3 ? 3 : 6));
    const Bernstein<Rational> b = random_poly(rng, deg);
    const auto H = bern_halves(b);
    const auto FH = bern_halves(to_flint(b));
    REQUIRE(H.size() == (std::size_t{1} << n));
    REQUIRE(FH.size() == H.size());
    std::vector<Rational> x(n), y(n);
    for (auto& v : x) v = parameter(rng);
    for (std::size_t K = 0; K < H.size(); ++K) {
      REQUIRE(H[K].deg == b.deg);
      for (std::size_t i = 0; i < b.c.size(); ++i) {
        REQUIRE(H[K].c[i] == FH[K].c[i].to_rational());
        REQUIRE(canonical(H[K].c[i]));
      }
      for (std::size_t l = 0; l < n; ++l) y[l] = ((K >> (n - 1 - l)) & 1 ? Rational(1, 2) : Rational(0)) + x[l] / 2;
      REQUIRE(bern_value(H[K], x) == bern_value(b, y));
    }
  }
}
