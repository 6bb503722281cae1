// The exact pieces of a trimmed cell's part of each face of its domain (issue 18; vrep/topology/region_graph.cpp,
// reported by trimmed_topology as Surface::pieces): closed forms (slabs, holes, disks that overlap or
// not, a face cut in four) and random disk arrangements on a face against an independent count (a
// flood fill of two sampling grids, used only where the arrangement is far from tangencies).
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <functional>
#include <random>

#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_topology.hpp"

using namespace splinex;
using R = Rational;

namespace {

BSpline<R> box(std::vector<R> lo, std::vector<R> hi) { return box_cells<R>(lo, hi).front(); }

/// The face (dir, side)'s Surface entry.
const TrimmedTopology<R>::Surface& face_of(const TrimmedTopology<R>& t, int dir, int side) {
  for (const auto& s : t.surfaces)
    if (s.dir == dir && s.side == side) return s;
  FAIL("no such face");
  return t.surfaces.front();
}

std::vector<std::size_t> surface_pieces(const TrimmedTopology<R>& t);

/// lo < x_axis < hi, as a region.
Region<R> slab(int axis, R lo, R hi) { return region_and<R>({test::above(axis, lo), region_not(test::above(axis, hi))}); }

}  // namespace

TEST_CASE("vrep face pieces: slabs, holes and disks on the faces of a cube, exact") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  SECTION("a slab removed across x: the faces along x fall in two, the end faces stay whole") {
    const auto t = trimmed_topology(V, region_not(slab(0, R(3, 4), R(5, 4))), 1024);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        const auto& f = face_of(t, d, s);
        REQUIRE(f.decided);
        CHECK(f.pieces == (d == 0 ? 1u : 2u));
        CHECK(f.pieces >= f.at_least);
      }
  }
  SECTION("two slabs removed crosswise: the faces z = 0, 2 fall in four") {
    const auto t = trimmed_topology(V, region_and<R>({region_not(slab(0, R(9, 10), R(11, 10))), region_not(slab(1, R(4, 5), R(6, 5)))}), 1024);
    CHECK(face_of(t, 2, 0).pieces == 4);
    CHECK(face_of(t, 2, 1).pieces == 4);
    CHECK(face_of(t, 0, 0).pieces == 2);  // only the slab across y cuts x = 0
    CHECK(face_of(t, 1, 1).pieces == 2);
  }
  SECTION("a cylindrical hole along z: an annulus on z = 0, 2 (one piece), the side faces whole") {
    const auto t = trimmed_topology(V, region_not(test::cylinder(2, {R(1), R(1), R(0)}, R(1, 2))), 1024);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) CHECK(face_of(t, d, s).pieces == 1);
  }
  SECTION("a cylinder inside: disks on z = 0, 2, nothing on the side faces") {
    const auto t = trimmed_topology(V, test::cylinder(2, {R(1), R(1), R(0)}, R(1, 2)), 1024);
    CHECK(face_of(t, 2, 0).pieces == 1);
    CHECK(face_of(t, 2, 1).pieces == 1);
    CHECK(face_of(t, 0, 0).decided);
    CHECK(face_of(t, 0, 0).pieces == 0);
  }
  SECTION("two balls on the face z = 0: apart two pieces, overlapping one, their union's top face none") {
    const auto apart = trimmed_topology(V, region_or<R>({test::ball({R(1, 2), R(1), R(0)}, R(3, 8)), test::ball({R(3, 2), R(1), R(0)}, R(3, 8))}), 1024);
    CHECK(face_of(apart, 2, 0).pieces == 2);
    CHECK(face_of(apart, 2, 1).pieces == 0);
    const auto overlap = trimmed_topology(V, region_or<R>({test::ball({R(1, 2), R(1), R(0)}, R(5, 8)), test::ball({R(3, 2), R(1), R(0)}, R(5, 8))}), 1024);
    INFO(face_of(overlap, 2, 0).undecided_reason);
    CHECK(face_of(overlap, 2, 0).pieces == 1);
    // Their intersection: the lens's trace, one piece; the difference: a disk minus a disk, one.
    const auto lens = trimmed_topology(V, region_and<R>({test::ball({R(1, 2), R(1), R(0)}, R(5, 8)), test::ball({R(3, 2), R(1), R(0)}, R(5, 8))}), 1024);
    CHECK(face_of(lens, 2, 0).pieces == 1);
    const auto moon = trimmed_topology(V, region_and<R>({test::ball({R(1, 2), R(1), R(0)}, R(5, 8)), region_not(test::ball({R(3, 2), R(1), R(0)}, R(5, 8)))}), 1024);
    CHECK(face_of(moon, 2, 0).pieces == 1);
  }
  SECTION("a disk that cuts the face's corner off and one whose removal splits the face") {
    // The ball about the corner (0, 0, 0) of radius 1: a quarter disk on each of the three faces there.
    const auto corner = trimmed_topology(V, test::ball({R(0), R(0), R(0)}, R(1)), 1024);
    CHECK(face_of(corner, 0, 0).pieces == 1);
    CHECK(face_of(corner, 2, 0).pieces == 1);
    CHECK(face_of(corner, 2, 1).pieces == 0);
    // A cylinder along z about (1, 1) of radius 5/4 removed: on z = 0 the square minus the disk
    // is its four corners, apart.
    const auto corners = trimmed_topology(V, region_not(test::cylinder(2, {R(1), R(1), R(0)}, R(5, 4))), 1024);
    CHECK(face_of(corners, 2, 0).pieces == 4);
    CHECK(face_of(corners, 0, 0).pieces == 2);  // the disk cuts x = 0 in the middle
  }
  SECTION("two disks that touch at one point: never one piece") {
    const auto t = trimmed_topology(V, region_or<R>({test::cylinder(2, {R(1, 2), R(1), R(0)}, R(1, 2)), test::cylinder(2, {R(3, 2), R(1), R(0)}, R(1, 2))}), 1024);
    const auto& f = face_of(t, 2, 0);
    CHECK((!f.decided || f.pieces == 2));
    if (!f.decided) CHECK(!f.undecided_reason.empty());
  }
  SECTION("coplanar contact: a slab's plane on the face z = 0 is read from inside, lower bound and count agree") {
    // The cube minus the slab [-1, 3]^2 x [0, 1]: the cell is the cube above z = 1; its face z = 0
    // lies in the removed slab's bottom plane (the leaf z >= 0 vanishes there) and holds nothing.
    const auto t = trimmed_topology(V, region_not(box_region<R>({R(-1), R(-1), R(0)}, {R(3), R(3), R(1)})), 1024);
    CHECK(face_of(t, 2, 0).decided);
    CHECK(face_of(t, 2, 0).pieces == 0);
    CHECK(face_of(t, 2, 0).at_least == 0);  // was 1: the cover read the vanishing leaf as "out"
    CHECK(face_of(t, 2, 1).pieces == 1);
    CHECK(face_of(t, 0, 0).pieces == 1);
    CHECK(surface_pieces(t) == std::vector<std::size_t>{0, 0, 0, 0, 0, 1});  // only z <= 1's plane bounds
  }
  SECTION("a ball touching a face: the face's part is one point, no piece, or undecided; never a piece") {
    const auto t = trimmed_topology(V, test::ball({R(1), R(1), R(1, 2)}, R(1, 2)), 1024);
    const auto& f = face_of(t, 2, 0);
    CHECK((!f.decided || f.pieces == 0));
    if (!f.decided) CHECK(!f.undecided_reason.empty());
  }
}

