// The fraction-free net (exact/ffnet.hpp) against the GMP kernel: exact agreement, field by
// field, on the structured generator (every edge structure of GUIDE.md), under both integer tiers,
// with the same errors for illegal input.
#include <catch2/catch.hpp>

#include <functional>
#include <set>
#include <random>
#include <string>
#include <typeinfo>

#include "exact/ffnet.hpp"
#include "fixtures/random_spline.hpp"
#include "spline/kernel.hpp"

using namespace splinex;

namespace {

/// The exact agreement checked everywhere: the FF result converts to the GMP result field by
/// field, and the GMP result converts to the FF words (the reduced form is unique).
void require_same(const ff::FFNet& F, const BSpline<Rational>& S) {
  const BSpline<Rational> B = ff::to_bspline(F);
  REQUIRE(B.degrees == S.degrees);
  REQUIRE(B.knots == S.knots);
  REQUIRE(B.q == S.q);
  REQUIRE(B.points == S.points);
  REQUIRE(B.weights == S.weights);
  REQUIRE(ff::same_value(F, ff::from_bspline(S)));
}

/// Runs f and g; both must throw the same type with the same message (field and text), or
/// neither. Returns whether they threw.
bool same_outcome(const std::function<void()>& f, const std::function<void()>& g) {
  std::string ef, eg;
  const std::type_info* tf = nullptr;
  const std::type_info* tg = nullptr;
  try { f(); } catch (const Error& e) { ef = e.what(); tf = &typeid(e); }
  try { g(); } catch (const Error& e) { eg = e.what(); tg = &typeid(e); }
  CHECK(ef == eg);
  CHECK((tf == nullptr) == (tg == nullptr));
  if (tf && tg) CHECK(*tf == *tg);
  return tf != nullptr;
}

Rational random_parameter(const BSpline<Rational>& S, int d, std::mt19937_64& rng) {
  const auto& U = S.knots[d];
  const std::size_t n = S.count(d);
  const int p = S.degrees[d];
  switch (rng() % 4) {
    case 0: return U[p + rng() % (n - p + 1)];  // a knot of the domain (either end too)
    case 1: return S.domain_lo(d);
    default: return random_inside(S.domain_lo(d), S.domain_hi(d), rng, rng() % 2 == 0);
  }
}

const ff::Tier tiers[] = {ff::Tier::small_first, ff::Tier::big_only};

}  // namespace

TEST_CASE("ff: from_bspline and to_bspline are exact inverses on the structured generator") {
  std::mt19937_64 rng(49049);
  for (int it = 0; it < 400; ++it) {
    const auto c = structured_case(rng);
    INFO("case " << it);
    require_same(ff::from_bspline(c.spline), c.spline);
  }
}

TEST_CASE("ff: insert_knot equals the GMP kernel exactly, both tiers, every multiplicity") {
  std::mt19937_64 rng(49050);
  std::size_t compared = 0, refused = 0;
  for (int it = 0; it < 300; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const ff::FFNet F = ff::from_bspline(S);
    const int d = static_cast<int>(rng() % S.dim());
    const Rational x = random_parameter(S, d, rng);
    const std::size_t mult = multiplicity(S.knots[d], x);
    const int room = S.degrees[d] + 1 - static_cast<int>(std::min<std::size_t>(mult, S.degrees[d] + 1));
    const int times = static_cast<int>(rng() % (room + 2));  // sometimes one too many
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it << " dir " << d << " x " << x << " times " << times << " tier " << static_cast<int>(tier));
      if (same_outcome([&] { ff::insert_knot(F, d, x, times); }, [&] { insert_knot(S, d, x, times); })) {
        ++refused;
        continue;
      }
      require_same(ff::insert_knot(F, d, x, times), insert_knot(S, d, x, times));
      ++compared;
    }
  }
  CHECK(compared > 300);
  CHECK(refused > 20);
}

