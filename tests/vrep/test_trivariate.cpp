// Trivariate constructors and certified regularity (issue 17, papers/002 Sections 3.2.2-3.2.3):
// each constructor proved by identity, regularity decided against an independent route (the
// kernel's derivatives, evaluated exactly).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "spline/kernel.hpp"
#include "fixtures/teapot.hpp"
#include "tests/helpers.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/regularity_impl.hpp"  // vrep_detail::jacobian_numerator_fused, _expanded
#include "vrep/model/trivariate.hpp"

using namespace splinex;
using splinex::test::q;
using splinex::test::spline;

namespace {

using R = Rational;

/// A curved polynomial surface in R^3 with interior knots in both directions.
BSpline<R> warped_surface() {
  return spline(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, "1/3", 1, 1, 1], [0, 0, "1/2", 1, 1]],
    "points": [[0,0,0],[1,"1/5",0],[2,0,"1/3"],[3,"1/7",0], [0,1,"1/2"],[1,1,1],[2,"6/5",0],[3,1,"1/4"],
               ["1/9",2,0],[1,2,"1/3"],[2,"11/5",0],[3,2,"1/2"]]})");
}

/// A rational profile surface in the xz-plane half-space x > 0.
BSpline<R> rational_profile() {
  return spline(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, 1, 1, 1], [0, 0, 1, 1]],
    "points": [[1,0,0],[2,0,"1/2"],[1,0,1], ["3/2",0,0],["5/2",0,"1/2"],["3/2",0,1]], "weights": [1, 2, 1, 1, 3, 1]})");
}

/// The homogeneous coordinates (w x_0, ..., w) of S at x, exactly.
std::vector<R> homogeneous_at(const BSpline<R>& S, const std::vector<R>& x) {
  auto v = evaluate(S, x);
  R w(1);
  if (S.is_rational()) {
    BSpline<R> W = S;
    W.q = 1;
    W.points = S.weights;
    W.weights.clear();
    w = evaluate(W, x)[0];
  }
  for (auto& c : v) c *= w;
  v.push_back(w);
  return v;
}

/// det J at x from the kernel's derivatives (A2.3 / A4.4), exactly: an independent route.
R det_at(const BSpline<R>& V, const std::vector<R>& x) {
  R J[3][3];
  for (int c = 0; c < 3; ++c) {
    std::vector<int> ord(3, 0);
    ord[c] = 1;
    const auto d = derivative(V, x, ord);
    for (int r = 0; r < 3; ++r) J[r][c] = d[r];
  }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

/// A grid of n^3 exact points of V's domain.
std::vector<std::vector<R>> grid(const BSpline<R>& V, int n) {
  std::vector<std::vector<R>> out;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c) {
        const int i[3] = {a, b, c};
        std::vector<R> x(3);
        for (int d = 0; d < 3; ++d) x[d] = V.domain_lo(d) + (V.domain_hi(d) - V.domain_lo(d)) * R(2 * i[d] + 1) / R(2 * n);
        out.push_back(x);
      }
  return out;
}

/// The same function: brought to a common space (exact elevation and insertion), the nets agree.
bool same_function(const BSpline<R>& A, const BSpline<R>& B) {
  auto [a, b] = make_compatible(A, B);
  return same_net(a, b);
}

/// The identity map of the box [0, 1]^3 at degrees p and knots U (control points at the Greville
/// abscissae: linear precision), optionally with some control points moved.
BSpline<R> identity_cube(int p, const std::vector<R>& U) {
  const std::vector<std::vector<R>> K{U, U, U};
  auto g = [&](std::size_t i) {
    R s(0);
    for (int k = 1; k <= p; ++k) s += U[i + k];
    return s / R(p);
  };
  return spline_from<R>({p, p, p}, K, 3, [&](const std::vector<std::size_t>& i) { return std::vector<R>{g(i[0]), g(i[1]), g(i[2])}; });
}

}  // namespace

TEST_CASE("vrep extrude: faces are the surface and its translate, T = S + V w exactly") {
  for (const auto& S : {warped_surface(), rational_profile()}) {
    const std::vector<R> V{q("1/3"), q("-2"), q("5/7")};
    const auto T = extrude(S, V);
    CHECK(same_net(face(T, 2, 0), S));
    auto moved = S;
    for (std::size_t i = 0; i < moved.size(); ++i)
      for (int c = 0; c < 3; ++c) moved.points[i * 3 + c] += V[c];
    CHECK(same_net(face(T, 2, 1), moved));
    for (const auto& x : grid(T, 3)) {
      const auto t = evaluate(T, x), s = evaluate(S, {x[0], x[1]});
      for (int c = 0; c < 3; ++c) CHECK(t[c] == s[c] + V[c] * x[2]);
    }
  }
  CHECK_THROWS_AS(extrude(warped_surface(), {R(1)}), ValidationError);
}