namespace {

/// Pieces of {formula true} on [0, 2]^2 by 4-connected flood fill of an n x n grid of cell centres.
std::size_t flood(const std::function<bool(double, double)>& in, int n) {
  std::vector<int> mark(static_cast<std::size_t>(n * n), 0);
  std::size_t count = 0;
  std::vector<int> stack;
  for (int s = 0; s < n * n; ++s) {
    if (mark[static_cast<std::size_t>(s)] || !in(2.0 * (s % n + 0.5) / n, 2.0 * (s / n + 0.5) / n)) continue;
    ++count;
    stack = {s};
    mark[static_cast<std::size_t>(s)] = 1;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int x = c % n, y = c / n;
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= n || ny[k] >= n) continue;
        const int m = ny[k] * n + nx[k];
        if (mark[static_cast<std::size_t>(m)] || !in(2.0 * (nx[k] + 0.5) / n, 2.0 * (ny[k] + 0.5) / n)) continue;
        mark[static_cast<std::size_t>(m)] = 1;
        stack.push_back(m);
      }
    }
  }
  return count;
}

}  // namespace

TEST_CASE("vrep face pieces: random disk arrangements on a face against a flood fill away from tangencies") {
  // Three cylinders along z (disks on the face z = 0 of the cube [0, 2]^3), centres on a 1/8 grid
  // in [-1/2, 5/2]^2, radii 1/4..1 in steps of 1/16, combined by one of six formulas.
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  std::mt19937 rng(20261204);
  std::uniform_int_distribution<int> cpos(-4, 20), rad(4, 16), form(0, 5);
  int compared = 0, skipped = 0, undecided = 0;
  std::size_t pieces_seen = 0;
  for (int trial = 0; trial < 400 && compared < 30; ++trial) {
    std::array<std::array<int, 2>, 3> c{};
    std::array<int, 3> r{};
    for (int k = 0; k < 3; ++k) {
      c[k] = {cpos(rng), cpos(rng)};
      r[k] = rad(rng);
    }
    const int f = form(rng);
    // Far from tangencies (margin 1/16 in the model): circle-circle, circle-edge, circle-corner.
    bool clear = true;
    auto away = [&](double v) { clear = clear && std::abs(v) > 0.0625; };
    for (int a = 0; a < 3; ++a) {
      const double ax = c[a][0] / 8.0, ay = c[a][1] / 8.0, ar = r[a] / 16.0;
      for (double line : {0.0, 2.0}) {
        away(std::abs(ax - line) - ar);
        away(std::abs(ay - line) - ar);
        for (double other : {0.0, 2.0}) away(std::hypot(ax - line, ay - other) - ar);
      }
      for (int b = a + 1; b < 3; ++b) {
        const double d = std::hypot(ax - c[b][0] / 8.0, ay - c[b][1] / 8.0), br = r[b] / 16.0;
        away(d - ar - br);
        away(d - std::abs(ar - br));
      }
    }
    if (!clear) {
      ++skipped;
      continue;
    }
    std::array<Region<R>, 3> disk;
    for (int k = 0; k < 3; ++k) disk[k] = test::cylinder(2, {R(c[k][0], 8), R(c[k][1], 8), R(0)}, R(r[k], 16));
    const std::array<Region<R>, 6> formulas = {region_or<R>({disk[0], disk[1], disk[2]}),
                                               region_and<R>({region_or<R>({disk[0], disk[1]}), region_not(disk[2])}),
                                               region_and<R>({disk[0], disk[1]}),
                                               region_and<R>({disk[0], region_not(region_or<R>({disk[1], disk[2]}))}),
                                               region_or<R>({region_and<R>({disk[0], disk[1]}), disk[2]}),
                                               region_not(region_or<R>({disk[0], disk[1], disk[2]}))};
    auto inside = [&](int k, double x, double y) {
      const double dx = x - c[k][0] / 8.0, dy = y - c[k][1] / 8.0, rr = r[k] / 16.0;
      return dx * dx + dy * dy < rr * rr;
    };
    const std::function<bool(double, double)> truth = [&](double x, double y) {
      const bool a = inside(0, x, y), b = inside(1, x, y), d = inside(2, x, y);
      switch (f) {
        case 0: return a || b || d;
        case 1: return (a || b) && !d;
        case 2: return a && b;
        case 3: return a && !(b || d);
        case 4: return (a && b) || d;
        default: return !(a || b || d);
      }
    };
    const std::size_t coarse = flood(truth, 301), fine = flood(truth, 457);
    if (coarse != fine) {
      ++skipped;
      continue;
    }
    const auto t = trimmed_topology(V, formulas[static_cast<std::size_t>(f)], 2048);
    const auto& face = face_of(t, 2, 0);
    if (!face.decided) {
      ++undecided;
      INFO("undecided: " << face.undecided_reason);
      CHECK(undecided <= 2);
      continue;
    }
    INFO("trial " << trial << " formula " << f);
    CHECK(face.pieces == fine);
    CHECK(face.at_least <= face.pieces);
    pieces_seen += face.pieces;
    ++compared;
  }
  CHECK(compared >= 30);
  CHECK(pieces_seen >= 30);  // the sample is not all empty or single faces
  WARN("compared " << compared << ", skipped near tangencies " << skipped << ", undecided " << undecided << ", pieces " << pieces_seen);
}