TEST_CASE("ff: refine_knots (A5.4) equals the GMP kernel exactly, both tiers") {
  std::mt19937_64 rng(49051);
  std::size_t compared = 0;
  for (int it = 0; it < 300; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const ff::FFNet F = ff::from_bspline(S);
    const int d = static_cast<int>(rng() % S.dim());
    std::vector<Rational> X;
    const int k = static_cast<int>(rng() % 7);
    for (int i = 0; i < k; ++i) {
      X.push_back(rng() % 3 ? random_inside(S.domain_lo(d), S.domain_hi(d), rng, rng() % 2 == 0) : random_parameter(S, d, rng));
      if (rng() % 6 == 0) X.push_back(X.back());
    }
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it << " dir " << d << " knots " << X.size());
      if (same_outcome([&] { ff::refine_knots(F, d, X); }, [&] { refine_knots(S, d, X); })) continue;
      require_same(ff::refine_knots(F, d, X), refine_knots(S, d, X));
      ++compared;
    }
  }
  CHECK(compared > 300);
}

TEST_CASE("ff: evaluate_points equals the GMP kernel exactly, both tiers, domain ends included") {
  std::mt19937_64 rng(49052);
  for (int it = 0; it < 300; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const ff::FFNet F = ff::from_bspline(S);
    std::vector<Rational> params;
    for (int i = 0; i < 4; ++i)
      for (int d = 0; d < S.dim(); ++d) params.push_back(i == 3 ? S.domain_hi(d) : random_parameter(S, d, rng));
    const auto expected = evaluate_points(S, params);
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it);
      REQUIRE(ff::to_points(ff::evaluate_points(F, params)) == expected);
    }
  }
}

TEST_CASE("ff: illegal input gets the kernel's errors") {
  std::mt19937_64 rng(49053);
  RandomSplineSpec spec;
  spec.degrees = {3, 2};
  spec.counts = {6, 5};
  const auto S = random_spline(spec, rng);
  const auto F = ff::from_bspline(S);
  const Rational out(3, 2), in(1, 3);
  CHECK(same_outcome([&] { ff::insert_knot(F, 2, in); }, [&] { insert_knot(S, 2, in, 1); }));
  CHECK(same_outcome([&] { ff::insert_knot(F, 0, in, -1); }, [&] { insert_knot(S, 0, in, -1); }));
  CHECK(same_outcome([&] { ff::insert_knot(F, 1, out); }, [&] { insert_knot(S, 1, out, 1); }));
  CHECK(same_outcome([&] { ff::insert_knot(F, 0, in, 5); }, [&] { insert_knot(S, 0, in, 5); }));
  CHECK(same_outcome([&] { ff::insert_knot(F, 0, in, 2, Limits{.max_control_points = 10}); },
                     [&] { insert_knot(S, 0, in, 2, Limits{.max_control_points = 10}); }));
  CHECK(same_outcome([&] { ff::refine_knots(F, 0, {in, in, in, in, in}); }, [&] { refine_knots(S, 0, {in, in, in, in, in}); }));
  CHECK(same_outcome([&] { ff::refine_knots(F, 1, {in, out}); }, [&] { refine_knots(S, 1, {in, out}); }));
  CHECK(same_outcome([&] { ff::evaluate_points(F, {in}); }, [&] { evaluate_points(S, {in}); }));
  CHECK(same_outcome([&] { ff::evaluate_points(F, {in, out}); }, [&] { evaluate_points(S, {in, out}); }));
}

TEST_CASE("ff: products past 2^62 fall back to big integers and stay exact") {
  // Coordinates near 2^61 and knots over 2^31: the small tier overflows in the first blend.
  std::mt19937_64 rng(49054);
  const Integer big = Integer(1) << 61;
  for (const bool rational : {false, true}) {
    BSpline<Rational> S;
    S.degrees = {3};
    S.q = 2;
    const Rational h(1, Integer(1) << 31);
    S.knots = {{0, 0, 0, 0, h, 2 * h, 1 - h, 1, 1, 1, 1}};
    for (int i = 0; i < 7; ++i) {
      S.points.push_back(Rational(big + i * 12345 + 1, 3));
      S.points.push_back(Rational(-big - i, 7));
      if (rational) S.weights.push_back(Rational(big - i, i + 1));
    }
    validate(S);
    const auto F = ff::from_bspline(S);
    const Rational x(5, (Integer(1) << 31) * 3);
    ff::promotions() = 0;
    require_same(ff::insert_knot(F, 0, x, 2), insert_knot(S, 0, x, 2));
    require_same(ff::refine_knots(F, 0, {x, Rational(1, 2), Rational(1, 2)}), refine_knots(S, 0, {x, Rational(1, 2), Rational(1, 2)}));
    const std::vector<Rational> at{x, Rational(1, 3), 1};
    REQUIRE(ff::to_points(ff::evaluate_points(F, at)) == evaluate_points(S, at));
    CHECK(ff::promotions() > 0);
  }
}

