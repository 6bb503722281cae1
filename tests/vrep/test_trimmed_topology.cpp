// The boundary structure of trimmed cells (issue 18, the topology of trimmed cells in part): exact
// V-points and V-curves on the trivariate's edges, certified lower bounds on the half-V-surfaces (their exact counts: test_region_pieces.cpp),
// on cells whose true boundary is known (a box cut by a plane, a quarter cylinder slice, a bar with a
// slab removed).
#include <catch2/catch.hpp>
#include <array>
#include <cmath>

#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_topology.hpp"

using namespace splinex;
using R = Rational;

namespace {

BSpline<R> box(std::vector<R> lo, std::vector<R> hi) { return box_cells<R>(lo, hi).front(); }

struct Counts {
  std::size_t edge_pieces = 0, edge_points = 0, surfaces = 0, absent = 0, collapsed = 0, face_curves = 0, face_curves_cover = 0;
};
template <class T>
Counts counts(const TrimmedTopology<T>& t) {
  Counts c;
  for (const auto& e : t.edges) {
    c.edge_pieces += e.pieces;
    c.edge_points += e.points;
  }
  for (const auto& s : t.surfaces) {
    c.surfaces += s.at_least;
    c.absent += s.absent;
    c.collapsed += s.collapsed;
  }
  for (const auto& f : t.face_curves) {
    c.face_curves += f.at_least;
    c.face_curves_cover += f.cover;
  }
  return c;
}

}  // namespace

TEST_CASE("vrep trimmed topology: a box cut by a plane has the boundary of the box [1/3, 2] x [0, 2]^2") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto trim = box_region<R>({R(1, 3), R(-1), R(-1)}, {R(3), R(3), R(3)});
  const auto t = trimmed_topology(V, trim, 512);
  CHECK(t.corners == 4);  // the corners at x = 2
  const auto c = counts(t);
  CHECK(c.edge_pieces == 8);  // four edges along x cut at x = 1/3, four whole at x = 2
  CHECK(c.edge_points == 4);
  // Each cut along x is exactly at u = 1/6 (x = 2u = 1/3).
  for (const auto& e : t.edges)
    if (e.along == 0) {
      REQUIRE(e.cuts.size() == 1);
      CHECK(e.cuts[0].first == R(1, 6));
      CHECK(e.cuts[0].second == R(1, 6));
    }
  CHECK(c.surfaces == 6);  // five faces of V and the plane x = 1/3
  CHECK(c.absent == 1 + 5);  // the face x = 0, and the five planes of the region that do not bound it
  CHECK(c.collapsed == 0);
  for (const auto& s : t.surfaces) CHECK(s.at_least == s.cover);
  CHECK(c.face_curves == 4);  // the plane's boundary: a segment on each of the faces y = 0, 2 and z = 0, 2
  CHECK(c.face_curves_cover == 4);
}

TEST_CASE("vrep trimmed topology: a box slice cut by a cylinder is a quarter cylinder slice (5 surfaces, 4 edge V-points)") {
  const auto V = box({R(0), R(0), R(1, 3)}, {R(2), R(2), R(2, 3)});
  const auto t = trimmed_topology(V, cylinder_region<R>(R(1), R(1)), 2048);
  CHECK(t.corners == 2);  // (0, 0, 1/3) and (0, 0, 2/3)
  const auto c = counts(t);
  CHECK(c.edge_points == 4);   // x = 1 on the two edges along x at y = 0, y = 1 on the two along y at x = 0
  CHECK(c.edge_pieces == 5);   // those four and the edge along z at x = y = 0
  CHECK(c.surfaces == 5);      // faces x = 0, y = 0, z = 1/3, z = 2/3 and the cylinder's side
  std::size_t side = 0;
  for (const auto& s : t.surfaces)
    if (s.leaf >= 0 && s.at_least > 0) ++side;
  CHECK(side == 1);
  CHECK(c.face_curves == 4);  // lines on x = 0 and y = 0, quarter circles on z = 1/3 and z = 2/3
  for (const auto& e : t.edges)
    for (const auto& cut : e.cuts) {
      CHECK(cut.first == R(1, 2));  // x = 2u = 1 (exact rational root)
      CHECK(cut.second == R(1, 2));
    }
}