namespace {

/// The pieces of every trimming surface's part, in collect order (0 where absent); REQUIREs decided.
std::vector<std::size_t> surface_pieces(const TrimmedTopology<R>& t) {
  std::vector<std::size_t> out;
  for (const auto& s : t.surfaces)
    if (s.leaf >= 0) {
      INFO(s.what << ": " << s.undecided_reason);
      REQUIRE(s.decided);
      CHECK(s.pieces >= s.at_least);
      out.push_back(s.pieces);
    }
  return out;
}

}  // namespace

TEST_CASE("vrep surface pieces: spheres, cylinders and planes in a cube, exact") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  using P = std::vector<std::size_t>;
  // A ball inside, and one through the top face: one piece of sphere each.
  CHECK(surface_pieces(trimmed_topology(V, test::ball({R(1), R(1), R(1)}, R(1, 2)), 2048)) == P{1});
  CHECK(surface_pieces(trimmed_topology(V, test::ball({R(1), R(1), R(7, 4)}, R(1, 2)), 2048)) == P{1});
  // The ball about the centre of radius 3/2 (between the edges' distance sqrt 2 and the corners'
  // sqrt 3): inside the cube its sphere is eight corner triangles.
  CHECK(surface_pieces(trimmed_topology(V, test::ball({R(1), R(1), R(1)}, R(3, 2)), 2048)) == P{8});
  // Two balls, their lens and their union: one piece of each sphere.
  const auto b1 = test::ball({R(3, 4), R(1), R(1)}, R(1, 2)), b2 = test::ball({R(5, 4), R(1), R(1)}, R(1, 2));
  CHECK(surface_pieces(trimmed_topology(V, region_and<R>({b1, b2}), 2048)) == P{1, 1});
  CHECK(surface_pieces(trimmed_topology(V, region_or<R>({b1, b2}), 2048)) == P{1, 1});
  // A ball with a cylindrical hole along z: its sphere is one band (the caps go), the hole's wall
  // one band; with a slab across its middle removed instead, two caps and two disks.
  CHECK(surface_pieces(trimmed_topology(V, region_and<R>({test::ball({R(1), R(1), R(1)}, R(3, 4)), region_not(test::cylinder(2, {R(1), R(1), R(0)}, R(1, 4)))}),
                                        2048)) == P{1, 1});
  CHECK(surface_pieces(trimmed_topology(V, region_and<R>({test::ball({R(1), R(1), R(1)}, R(3, 4)), region_not(slab(2, R(7, 8), R(9, 8)))}), 2048)) ==
        P{2, 1, 1});
  // A cylinder along z with a slab removed: two pieces of its wall, one disk on each plane.
  CHECK(surface_pieces(trimmed_topology(V, region_and<R>({test::cylinder(2, {R(1), R(1), R(0)}, R(1, 2)), region_not(slab(2, R(3, 4), R(5, 4)))}),
                                        2048)) == P{2, 1, 1});
  // A horizontal plane with two crossing slabs removed: four pieces of the plane; each slab's
  // planes are cut by the other slab into two pieces.
  CHECK(surface_pieces(trimmed_topology(V, region_and<R>({test::above(2, R(1, 3)), region_not(slab(0, R(9, 10), R(11, 10))),
                                                           region_not(slab(1, R(4, 5), R(6, 5)))}),
                                        2048)) == P{4, 2, 2, 2, 2});
}