TEST_CASE("ff: values at the edge of FLINT's small range (2^62 - 1) convert and insert exactly") {
  const Integer cmax = (Integer(1) << 62) - 1;
  BSpline<Rational> S;
  S.degrees = {1};
  S.q = 1;
  S.knots = {{0, 0, 1, 1}};
  S.points = {Rational(cmax), Rational(-cmax)};
  const auto F = ff::from_bspline(S);
  require_same(F, S);
  for (const ff::Tier tier : tiers) {
    ff::PolicyScope scope({tier});
    require_same(ff::insert_knot(F, 0, Rational(1, 2)), insert_knot(S, 0, Rational(1, 2), 1));
    require_same(ff::insert_knot(F, 0, Rational(1, 3), 2), insert_knot(S, 0, Rational(1, 3), 2));
  }
}

TEST_CASE("ff: the agreement check sees a one-unit difference (planted)") {
  std::mt19937_64 rng(49055);
  RandomSplineSpec spec;
  spec.degrees = {2};
  spec.counts = {5};
  const auto S = random_spline(spec, rng);
  auto F = ff::insert_knot(ff::from_bspline(S), 0, Rational(1, 3));
  const auto R = insert_knot(S, 0, Rational(1, 3), 1);
  REQUIRE(ff::same_value(F, ff::from_bspline(R)));
  fmpz_add_ui(F.words + 2 * F.stride(), F.words + 2 * F.stride(), 1);  // one numerator of a new point
  CHECK_FALSE(ff::same_value(F, ff::from_bspline(R)));
  CHECK_FALSE(ff::to_bspline(F).points == R.points);
}

TEST_CASE("ff: heap bytes of a small-valued net are 8 per stored integer") {
  std::mt19937_64 rng(49056);
  RandomSplineSpec spec;
  spec.degrees = {3};
  spec.counts = {1000};
  spec.dyadic = true;
  const auto F = ff::from_bspline(random_spline(spec, rng));
  CHECK(ff::heap_bytes(F) == 8 * (F.size() * F.stride() + F.knots[0].size() + 1));
}

TEST_CASE("ff: clamp, Bezier form and pieces equal the GMP kernel exactly, both tiers") {
  std::mt19937_64 rng(49057);
  std::size_t pieces_compared = 0;
  for (int it = 0; it < 250; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const ff::FFNet F = ff::from_bspline(S);
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it);
      const int d = static_cast<int>(rng() % S.dim());
      require_same(ff::clamp(F, d), clamp(S, d));
      const Limits small{.max_control_points = 20000};
      if (same_outcome([&] { ff::bezier_form(F, small); }, [&] { bezier_form(S, small); })) continue;
      const auto B = ff::bezier_form(F, small);
      const auto K = bezier_form(S, small);
      require_same(B.spline, K.spline);
      REQUIRE(B.break_values() == K.breaks);
      REQUIRE(B.first == K.first);
      REQUIRE(B.size() == K.size());
      if (K.size() > 64) continue;
      const auto P = ff::extract_bezier(F);
      const auto Q = extract_bezier(S);
      REQUIRE(P.size() == Q.size());
      for (std::size_t i = 0; i < P.size(); ++i) require_same(P[i], Q[i].spline);
      pieces_compared += P.size();
    }
  }
  CHECK(pieces_compared > 1000);
}