TEST_CASE("vrep ruled: faces equal the two surfaces exactly after a common space, rulings straight") {
  const auto S1 = warped_surface();
  const auto S2 = spline(R"({"type": "bspline", "degrees": [1, 2], "knots": [[0, 0, "1/4", 1, 1], [0, 0, 0, 1, 1, 1]],
    "points": [[0,0,5],[1,0,6],[3,0,5], [0,1,5],[1,1,7],[3,1,6], [0,2,5],[1,2,5],[3,2,6]]})");
  const auto T = ruled(S1, S2);
  CHECK(T.degrees == std::vector<int>{2, 2, 1});
  CHECK(same_function(face(T, 2, 0), S1));
  CHECK(same_function(face(T, 2, 1), S2));
  for (const auto& x : grid(T, 3)) {  // T(u, v, w) = (1 - w) S1 + w S2 for polynomial surfaces
    const auto t = evaluate(T, x), a = evaluate(S1, {x[0], x[1]}), b = evaluate(S2, {x[0], x[1]});
    for (int c = 0; c < 3; ++c) CHECK(t[c] == (1 - x[2]) * a[c] + x[2] * b[c]);
  }
  // Rational: the faces are the surfaces; every ruling lies on the segment S1(u, v) S2(u, v).
  const auto P = rational_profile();
  auto P2 = P;
  for (std::size_t i = 0; i < P2.size(); ++i) P2.points[i * 3 + 1] += 3;
  const auto Tr = ruled(P, P2);
  CHECK(same_function(face(Tr, 2, 0), P));
  CHECK(same_function(face(Tr, 2, 1), P2));
  for (const auto& x : grid(Tr, 3)) {
    const auto t = evaluate(Tr, x), a = evaluate(P, {x[0], x[1]}), b = evaluate(P2, {x[0], x[1]});
    // collinear: (t - a) x (b - a) = 0, and between: 0 <= (t - a).(b - a) <= |b - a|^2
    R cross[3], dot(0), len(0);
    for (int c = 0; c < 3; ++c) {
      dot += (t[c] - a[c]) * (b[c] - a[c]);
      len += (b[c] - a[c]) * (b[c] - a[c]);
      cross[c] = (t[(c + 1) % 3] - a[(c + 1) % 3]) * (b[(c + 2) % 3] - a[(c + 2) % 3]) -
                 (t[(c + 2) % 3] - a[(c + 2) % 3]) * (b[(c + 1) % 3] - a[(c + 1) % 3]);
    }
    CHECK((cross[0] == 0 && cross[1] == 0 && cross[2] == 0));
    CHECK((0 <= dot && dot <= len));
  }
  CHECK_THROWS_AS(ruled(S1, spline(R"({"type": "bspline", "degrees": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
    "points": [[0,0],[1,0],[0,1],[1,1]]})")), ValidationError);
}