TEST_CASE("vrep trimmed topology: a bar with a slab removed: two pieces per face and per edge, certified") {
  const auto V = box({R(0), R(0), R(0)}, {R(4), R(1), R(1)});
  const auto trim = region_not(box_region<R>({R(4, 3), R(-1), R(-1)}, {R(7, 3), R(2), R(2)}));
  const auto t = trimmed_topology(V, trim, 2048);
  CHECK(t.corners == 8);
  std::size_t split_faces = 0, planes = 0;
  for (const auto& s : t.surfaces) {
    if (s.dir >= 0 && s.dir != 0) {
      CHECK(s.at_least == 2);
      ++split_faces;
    }
    if (s.leaf >= 0 && s.at_least == 1) ++planes;
  }
  CHECK(split_faces == 4);
  CHECK(planes == 2);  // x = 4/3 and x = 7/3
  CHECK(counts(t).face_curves == 8);  // each plane meets the four long faces
  for (const auto& e : t.edges)
    if (e.along == 0) {
      CHECK(e.pieces == 2);
      CHECK(e.points == 2);
    } else {
      CHECK(e.pieces == 1);
      CHECK(e.points == 0);
    }
}

TEST_CASE("vrep trimmed topology: edges on a trimming surface, collapsed edges and faces are said so, bad input refused") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto t = trimmed_topology(V, box_region<R>({R(0), R(-1), R(-1)}, {R(3), R(3), R(3)}), 256);
  std::size_t on = 0;
  for (const auto& e : t.edges) on += e.status == TrimmedTopology<R>::Edge::on_trimming_surface;
  CHECK(on == 4);  // the four edges of the face x = 0 lie on the plane x = 0
  // A singular cylinder (one trivariate, an axis collapsed): its collapsed face carries no surface.
  const auto S = singular_cylinder<R>(R(1), R(1));
  const auto ts = trimmed_topology(S, box_region<R>({R(-2), R(-2), R(-1)}, {R(2), R(2), R(1, 2)}), 512);
  std::size_t collapsed = 0;
  for (const auto& s : ts.surfaces) collapsed += s.collapsed;
  CHECK(collapsed >= 1);
  CHECK_THROWS_AS(trimmed_topology(V, box_region<R>({R(0), R(0), R(0)}, {R(1), R(1), R(1)}), 4), ValidationError);
  auto open = V;
  open.knots[0] = {R(-1), R(0), R(1), R(2)};
  CHECK_THROWS_AS(trimmed_topology(open, box_region<R>({R(0), R(0), R(0)}, {R(1), R(1), R(1)}), 64), ValidationError);
}