namespace {

/// Pieces of the set `in` on a sphere (centre c, radius r) sampled on an n x 2n latitude-longitude
/// grid of cell centres, 4-connected, longitudes wrapping, the rows at each pole joined through it
/// when the pole is in the set.
std::size_t flood_sphere(const std::function<bool(double, double, double)>& in, const std::array<double, 3>& c, double r, int n) {
  const int m = 2 * n;
  auto point = [&](int i, int j, std::array<double, 3>& x) {
    const double th = M_PI * (i + 0.5) / n, ph = 2 * M_PI * (j + 0.5) / m;
    x = {c[0] + r * std::sin(th) * std::cos(ph), c[1] + r * std::sin(th) * std::sin(ph), c[2] + r * std::cos(th)};
  };
  std::vector<int> state(static_cast<std::size_t>(n * m), -1);  // -1 unknown, 0 out, 1 in, 2 visited
  auto at = [&](int i, int j) -> int& { return state[static_cast<std::size_t>(i * m + ((j % m) + m) % m)]; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      std::array<double, 3> x;
      point(i, j, x);
      at(i, j) = in(x[0], x[1], x[2]) ? 1 : 0;
    }
  const bool north = in(c[0], c[1], c[2] + r), south = in(c[0], c[1], c[2] - r);
  std::size_t count = 0;
  for (int i0 = 0; i0 < n; ++i0)
    for (int j0 = 0; j0 < m; ++j0) {
      if (at(i0, j0) != 1) continue;
      ++count;
      std::vector<std::pair<int, int>> stack{{i0, j0}};
      at(i0, j0) = 2;
      while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        std::vector<std::pair<int, int>> next{{i, j - 1}, {i, j + 1}};
        if (i > 0) next.push_back({i - 1, j});
        if (i + 1 < n) next.push_back({i + 1, j});
        if ((i == 0 && north) || (i == n - 1 && south))
          for (int k = 0; k < m; ++k) next.push_back({i, k});
        for (const auto& [a, b] : next)
          if (at(a, b) == 1) {
            at(a, b) = 2;
            stack.push_back({a, ((b % m) + m) % m});
          }
      }
    }
  return count;
}

}  // namespace