TEST_CASE("vrep revolve: exact rational circles, proved on the circle by a degree-bound identity") {
  for (int quarters = 1; quarters <= 4; ++quarters) {
    const auto C = rational_circle<R>(quarters);
    for (int i = 0; i <= 40; ++i) {
      const auto p = evaluate(C, {R(i, 40)});
      CHECK(p[0] * p[0] + p[1] * p[1] == 1);
    }
    CHECK(evaluate(C, {R(1)}) == std::vector<R>{R(quarters == 1 || quarters == 3 ? 0 : quarters == 2 ? -1 : 1),
                                                  R(quarters == 1 ? 1 : quarters == 3 ? -1 : 0)});
  }
  for (const auto& S : {rational_profile(), warped_surface()}) {
    for (int axis = 0; axis < 3; ++axis) {
      const auto T = revolve(S, axis, 4);
      CHECK(same_net(face(T, 2, 0), [&] {
        auto s = S;
        if (!s.is_rational()) s.weights.assign(s.size(), R(1));
        return s;
      }()));
      // Identity per Bezier piece: (A^2 + B^2) W_S^2 = (A_S^2 + B_S^2) W^2 and Z W_S = Z_S W in
      // homogeneous coordinates (A, B the rotated pair, Z the axis coordinate), polynomials of
      // degree at most (4p, 4q, 4) on each piece: equal at 4p+1 x 4q+1 x 5 points of every piece
      // means equal everywhere.
      const int ia = (axis + 1) % 3, ib = (axis + 2) % 3;
      std::size_t points = 0;
      for (const auto& pc : extract_bezier(T)) {
        const int n0 = 4 * T.degrees[0] + 1, n1 = 4 * T.degrees[1] + 1, n2 = 5;
        for (int a = 0; a < n0; ++a)
          for (int b = 0; b < n1; ++b)
            for (int c = 0; c < n2; ++c) {
              const std::vector<R> x{pc.box[0].first + (pc.box[0].second - pc.box[0].first) * R(a, n0 - 1),
                                     pc.box[1].first + (pc.box[1].second - pc.box[1].first) * R(b, n1 - 1),
                                     pc.box[2].first + (pc.box[2].second - pc.box[2].first) * R(c, n2 - 1)};
              const auto h = homogeneous_at(T, x), hs = homogeneous_at(S, {x[0], x[1]});
              const R W = h[3], WS = hs[3];
              REQUIRE((h[ia] * h[ia] + h[ib] * h[ib]) * WS * WS == (hs[ia] * hs[ia] + hs[ib] * hs[ib]) * W * W);
              REQUIRE(h[axis] * WS == hs[axis] * W);
              ++points;
            }
      }
      CHECK(points > 0);
    }
  }
  const auto half = revolve(rational_profile(), 2, 2);  // half a turn ends at the profile rotated by 180 degrees
  auto flipped = rational_profile();
  for (std::size_t i = 0; i < flipped.size(); ++i) {
    flipped.points[i * 3] = -flipped.points[i * 3];
    flipped.points[i * 3 + 1] = -flipped.points[i * 3 + 1];
  }
  CHECK(same_function(face(half, 2, 1), flipped));
  CHECK_THROWS_AS(revolve(warped_surface(), 3), ValidationError);
  CHECK_THROWS_AS(rational_circle<R>(5), ValidationError);
}

TEST_CASE("vrep boolean sum: the trivariate Coons volume reproduces its six faces exactly") {
  // The faces of a curved trivariate V (degrees 2, 1, 3 with interior knots).
  const std::vector<std::vector<R>> K{{0, 0, 0, q("1/2"), 1, 1, 1}, {0, 0, q("1/3"), 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}};
  const auto V = spline_from<R>({2, 1, 3}, K, 3, [](const std::vector<std::size_t>& i) {
    const R a(static_cast<long>(i[0])), b(static_cast<long>(i[1])), c(static_cast<long>(i[2]));
    return std::vector<R>{a + b * c / 7, b + a * a / 5, c + (a * b) / 3};
  });
  std::array<std::array<BSpline<R>, 2>, 3> F;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) F[d][s] = face(V, d, s);
  const auto T = boolean_sum(F);
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) CHECK(same_net(face(T, d, s), F[d][s]));
  // A trilinear volume is its own Coons volume.
  const auto L = spline_from<R>({1, 1, 1}, {{0, 0, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}}, 3, [](const std::vector<std::size_t>& i) {
    return std::vector<R>{R(static_cast<long>(i[0])) + R(static_cast<long>(i[1] * i[2])) / 3, R(static_cast<long>(i[1])),
                          R(static_cast<long>(i[2])) * 2};
  });
  std::array<std::array<BSpline<R>, 2>, 3> FL;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) FL[d][s] = face(L, d, s);
  CHECK(same_net(boolean_sum(FL), L));
  // Faces of different degrees and knots are made compatible; the result still has them as faces.
  auto G = F;
  G[0][0] = elevate_degree(G[0][0], 0, 1);
  G[2][1] = refine_knots(G[2][1], 0, {q("1/4")});
  const auto T2 = boolean_sum(G);
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) CHECK(same_function(face(T2, d, s), G[d][s]));
  // Faces that do not meet along an edge are refused, naming them.
  auto bad = F;
  bad[2][1].points[0] += 1;
  try {
    boolean_sum(bad);
    FAIL("accepted faces that do not meet");
  } catch (const ValidationError& e) {
    CHECK(std::string(e.what()).find("w1") != std::string::npos);
  }
}