TEST_CASE("ff: elevate_degree (A5.9) equals the GMP kernel exactly, both tiers, C^-1 knots and degree 0") {
  std::mt19937_64 rng(49058);
  std::size_t compared = 0;
  for (int it = 0; it < 250; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const ff::FFNet F = ff::from_bspline(S);
    const int d = static_cast<int>(rng() % S.dim());
    const int t = static_cast<int>(rng() % 4);
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it << " dir " << d << " by " << t);
      const Limits lim{.max_control_points = 50000};
      if (same_outcome([&] { ff::elevate_degree(F, d, t, lim); }, [&] { elevate_degree(S, d, t, ElevationMethod::automatic, lim); }))
        continue;
      require_same(ff::elevate_degree(F, d, t, lim), elevate_degree(S, d, t, ElevationMethod::automatic, lim));
      ++compared;
    }
  }
  CHECK(compared > 400);
  // The kernel's errors for illegal amounts and directions.
  std::mt19937_64 r2(1);
  const auto S = structured_case(r2).spline;
  const auto F = ff::from_bspline(S);
  CHECK(same_outcome([&] { ff::elevate_degree(F, 0, -1); }, [&] { elevate_degree(S, 0, -1); }));
  CHECK(same_outcome([&] { ff::elevate_degree(F, 5, 1); }, [&] { elevate_degree(S, 5, 1); }));
  CHECK(same_outcome([&] { ff::elevate_degree(F, 0, 200); }, [&] { elevate_degree(S, 0, 200); }));
}

TEST_CASE("ff: elevation by one at degree >= 3 (the blossom) equals the GMP kernel's A5.9, every structure, both tiers") {
  // The fraction-free kernel elevates by one at p >= 3 through the symmetrized blossom and the GMP
  // kernel by A5.9: two algorithms, one exact answer. Every structure of the generator (C^-1 knots,
  // unclamped ends, gaps of 2^-1100, rational with extreme weights) in every direction.
  std::mt19937_64 rng(49071);
  std::size_t compared = 0;
  std::set<std::string> seen;
  for (int it = 0; it < 400 && compared < 240; ++it) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const int d = static_cast<int>(rng() % S.dim());
    if (S.degrees[d] < 3) continue;
    for (const auto& s : c.structures) seen.insert(s);
    const ff::FFNet F = ff::from_bspline(S);
    for (const ff::Tier tier : tiers) {
      ff::PolicyScope scope({tier});
      INFO("case " << it << " dir " << d << " degree " << S.degrees[d]);
      const Limits lim{.max_control_points = 50000};
      if (same_outcome([&] { ff::elevate_degree(F, d, 1, lim); }, [&] { elevate_degree(S, d, 1, ElevationMethod::bezier_pieces, lim); }))
        continue;
      require_same(ff::elevate_degree(F, d, 1, lim), elevate_degree(S, d, 1, ElevationMethod::bezier_pieces, lim));
      ++compared;
    }
  }
  CHECK(compared >= 120);
  for (const char* s : {"C^-1 knot", "unclamped", "rational", "single span"}) {
    INFO(s);
    CHECK(seen.count(s) == 1);
  }
}

TEST_CASE("ff: elevation by one at p = 3..7 on long dyadic and decimal curves equals the GMP kernel") {
  // The benchmark's inputs (random clamped curves in R^3, simple knots): many spans, so the span
  // walk and the shortcuts of the blossom's triangles meet every neighbour pattern.
  for (const bool dyadic : {true, false})
    for (int p = 3; p <= 7; ++p) {
      std::mt19937_64 rng(4900 + p);
      RandomSplineSpec spec;
      spec.degrees = {p};
      spec.counts = {static_cast<std::size_t>(60 + 7 * p)};
      spec.q = 3;
      spec.dyadic = dyadic;
      spec.max_interior_multiplicity = 1 + p % 3;
      const BSpline<Rational> S = random_spline(spec, rng);
      INFO("p " << p << (dyadic ? " dyadic" : " decimal"));
      require_same(ff::elevate_degree(ff::from_bspline(S), 0, 1), elevate_degree(S, 0, 1, ElevationMethod::bezier_pieces));
    }
}