TEST_CASE("vrep surface pieces: random balls and a plane against a sampled count away from tangencies") {
  // Two balls (centres on a 1/8 grid in [0, 2]^3, radii 3/8..1) and a plane z = c in the cube
  // [0, 2]^3, combined by one of four formulas; each surface's part where the formula depends on
  // its sign, counted exactly and by flood fills of two sampling grids (on the sphere, on the
  // plane's square), compared where the two grids agree and the configuration is 1/16 away from
  // the tangencies the margins see.
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  std::mt19937 rng(4122026);
  std::uniform_int_distribution<int> cpos(2, 14), rad(3, 8), plane(3, 13), form(0, 3);
  int compared = 0, skipped = 0, undecided = 0, trials = 0;
  std::size_t pieces_seen = 0;
  for (; trials < 300 && compared < 24; ++trials) {
    std::array<std::array<int, 3>, 2> c{};
    std::array<int, 2> r{};
    for (int k = 0; k < 2; ++k) {
      for (auto& x : c[k]) x = cpos(rng);
      r[k] = rad(rng);
    }
    const int zc = plane(rng), f = form(rng);
    bool clear = true;
    auto away = [&](double v) { clear = clear && std::abs(v) > 0.0625; };
    for (int k = 0; k < 2; ++k) {
      const double rr = r[k] / 8.0;
      for (int d = 0; d < 3; ++d) {
        away(c[k][d] / 8.0 - rr);
        away(2 - c[k][d] / 8.0 - rr);
      }
      away(std::abs(c[k][2] / 8.0 - zc / 8.0) - rr);
    }
    const double d12 = std::hypot(std::hypot((c[0][0] - c[1][0]) / 8.0, (c[0][1] - c[1][1]) / 8.0), (c[0][2] - c[1][2]) / 8.0);
    away(d12 - (r[0] + r[1]) / 8.0);
    away(d12 - std::abs(r[0] - r[1]) / 8.0);
    // Circles (two spheres, a sphere and the plane, a sphere and a face) against the planes x_a =
    // 0, 2 and z = plane: their extent along a is centre_a +- rho sqrt(1 - n_a^2).
    auto circle = [&](std::array<double, 3> m, std::array<double, 3> n, double rho) {
      for (int a = 0; a < 3; ++a) {
        if (std::abs(std::abs(n[a]) - 1) < 1e-12) continue;  // the circle's own plane
        const double e = rho * std::sqrt(1 - n[a] * n[a]);
        for (double at : {0.0, 2.0}) {
          away(m[a] + e - at);
          away(m[a] - e - at);
        }
        if (a == 2) {
          away(m[a] + e - zc / 8.0);
          away(m[a] - e - zc / 8.0);
        }
      }
    };
    for (int k = 0; k < 2; ++k) {
      const std::array<double, 3> ck{c[k][0] / 8.0, c[k][1] / 8.0, c[k][2] / 8.0};
      const double rr = r[k] / 8.0;
      for (int a = 0; a < 3; ++a)
        for (double at : {0.0, 2.0, a == 2 ? zc / 8.0 : -1.0}) {
          const double h = ck[a] - at;
          if (at < 0 || std::abs(h) >= rr) continue;
          std::array<double, 3> m = ck, n{0, 0, 0};
          m[a] = at;
          n[a] = 1;
          circle(m, n, std::sqrt(rr * rr - h * h));
        }
    }
    if (d12 < (r[0] + r[1]) / 8.0 && d12 > std::abs(r[0] - r[1]) / 8.0) {
      const double r0 = r[0] / 8.0, r1 = r[1] / 8.0, t = (d12 * d12 + r0 * r0 - r1 * r1) / (2 * d12);
      std::array<double, 3> n, m;
      for (int a = 0; a < 3; ++a) {
        n[a] = (c[1][a] - c[0][a]) / 8.0 / d12;
        m[a] = c[0][a] / 8.0 + t * n[a];
      }
      circle(m, n, std::sqrt(r0 * r0 - t * t));
    }
    if (!clear) {
      ++skipped;
      continue;
    }
    auto inside_ball = [&](int k, double x, double y, double z) {
      const double dx = x - c[k][0] / 8.0, dy = y - c[k][1] / 8.0, dz = z - c[k][2] / 8.0, rr = r[k] / 8.0;
      return dx * dx + dy * dy + dz * dz < rr * rr;
    };
    // The formula over (ball 1, ball 2, plane) truths; the leaves in collect order per formula.
    auto F = [&](bool a, bool b, bool h) {
      switch (f) {
        case 0: return a && b && h;
        case 1: return (a || b) && h;
        case 2: return a && !b;
        default: return (a && !h) || b;
      }
    };
    const Region<R> B1 = test::ball({R(c[0][0], 8), R(c[0][1], 8), R(c[0][2], 8)}, R(r[0], 8));
    const Region<R> B2 = test::ball({R(c[1][0], 8), R(c[1][1], 8), R(c[1][2], 8)}, R(r[1], 8));
    const Region<R> H = test::above(2, R(zc, 8));
    const std::array<Region<R>, 4> formulas = {region_and<R>({B1, B2, H}), region_and<R>({region_or<R>({B1, B2}), H}), region_and<R>({B1, region_not(B2)}),
                                               region_or<R>({region_and<R>({B1, region_not(H)}), B2})};
    // Collect order: which surface (0, 1 balls, 2 plane) each leaf is.
    const std::vector<int> order = f == 0 ? std::vector<int>{0, 1, 2} : f == 1 ? std::vector<int>{0, 1, 2} : f == 2 ? std::vector<int>{0, 1} : std::vector<int>{0, 2, 1};
    auto active = [&](int which, double x, double y, double z) {
      if (x <= 0 || y <= 0 || z <= 0 || x >= 2 || y >= 2 || z >= 2) return false;
      bool v[3] = {inside_ball(0, x, y, z), inside_ball(1, x, y, z), z > zc / 8.0};
      v[which] = true;
      const bool t1 = F(v[0], v[1], v[2]);
      v[which] = false;
      return t1 != F(v[0], v[1], v[2]);
    };
    std::vector<std::size_t> expect;
    bool consistent = true;
    for (int which : order) {
      std::size_t a, b;
      if (which < 2) {
        const std::array<double, 3> cc{c[which][0] / 8.0, c[which][1] / 8.0, c[which][2] / 8.0};
        auto in = [&](double x, double y, double z) { return active(which, x, y, z); };
        a = flood_sphere(in, cc, r[which] / 8.0, 90);
        b = flood_sphere(in, cc, r[which] / 8.0, 151);
      } else {
        auto in = [&](double x, double y) { return active(2, x, y, zc / 8.0); };
        a = flood(in, 301);
        b = flood(in, 457);
      }
      consistent = consistent && a == b;
      expect.push_back(b);
    }
    if (!consistent) {
      ++skipped;
      continue;
    }
    const auto t = trimmed_topology(V, formulas[static_cast<std::size_t>(f)], 2048);
    std::vector<std::size_t> got;
    bool decided = true;
    for (const auto& s : t.surfaces)
      if (s.leaf >= 0) {
        decided = decided && s.decided;
        got.push_back(s.pieces);
        if (!s.decided) WARN("undecided: " << s.undecided_reason);
      }
    if (!decided) {
      ++undecided;
      continue;
    }
    INFO("trial " << trials << " formula " << f << " balls " << c[0][0] << "," << c[0][1] << "," << c[0][2] << " r " << r[0] << " / " << c[1][0] << ","
                  << c[1][1] << "," << c[1][2] << " r " << r[1] << " plane " << zc << " (eighths)");
    CHECK(got == expect);
    for (std::size_t p : got) pieces_seen += p;
    ++compared;
  }
  CHECK(compared >= 24);
  CHECK(undecided <= 3);
  WARN("surfaces: compared " << compared << " cells in " << trials << " trials, skipped " << skipped << ", undecided " << undecided << ", pieces "
                             << pieces_seen);
}