namespace {

/// The four boundary curves of a clamped surface: [0][s] at u = s (a curve in v), [1][s] at v = s
/// (a curve in u), read off the net's boundary rows.
std::array<std::array<BSpline<R>, 2>, 2> boundary_curves(const BSpline<R>& S) {
  std::array<std::array<BSpline<R>, 2>, 2> C;
  const std::size_t nu = S.count(0), nv = S.count(1), qq = static_cast<std::size_t>(S.q);
  for (int s = 0; s < 2; ++s) {
    for (int d = 0; d < 2; ++d) {
      C[d][s].degrees = {S.degrees[1 - d]};
      C[d][s].knots = {S.knots[1 - d]};
      C[d][s].q = S.q;
    }
    for (std::size_t j = 0; j < nv; ++j)
      for (std::size_t c = 0; c < qq; ++c) C[0][s].points.push_back(S.points[((s ? nu - 1 : 0) + nu * j) * qq + c]);
    for (std::size_t i = 0; i < nu; ++i)
      for (std::size_t c = 0; c < qq; ++c) C[1][s].points.push_back(S.points[(i + nu * (s ? nv - 1 : 0)) * qq + c]);
  }
  return C;
}

}  // namespace

TEST_CASE("vrep coons_surface: interpolates its four curves, reproduces what it can represent, exactly") {
  std::mt19937_64 rng(5013);
  auto r = [&] { return R(static_cast<long>(rng() % 2001) - 1000, 97); };
  // A bicubic surface with interior knots and random points: not a Coons surface itself, but the
  // Coons surface of its boundary has that boundary, and is its own Coons surface (idempotence).
  const std::vector<std::vector<R>> K{{0, 0, 0, 0, q("1/3"), q("1/2"), 1, 1, 1, 1}, {0, 0, 0, 0, q("2/5"), 1, 1, 1, 1}};
  const auto S = spline_from<R>({3, 3}, K, 3, [&](const std::vector<std::size_t>&) { return std::vector<R>{r(), r(), r()}; });
  const auto C = boundary_curves(S);
  const auto P = coons_surface(C);
  const auto B = boundary_curves(P);
  for (int d = 0; d < 2; ++d)
    for (int s = 0; s < 2; ++s) CHECK(same_function(B[d][s], C[d][s]));
  CHECK_FALSE(same_function(P, S));  // the interior of S is not bilinearly blended
  CHECK(same_function(coons_surface(B), P));
  // A surface ruled between two curves (degree 1 in v) is its own Coons surface (linear precision),
  // and so is a bilinear patch.
  const auto ruled_uv = spline_from<R>({3, 1}, {K[0], {0, 0, 1, 1}}, 3, [&](const std::vector<std::size_t>&) {
    return std::vector<R>{r(), r(), r()};
  });
  CHECK(same_function(coons_surface(boundary_curves(ruled_uv)), ruled_uv));
  const auto bilinear = spline_from<R>({1, 1}, {{0, 0, 1, 1}, {0, 0, 1, 1}}, 4, [&](const std::vector<std::size_t>&) {
    return std::vector<R>{r(), r(), r(), r()};
  });
  CHECK(same_net(coons_surface(boundary_curves(bilinear)), bilinear));
  // Curves of different degrees and knots are made compatible; the surface still has them.
  auto G = C;
  G[0][1] = elevate_degree(G[0][1], 0, 2);
  G[1][0] = refine_knots(G[1][0], 0, {q("1/7"), q("5/7")});
  const auto PG = coons_surface(G);
  const auto BG = boundary_curves(PG);
  for (int d = 0; d < 2; ++d)
    for (int s = 0; s < 2; ++s) CHECK(same_function(BG[d][s], G[d][s]));
  CHECK(same_function(PG, P));  // the same four functions: the same surface
}

TEST_CASE("vrep coons_surface: bad curves are refused, naming them") {
  const auto S = spline_from<R>({2, 1}, {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}}, 3, [](const std::vector<std::size_t>& i) {
    return std::vector<R>{R(static_cast<long>(i[0])), R(static_cast<long>(i[1])), R(static_cast<long>(i[0] * i[1]))};
  });
  const auto C = boundary_curves(S);
  auto expect = [](const std::array<std::array<BSpline<R>, 2>, 2>& bad, const std::string& field) {
    try {
      coons_surface(bad);
      FAIL("accepted bad curves");
    } catch (const ValidationError& e) {
      CHECK(std::string(e.what()).find(field) != std::string::npos);
    }
  };
  auto gap = C;
  gap[1][1].points.back() += 1;  // the curve at v = 1 misses the corner (1, 1)
  expect(gap, "u1,v1");
  auto rational = C;
  rational[0][0].weights.assign(rational[0][0].size(), R(2));
  expect(rational, "u0.weights");
  auto surface = C;
  surface[1][0] = S;
  expect(surface, "v0.degrees");
  auto shifted = C;
  for (auto& k : shifted[0][1].knots[0]) k += 1;  // the curve at u = 1 on [1, 2]
  expect(shifted, "u1.knots");
}

