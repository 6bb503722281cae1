// papers/004 for d = 3: solids bounded by surface facets, cutting loops, the guiding surface exactly
// and in double, certified separation (also of hand-made guides that must fail).
#include <catch2/catch.hpp>

#include "base/errors.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"

using namespace splinex;

namespace {
Rational q(long a, long b = 1) { return Rational(a, b); }

// The coefficients of a polynomial of degree <= 2 in each variable in the cubic basis of U: by
// blossoming, t^0 -> 1, t -> (a + b + c)/3, t^2 -> (ab + ac + bc)/3 for the knots a, b, c of N_i.
std::vector<Rational> power_coefficients(const std::vector<Rational>& U, int power) {
  std::vector<Rational> c;
  for (std::size_t i = 0; i + 4 < U.size(); ++i) {
    const Rational &a = U[i + 1], &b = U[i + 2], &d = U[i + 3];
    c.push_back(power == 0 ? q(1) : power == 1 ? Rational((a + b + d) / 3) : Rational((a * b + a * d + b * d) / 3));
  }
  return c;
}
}  // namespace

TEST_CASE("cut3: the thin-plate matrix in three variables against energies known in closed form", "[cut]") {
  // f = x^2 + y z + x y: f_xx = 2, f_xy = 1, f_yz = 1, so the energy over [0,1]^3 is
  // 2^2 + 2 (1^2 + 1^2) = 8. Different knots per direction.
  const std::array<std::vector<Rational>, 3> U{guide_knots(1), guide_knots(2), guide_knots(0)};
  const auto M = regularization_matrix3(U);
  std::array<std::array<std::vector<Rational>, 3>, 3> P;  // P[a][p]: coefficients of t^p in direction a
  for (int a = 0; a < 3; ++a)
    for (int p = 0; p < 3; ++p) P[a][p] = power_coefficients(U[a], p);
  const std::size_t nx = P[0][0].size(), ny = P[1][0].size(), nz = P[2][0].size(), N = nx * ny * nz;
  REQUIRE(M.size() == N * N);
  std::vector<Rational> c(N);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        c[i + nx * (j + ny * k)] = P[0][2][i] * P[1][0][j] * P[2][0][k] + P[0][0][i] * P[1][1][j] * P[2][1][k] + P[0][1][i] * P[1][1][j] * P[2][0][k];
  Rational e(0);
  for (std::size_t I = 0; I < N; ++I)
    for (std::size_t J = 0; J < N; ++J) e += c[I] * M[I * N + J] * c[J];
  CHECK(e == q(8));
  // An affine function has no energy.
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) c[i + nx * (j + ny * k)] = 3 * P[0][1][i] - P[1][1][j] + 5 * P[2][1][k] + 7;
  e = 0;
  for (std::size_t I = 0; I < N; ++I)
    for (std::size_t J = 0; J < N; ++J) e += c[I] * M[I * N + J] * c[J];
  CHECK(e == 0);
}