TEST_CASE("vrep trimmed topology: V-points off the edges, on faces and inside, exact") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  const auto plane = test::above;
  // Two planes: their line crosses the faces z = 0 and z = 2 at corners of the cell.
  const auto two = trimmed_topology(V, region_and<R>({plane(0, R(1, 3)), plane(1, R(1, 4))}), 512);
  CHECK(two.face_points == 2);
  CHECK(two.interior_points == 0);
  CHECK(two.points_undecided == 0);
  // Three planes: the cell is the box [1/3, 2] x [1/4, 2] x [1/5, 2], whose 8 vertices are one
  // corner of V's domain, three V-points on its edges, three on its faces and one inside.
  const auto three = trimmed_topology(V, region_and<R>({plane(0, R(1, 3)), plane(1, R(1, 4)), plane(2, R(1, 5))}), 512);
  CHECK(three.corners == 1);
  std::size_t edge_points = 0;
  for (const auto& e : three.edges) edge_points += e.points;
  CHECK(edge_points == 3);
  CHECK(three.face_points == 3);
  CHECK(three.interior_points == 1);
  CHECK(three.points_undecided == 0);
  REQUIRE(three.inner_points.size() == 4);
  for (const auto& p : three.inner_points)
    if (p.dir < 0) {  // the inside corner (1/3, 1/4, 1/5) / 2 in V's parameters
      const R want[3] = {R(1, 6), R(1, 8), R(1, 10)};
      for (int d = 0; d < 3; ++d) CHECK((p.lo[d] <= want[d] && want[d] <= p.hi[d]));
    }
  // The lens of two balls cut by a plane: its circular edge crosses the plane at two irrational
  // points, y = 1 +- sqrt(1/5).
  using test::ball;
  const auto lens = trimmed_topology(V, region_and<R>({ball({R(4, 5), R(1), R(1)}, R(1, 2)), ball({R(6, 5), R(1), R(1)}, R(1, 2)), plane(2, R(11, 10))}), 512);
  CHECK(lens.interior_points == 2);
  CHECK(lens.face_points == 0);
  CHECK(lens.points_undecided == 0);
  for (const auto& p : lens.inner_points) {
    const double y = (to_double(p.lo[1]) + to_double(p.hi[1])) / 2 * 2;  // v = y / 2
    CHECK(std::abs(std::abs(y - 1) - std::sqrt(0.2)) < 1e-9);
  }
  // The same balls without the plane: the lens's edge is a circle, no V-point anywhere.
  const auto lens_only = trimmed_topology(V, region_and<R>({ball({R(4, 5), R(1), R(1)}, R(1, 2)), ball({R(6, 5), R(1), R(1)}, R(1, 2))}), 512);
  CHECK(lens_only.interior_points == 0);
  CHECK(lens_only.face_points == 0);
}

TEST_CASE("vrep trimmed topology: the trimming surfaces' curves on the faces, exact arcs and loops") {
  const auto V = box({R(0), R(0), R(0)}, {R(2), R(2), R(2)});
  auto exact = [](const TrimmedTopology<R>& t) {
    std::array<std::size_t, 4> c{};  // arcs, loops, ends on edges, ends at face V-points
    for (const auto& f : t.face_curves) {
      CHECK(f.decided);
      c[0] += f.arcs;
      c[1] += f.loops;
      c[2] += f.ends_on_edges;
      c[3] += f.ends_at_points;
    }
    return c;
  };
  // A plane: four lines across the faces it cuts, edge to edge.
  const auto plane = exact(trimmed_topology(V, test::above(0, R(1, 3)), 512));
  CHECK(plane == std::array<std::size_t, 4>{4, 0, 8, 0});
  // Three planes: on each of the faces x, y, z = 2 two lines from an edge to the face's V-point.
  const auto three = exact(trimmed_topology(V, region_and<R>({test::above(0, R(1, 3)), test::above(1, R(1, 4)), test::above(2, R(1, 5))}), 512));
  CHECK(three == std::array<std::size_t, 4>{6, 0, 6, 6});
  // A cylinder along z inside the cube: its circles on the faces z = 0 and z = 2 are loops.
  const auto cyl = exact(trimmed_topology(V, test::cylinder(2, {R(1), R(1), R(0)}, R(1, 2)), 512));
  CHECK(cyl == std::array<std::size_t, 4>{0, 2, 0, 0});
  // A ball inside: nothing on the faces.
  const auto ball = exact(trimmed_topology(V, test::ball({R(1), R(1), R(1)}, R(1, 2)), 512));
  CHECK(ball == std::array<std::size_t, 4>{0, 0, 0, 0});
  // The ball through the face z = 2 (centre at height 7/4, radius 1/2): one circle there.
  const auto cap = exact(trimmed_topology(V, test::ball({R(1), R(1), R(7, 4)}, R(1, 2)), 512));
  CHECK(cap == std::array<std::size_t, 4>{0, 1, 0, 0});
  // A cylinder along x through the cube's corner edge region: on the faces x = 0 and x = 2 its
  // circle about (y, z) = (0, 0) radius 1 is cut by the edges: a quarter circle from edge to edge
  // on each; on the faces y = 0 and z = 0 it runs as two lines.
  const auto corner = exact(trimmed_topology(V, test::cylinder(0, {R(0), R(0), R(0)}, R(1)), 512));
  CHECK(corner == std::array<std::size_t, 4>{4, 0, 8, 0});
}