TEST_CASE("vrep tube_boolean_sum: a square tube gives the box, a curved tube keeps its strips as faces") {
  // A square tube around the z axis: degree 1 around (corners at u = 0..4, closed), 1 along.
  const auto tube = spline_from<R>({1, 1}, {{0, 0, 1, 2, 3, 4, 4}, {0, 0, 1, 1}}, 3, [](const std::vector<std::size_t>& i) {
    const long x[5] = {-1, 1, 1, -1, -1}, y[5] = {-1, -1, 1, 1, -1};
    return std::vector<R>{R(x[i[0]]), R(y[i[0]]), R(2 * static_cast<long>(i[1]))};
  });
  const auto T = tube_boolean_sum(tube);
  // The box [-1, 1]^2 x [0, 2] as T(u, v, w) = (2u - 1, 2v - 1, 2w), exactly at random points.
  std::mt19937_64 rng(5021);
  for (int k = 0; k < 20; ++k) {
    const R u(static_cast<long>(rng() % 97), 96), v(static_cast<long>(rng() % 97), 96), w(static_cast<long>(rng() % 97), 96);
    CHECK(evaluate(T, {u, v, w}) == std::vector<R>{2 * u - 1, 2 * v - 1, 2 * w});
  }
  CHECK(certify_regularity(T).verdict.is_proved());
  // The teapot's handle (a closed bicubic tube): the four side faces are its quarter strips, on
  // [0, 1]^2, the caps are the Coons surfaces of their ends.
  BSpline<R> handle;
  for (const auto& t : teapot_surfaces(read_bpt(data_path("teapot.bpt"))))
    if (t.name == "handle") handle = t.surface;
  REQUIRE(handle.dim() == 2);
  const auto H = tube_boolean_sum(handle);
  const R lo = handle.domain_lo(0), hi = handle.domain_hi(0);
  auto strip = [&](int k) {
    auto P = handle;  // cut at lo + k/4 and lo + (k+1)/4 of the way around, where those are inside
    if (k > 0) P = split_at(P, 0, lo + (hi - lo) * R(k, 4)).second;
    if (k < 3) P = split_at(P, 0, lo + (hi - lo) * R(k + 1, 4)).first;
    return reparametrize(reparametrize(P, 0, R(0), R(1)), 1, R(0), R(1));
  };
  CHECK(same_function(face(H, 1, 0), strip(0)));
  CHECK(same_function(face(H, 0, 1), strip(1)));
  CHECK(same_function(face(H, 1, 1), reverse(strip(2), 0)));
  CHECK(same_function(face(H, 0, 0), reverse(strip(3), 0)));
  // Its caps are the Coons surfaces of the strips' ends (the side faces' rows at w = 0, 1).
  for (int w = 0; w < 2; ++w) {
    auto row = [&](const BSpline<R>& F) {  // the curve at w = side of a face in (x, w)
      BSpline<R> C;
      C.degrees = {F.degrees[0]};
      C.knots = {F.knots[0]};
      C.q = F.q;
      const std::size_t n0 = F.count(0), j = w == 0 ? 0 : F.count(1) - 1;
      C.points.assign(F.points.begin() + static_cast<std::ptrdiff_t>(j * n0 * 3), F.points.begin() + static_cast<std::ptrdiff_t>((j + 1) * n0 * 3));
      return C;
    };
    const auto cap = coons_surface<R>({{{row(reverse(strip(3), 0)), row(strip(1))}, {row(strip(0)), row(reverse(strip(2), 0))}}});
    CHECK(same_function(face(H, 2, w), cap));
  }
  // In double the same construction runs (the caps' edges are the curves' own values, so the Boolean
  // sum's exact edge comparison meets them) and stays within rounding of the exact volume.
  auto to_d = [](const BSpline<R>& X) { return convert<double>(X, [](const R& x) { return x.convert_to<double>(); }); };
  const auto Hd = tube_boolean_sum(to_d(handle));
  for (int k = 0; k < 10; ++k) {
    const R u(static_cast<long>(rng() % 97), 96), v(static_cast<long>(rng() % 97), 96), w(static_cast<long>(rng() % 97), 96);
    const auto e = evaluate(H, {u, v, w});
    const auto d = evaluate(Hd, {u.convert_to<double>(), v.convert_to<double>(), w.convert_to<double>()});
    for (int c = 0; c < 3; ++c) CHECK(std::abs(d[c] - e[c].convert_to<double>()) < 1e-12);
  }
  // Not closed, or rational: refused, naming the surface.
  auto open = tube;
  open.points[0] = R(-2);
  CHECK_THROWS_WITH(tube_boolean_sum(open), Catch::Contains("surface: is not closed around"));
  auto weighted = tube;
  weighted.weights.assign(weighted.size(), R(1));
  CHECK_THROWS_WITH(tube_boolean_sum(weighted), Catch::Contains("surface.weights"));
}