TEST_CASE("cut3: solids of surface facets and cutting loops are validated with typed errors", "[cut]") {
  const auto cube = cut_example3("cube");
  CHECK(cube.solid.facets.size() == 24);
  CHECK(signed_volume(cube.solid) == q(8));
  CHECK(signed_volume(cut_example3("slotted").solid) == q(16));  // 5 * 2 * 1 + 3 teeth of 1 * 2 * 1
  CHECK(signed_volume(cut_example3("maiden").solid) == q(15));   // 20 minus two spikes of 5/2
  const auto loop = validate_cut(cube.solid, cube.cut);
  CHECK(loop.size() == 8);
  for (std::size_t m = 0; m < loop.size(); ++m) {
    CHECK(loop[m].end == loop[(m + 1) % loop.size()].start);  // one closed cycle
    CHECK(loop[m].start[2] == 1);
    CHECK(loop[m].normal[2] > 0);  // towards b (above)
    const Rational len2 = loop[m].normal[0] * loop[m].normal[0] + loop[m].normal[1] * loop[m].normal[1] + loop[m].normal[2] * loop[m].normal[2];
    CHECK(abs(len2 - 1) < Rational(1, Integer(1) << 38));
  }
  CHECK(validate_cut(cut_example3("maiden").solid, cut_example3("maiden").cut).size() == 34);
  CHECK(validate_cut(cut_example3("slotted").solid, cut_example3("slotted").cut).size() == 4);

  // A facet turned inside out: its sides no longer run against its neighbours'.
  auto flipped = cube.solid;
  flipped.facets[0] = reverse(flipped.facets[0], 0);
  CHECK_THROWS_WITH(validate_solid(flipped), Catch::Contains("facets[") && Catch::Contains("no other facet shares"));
  // All facets inside out: watertight, negative volume.
  auto inside_out = cube.solid;
  for (auto& F : inside_out.facets) F = reverse(F, 0);
  CHECK_THROWS_WITH(validate_solid(inside_out), Catch::Contains("oriented inwards"));
  // A missing facet: a hole.
  auto hole = cube.solid;
  hole.facets.pop_back();
  CHECK_THROWS_AS(validate_solid(hole), ValidationError);
  // A rational facet.
  auto rat = cube.solid;
  rat.facets[3].weights.assign(4, q(1));
  rat.facets[3].weights[0] = q(2);
  CHECK_THROWS_WITH(validate_solid(rat), Catch::Contains("facets[3]") && Catch::Contains("rational"));
  // A curve is not a facet.
  auto curve = cube.solid;
  curve.facets[1] = make_spline<Rational>({1}, {clamped_knots<Rational>(1, q(0), q(1))}, 3, {q(0), q(0), q(0), q(1), q(0), q(0)});
  CHECK_THROWS_WITH(validate_solid(curve), Catch::Contains("facets[1]") && Catch::Contains("not a surface"));

  // Cutting data: a tangent pointing out, in a facet's plane, missing; b empty, all, out of range;
  // two loops.
  auto out = cube.cut;
  out.tangents[0].tangent = {-out.tangents[0].tangent[0], -out.tangents[0].tangent[1], -out.tangents[0].tangent[2]};
  CHECK_THROWS_WITH(validate_cut(cube.solid, out), Catch::Contains("tangents[0].tangent") && Catch::Contains("strictly into"));
  auto flat = cube.cut;
  flat.tangents[2].tangent = {q(0), q(0), q(1)};  // along the wall: in both facets' planes
  CHECK_THROWS_WITH(validate_cut(cube.solid, flat), Catch::Contains("tangents[2].tangent"));
  auto tilted = cube.cut;  // tilted upwards but still into the solid: accepted
  for (auto& t : tilted.tangents) t.tangent[2] = q(1, 3);
  CHECK_NOTHROW(validate_cut(cube.solid, tilted));
  auto missing = cube.cut;
  missing.tangents.pop_back();
  CHECK_THROWS_WITH(validate_cut(cube.solid, missing), Catch::Contains("tangents") && Catch::Contains("no tangent"));
  auto twice = cube.cut;
  twice.tangents.push_back(twice.tangents[0]);
  CHECK_THROWS_WITH(validate_cut(cube.solid, twice), Catch::Contains("repeats"));
  auto stray = cube.cut;
  stray.tangents[0].side = (stray.tangents[0].side + 2) % 4;  // the facet's side away from the loop
  CHECK_THROWS_AS(validate_cut(cube.solid, stray), ValidationError);
  CutData3 none;
  CHECK_THROWS_WITH(validate_cut(cube.solid, none), Catch::Contains("positive"));
  CutData3 all;
  for (std::size_t i = 0; i < cube.solid.facets.size(); ++i) all.positive.push_back(i);
  CHECK_THROWS_WITH(validate_cut(cube.solid, all), Catch::Contains("every facet"));
  CutData3 far;
  far.positive = {99};
  CHECK_THROWS_WITH(validate_cut(cube.solid, far), Catch::Contains("positive[0]"));
  // b = the top and the bottom face: two loops.
  CutData3 two;
  for (std::size_t i = 0; i < cube.solid.facets.size(); ++i) {
    const auto& F = cube.solid.facets[i];
    const bool top = F.points[2] == 2 && F.points[5] == 2 && F.points[8] == 2 && F.points[11] == 2;
    const bool bottom = F.points[2] == 0 && F.points[5] == 0 && F.points[8] == 0 && F.points[11] == 0;
    if (top || bottom) two.positive.push_back(i);
  }
  REQUIRE(two.positive.size() == 8);
  CHECK_THROWS_WITH(validate_cut(cube.solid, two), Catch::Contains("several loops"));
}