TEST_CASE("vrep face and surface pieces: inputs at the edges") {
  // Scales no double holds: a cube of side 2^-1100 (and 2^1100) with a ball inside, exactly: the
  // sphere one piece, no face touched; a ball through the top face: one cap on it.
  for (int e : {-1100, 1100}) {
    R s(1);
    for (int i = 0; i < 1100; ++i) s = e < 0 ? R(s / 2) : R(s * 2);
    const auto V = box({R(0), R(0), R(0)}, {R(2 * s), R(2 * s), R(2 * s)});
    const auto inside = trimmed_topology(V, test::ball({s, s, s}, R(s / 2)), 1024);
    CHECK(surface_pieces(inside) == std::vector<std::size_t>{1});
    for (int d = 0; d < 3; ++d) CHECK(face_of(inside, d, 0).pieces == 0);
    const auto cap = trimmed_topology(V, test::ball({s, s, R(7 * s / 4)}, R(s / 2)), 1024);
    CHECK(face_of(cap, 2, 1).pieces == 1);
    CHECK(surface_pieces(cap) == std::vector<std::size_t>{1});
  }
  // Refused before the work, as for the curves: unclamped knots, an inner knot of multiplicity
  // p + 1 (C^-1), degree 0 in a direction.
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto b = test::ball({R(1), R(1), R(1)}, R(1, 2));
  auto open = V;
  open.knots[0] = {R(-1), R(0), R(1), R(2)};
  CHECK_THROWS_AS(trimmed_topology(open, b, 64), ValidationError);
  auto flat = V;
  flat.degrees[2] = 0;
  flat.knots[2] = {R(0), R(2)};
  CHECK_THROWS_AS(trimmed_topology(flat, b, 64), Error);
}