TEST_CASE("vrep sweep: interpolating sections of a volume reproduces it, exactly") {
  // V(u, v, w) = sum_l B_l^3(w) P_l(u, v): cubic in w, four sections at w_k determine it.
  const auto S = warped_surface();
  std::vector<BSpline<R>> layers;
  for (int l = 0; l < 4; ++l) {
    auto P = S;
    for (std::size_t i = 0; i < P.size(); ++i) P.points[i * 3 + 2] += R(l * l, 3) + R(static_cast<long>(i % 3), 5) * l;
    layers.push_back(P);
  }
  BSpline<R> V = S;
  V.degrees = {S.degrees[0], S.degrees[1], 3};
  V.knots = {S.knots[0], S.knots[1], {0, 0, 0, 0, 1, 1, 1, 1}};
  V.points.clear();
  for (const auto& P : layers) V.points.insert(V.points.end(), P.points.begin(), P.points.end());
  const std::vector<R> at{0, q("1/5"), q("2/3"), 1};
  std::vector<BSpline<R>> sections;
  for (const R& w : at) {
    auto sec = S;
    for (auto& x : sec.points) x = 0;
    const std::vector<R> b{(1 - w) * (1 - w) * (1 - w), 3 * w * (1 - w) * (1 - w), 3 * w * w * (1 - w), w * w * w};
    for (int l = 0; l < 4; ++l)
      for (std::size_t i = 0; i < sec.points.size(); ++i) sec.points[i] += b[l] * layers[l].points[i];
    sections.push_back(sec);
  }
  CHECK(same_net(sweep(sections, at, 3), V));
  // More sections than degree + 1, rational ones: T(u, v, w_k) = S_k (an identity in (u, v) of
  // bounded degree per piece, checked on a grid that bounds it).
  std::vector<BSpline<R>> rs;
  std::vector<R> ws;
  for (int k = 0; k < 6; ++k) {
    auto P = rational_profile();
    for (std::size_t i = 0; i < P.size(); ++i) {
      P.points[i * 3 + 1] = R(k * k, 4) + R(static_cast<long>(i), 7);
      P.weights[i] += R(k, 3);
    }
    rs.push_back(P);
    ws.push_back(R(k * k, 25));
  }
  const auto T = sweep(rs, ws, 3);
  CHECK(T.degrees[2] == 3);
  for (int k = 0; k < 6; ++k)
    for (int a = 0; a <= 8; ++a)
      for (int b = 0; b <= 4; ++b) {
        const std::vector<R> x{R(a, 8), R(b, 4), ws[k]};
        CHECK(evaluate(T, x) == evaluate(rs[k], {x[0], x[1]}));
      }
  CHECK_THROWS_AS(sweep(rs, std::vector<R>{0, q("1/2"), q("1/2"), q("3/4"), q("4/5"), 1}, 3), ValidationError);
  CHECK_THROWS_AS(sweep(std::vector<BSpline<R>>{rs[0]}, std::vector<R>{R(0)}, 3), ValidationError);
}

TEST_CASE("vrep regularity: the identity cube is regular, a mirrored one regular with sign -1") {
  const auto C = identity_cube(2, {0, 0, 0, q("1/2"), 1, 1, 1});
  const auto rep = certify_regularity(C);
  CHECK(rep.verdict.is_proved());
  CHECK(rep.sign == 1);
  for (const auto& x : grid(C, 3)) CHECK(det_at(C, x) == 1);
  auto M = C;
  for (std::size_t i = 0; i < M.size(); ++i) M.points[i * 3] = -M.points[i * 3];
  const auto m = certify_regularity(M);
  CHECK(m.verdict.is_proved());
  CHECK(m.sign == -1);
  // det J as a B-spline equals the independent determinant everywhere it is sampled.
  const auto J = jacobian_determinant(M);
  for (const auto& x : grid(M, 3)) CHECK(evaluate(J, x)[0] == det_at(M, x));
}