TEST_CASE("cut3: certified separation of hand-made guides, one that must fail", "[cut]") {
  // The cube normalized to [0,1]^3: the loop at z = 1/2, b above. f = z - 1/2 separates exactly
  // (zero only on the loop, excluded by the strip); f = z - 3/4 is negative on b's facets between
  // z = 1/2 and 3/4; f = (z - 1/2)(x - 2)... changes the sign on b-bar near x = ... never (x <= 1),
  // f = 1/2 - z separates the wrong way round.
  const auto e = cut_example3("cube");
  const auto solid = to_frame(e.solid, unit_frame(e.solid));
  const auto loop = validate_cut(solid, e.cut);
  auto linear_in_z = [](const Rational& c0, const Rational& c1) {
    // c0 + c1 z as a trivariate cubic (coefficients linear in the z Greville abscissae)
    const auto U = guide_knots(0);
    std::vector<Rational> pts;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) pts.push_back(c0 + c1 * Rational(k, 3));
    return make_spline<Rational>({3, 3, 3}, {U, U, U}, 1, pts);
  };
  const Rational strip(1, 16);
  const auto good = certify_separation(solid, loop, e.cut.positive, linear_in_z(q(-1, 2), q(1)), strip);
  CHECK(good.verdict.is_proved());
  CHECK(good.excluded > 0);
  const auto high = certify_separation(solid, loop, e.cut.positive, linear_in_z(q(-3, 4), q(1)), strip);
  REQUIRE(high.verdict.is_refuted());
  REQUIRE(high.witness);
  CHECK(high.witness->positive_side);
  CHECK(high.witness->point[2] > q(1, 2));
  CHECK(high.witness->point[2] <= q(3, 4));
  CHECK(high.witness->value == high.witness->point[2] - q(3, 4));
  const auto wrong = certify_separation(solid, loop, e.cut.positive, linear_in_z(q(1, 2), q(-1)), strip);
  CHECK(wrong.verdict.is_refuted());
}

TEST_CASE("cut3: the guiding surface of the cube exactly (KKT, positive definite), certified, and in double judged exactly", "[cut]") {
  const auto e = cut_example3("cube");
  GuideOptions3 o;
  o.base.inner_knots = 0;
  o.base.samples = 2;
  o.loop_samples = 2;
  const auto R = guide_surface<Rational>(e.solid, e.cut, o);
  REQUIRE(R.status == QPStatus::optimal);
  CHECK(R.kkt.holds);
  CHECK(R.positive_definite);
  CHECK(R.samples_positive + R.samples_negative == 24 * 4);
  const auto sep = certify_separation(R.solid, R.loop, e.cut.positive, R.f_exact, o.base.strip);
  CHECK(sep.verdict.is_proved());
  // By the symmetry of the data under x -> 1 - x, y -> 1 - y and x <-> y, and the uniqueness of the
  // minimizer (Lemma 1), f* takes equal values at mirrored points.
  const std::vector<Rational> p{q(1, 5), q(2, 7), q(3, 5)}, pm{q(4, 5), q(2, 7), q(3, 5)}, ps{q(2, 7), q(1, 5), q(3, 5)};
  CHECK(evaluate(R.f_exact, p) == evaluate(R.f_exact, pm));
  CHECK(evaluate(R.f_exact, p) == evaluate(R.f_exact, ps));
  const auto D = guide_surface<double>(e.solid, e.cut, o);
  REQUIRE(D.status == QPStatus::optimal);
  Rational err(0), mag(0);
  for (std::size_t i = 0; i < R.coefficients.size(); ++i) {
    err = std::max(err, Rational(abs(D.f_exact.points[i] - R.coefficients[i])));
    mag = std::max(mag, Rational(abs(R.coefficients[i])));
  }
  CHECK(mag > 0);
  CHECK(err <= mag * Rational(1, Integer(1) << 30));  // the double program is the exact one rounded
}