TEST_CASE("vrep regularity: Figure 1 b (three inner control points moved out) and Figure 8 are singular") {
  // Figure 1 b: a cuboid whose three inner control points are pulled up and out of it.
  auto C = identity_cube(2, {0, 0, 0, q("1/3"), q("2/3"), 1, 1, 1});
  const std::size_t n = 5;
  for (const auto& [i, j] : std::vector<std::pair<std::size_t, std::size_t>>{{1, 1}, {2, 1}, {1, 2}})
    C.points[(i + n * (j + n * 3)) * 3 + 2] = R(9, 5);  // z of inner control point (i, j, 3) -> 1.8 > 1
  const auto rep = certify_regularity(C);
  REQUIRE(rep.verdict.is_refuted());
  REQUIRE(rep.point.size() == 3);
  // The witnesses, checked by the independent route: opposite signs (or 0).
  const R a = det_at(C, rep.point);
  if (rep.other.empty()) {
    CHECK(a == 0);
  } else {
    const R b = det_at(C, rep.other);
    CHECK(((a < 0 && 0 < b) || (b < 0 && 0 < a)));
  }
  // Figure 8 a: a single-trivariate cylinder, the rectangle x in [0, 1], z in [0, 1] revolved about
  // z: det J = 0 on the axis (u = 0), found exactly.
  const auto rect = spline(R"({"type": "bspline", "degrees": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
    "points": [[0,0,0],[1,0,0],[0,0,1],[1,0,1]]})");
  const auto cyl = revolve(rect, 2, 4);
  const auto c = certify_regularity(cyl);
  REQUIRE(c.verdict.is_refuted());
  CHECK(c.other.empty());
  CHECK(c.point[0] == 0);  // on the axis
  CHECK(c.value == 0);
  // Figure 8 b: a sphere as one trivariate: a half disk (the axis segment ruled to a half circle)
  // revolved about z; singular on the axis.
  const auto arc = rational_circle<R>(2);
  BSpline<R> axis_seg = arc, half_circle = arc;
  axis_seg.q = half_circle.q = 3;
  axis_seg.points.clear();
  half_circle.points.clear();
  for (std::size_t i = 0; i < arc.size(); ++i) {
    const R x = arc.points[2 * i], y = arc.points[2 * i + 1];  // (1,0) -> (0,1) -> (-1,0): map to (y, 0, -x)
    half_circle.points.insert(half_circle.points.end(), {y, R(0), -x});
    axis_seg.points.insert(axis_seg.points.end(), {R(0), R(0), -x});
  }
  BSpline<R> disk;  // ruled surface between the two curves, as a surface (u along the arc, v across)
  disk.degrees = {2, 1};
  disk.knots = {arc.knots[0], {0, 0, 1, 1}};
  disk.q = 3;
  disk.points = axis_seg.points;
  disk.points.insert(disk.points.end(), half_circle.points.begin(), half_circle.points.end());
  disk.weights = arc.weights;
  disk.weights.insert(disk.weights.end(), arc.weights.begin(), arc.weights.end());
  const auto sphere = revolve(disk, 2, 4);
  const auto s = certify_regularity(sphere);
  CHECK(s.verdict.is_refuted());
  for (const auto& x : grid(sphere, 2)) {  // on the unit ball
    const auto p = evaluate(sphere, x);
    CHECK(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] <= 1);
  }
}

TEST_CASE("vrep regularity: rational det J numerator agrees with the independent determinant") {
  // A revolved annular profile (x in [1, 3/2]) a quarter turn: regular, rational.
  const auto T = revolve(rational_profile(), 2, 1);
  const auto rep = certify_regularity(T);
  CHECK(rep.verdict.is_proved());
  const auto J = jacobian_determinant(T);
  for (const auto& x : grid(T, 2)) {
    const R W = homogeneous_at(T, x)[3];
    CHECK(evaluate(J, x)[0] == det_at(T, x) * W * W * W * W);
    CHECK((det_at(T, x) < 0) == (rep.sign < 0));
  }
}

TEST_CASE("vrep regularity: det J's numerator on integers is the product-by-product expansion, proved coefficientwise") {
  // The fused route (product_sums: one reduction per sum) against the expansion floats use, on
  // random trivariates (polynomial and rational, degrees 1-3 mixed, interior knots, odd
  // denominators): equal Bernstein coefficients are the same polynomial on every piece.
  std::mt19937_64 rng(4917);
  auto num = [&](int bound) {
    std::uniform_int_distribution<int> n(-bound, bound), d(1, 12);
    return R(n(rng), d(rng));
  };
  int pieces = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<int> deg(3);
    std::vector<std::vector<R>> K(3);
    for (int d = 0; d < 3; ++d) {
      deg[d] = 1 + static_cast<int>(rng() % 3);
      K[d].assign(deg[d] + 1, R(0));
      if (rng() % 2) K[d].push_back(R(1 + static_cast<int>(rng() % 5), 7));
      K[d].insert(K[d].end(), deg[d] + 1, R(1));
    }
    auto V = spline_from<R>(deg, K, 3, [&](const std::vector<std::size_t>&) { return std::vector<R>{num(40), num(40), num(40)}; });
    if (trial % 2) {
      V.weights.clear();
      for (std::size_t i = 0; i < V.size(); ++i) V.weights.push_back(R(1 + static_cast<int>(rng() % 9), 1 + static_cast<int>(rng() % 4)));
    }
    const auto F = bezier_form(V);
    for (std::size_t k = 0; k < F.size(); ++k, ++pieces) {
      const auto pc = F.piece(k);
      const auto a = vrep_detail::jacobian_numerator_fused(pc.spline), b = vrep_detail::jacobian_numerator_expanded(pc.spline);
      REQUIRE(a.deg == b.deg);
      CHECK(a.c == b.c);
      // The comparison sees a change: one control point moved changes the fused numerator.
      auto moved = pc.spline;
      moved.points[moved.points.size() / 2] += R(1, 3);
      CHECK(vrep_detail::jacobian_numerator_fused(moved).c != b.c);
    }
  }
  CHECK(pieces >= 12);
}

TEST_CASE("vrep in double: the constructors and the regularity test run in floats, judged exactly") {
  const auto S = warped_surface();
  const auto Sd = convert<double>(S, [](const R& x) { return to_double(x); });
  const auto T = revolve(S, 2, 4);
  const auto Td = revolve(Sd, 2, 4);
  REQUIRE(Td.points.size() == T.points.size());
  R worst(0);
  for (std::size_t i = 0; i < T.points.size(); ++i) worst = std::max(worst, R(abs(R(exact_from_double(Td.points[i]) - T.points[i]))));
  CHECK(worst < R(1, 1 << 20));  // the rotation multiplies by 0, +-1 and +-2: rounding of the input only
  auto C = identity_cube(2, {0, 0, 0, q("1/3"), q("2/3"), 1, 1, 1});
  for (const auto& [i, j] : std::vector<std::pair<std::size_t, std::size_t>>{{1, 1}, {2, 1}, {1, 2}})
    C.points[(i + 5 * (j + 5 * 3)) * 3 + 2] = R(9, 5);
  const auto rd = certify_regularity(convert<double>(C, [](const R& x) { return to_double(x); }));
  const auto re = certify_regularity(C);
  CHECK(re.verdict.is_refuted());
  CHECK(rd.verdict.status() == re.verdict.status());  // here double agrees; where it does not is measured in the report
}

TEST_CASE("vrep regularity: sizes checked before the work, the box budget bounds memory, undecided is honest") {
  // z = (w - 1/3)^3: det J = 3 (w - 1/3)^2 vanishes on the plane w = 1/3, which no dyadic
  // subdivision hits: the honest verdict is "undecided", never "regular".
  const auto V = spline_from<R>({1, 1, 3}, {{0, 0, 1, 1}, {0, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}}, 3, [](const std::vector<std::size_t>& i) {
    // Bernstein coefficients of (w - 1/3)^3 on [0, 1]: (-1/27, 2/27, -1/27 ... ) from the blossom.
    const R a = R(-1, 3), b = R(2, 3);  // w - 1/3 at w = 0 and w = 1
    const R c[4] = {a * a * a, a * a * b, a * b * b, b * b * b};
    return std::vector<R>{R(static_cast<long>(i[0])), R(static_cast<long>(i[1])), c[i[2]]};
  });
  CHECK(evaluate(V, {R(0), R(0), R(1, 3)})[2] == 0);
  const auto rep = certify_regularity(V, 4);
  CHECK(rep.verdict.is_undecided());
  Limits small;
  small.max_control_points = 2000;
  const auto capped = certify_regularity(V, 12, small);
  CHECK(capped.verdict.is_undecided());
  CHECK(capped.verdict.reason().find("memory budget") != std::string::npos);
  CHECK(capped.boxes < 2000);
  // det J of a cube split into 3 x 3 x 3 pieces needs 27 x 6^3 coefficients: refused before the work.
  Limits tiny;
  tiny.max_control_points = 500;
  CHECK_THROWS_AS(certify_regularity(identity_cube(2, {0, 0, 0, q("1/3"), q("2/3"), 1, 1, 1}), 6, tiny), SizeLimitError);
  CHECK_THROWS_AS(jacobian_determinant(identity_cube(2, {0, 0, 0, q("1/3"), q("2/3"), 1, 1, 1}), tiny), SizeLimitError);
}
