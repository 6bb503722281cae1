// The cutting surface's certificates (papers/004 Section 2's conditions, decided exactly): the
// vertices, the boundary deviation, the tangents, regularity and injectivity (a monotone
// projection, else the grid of monotone windows of surface_injectivity.cpp), collision with exact
// ray parity, the verdict; and the split as facet lists (cut/surface_facet.hpp).
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "bernstein/subdivide.hpp"
#include "bernstein/tensor.hpp"
#include "compose/compose.hpp"
#include "cut/membership.hpp"
#include "cut/surface_facet.hpp"
#include "cut/surface_facet_impl.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/hodograph.hpp"

namespace splinex {

using namespace surface_detail;

namespace {

Rational max_abs3(const P3& a) { return std::max(rabs(a[0]), std::max(rabs(a[1]), rabs(a[2]))); }

// The 2 x 2 matrix M of the regularity certificate: P = M (x_a0, x_a1). Any invertible M keeps the
// argument (M P p injective implies p injective; D(M P p) non-singular implies Dp of rank 2), and the
// monotone criterion needs M P p to look like the identity of Omega: M is the least-squares linear
// fit of Omega's vertices to the loop's projected vertices (both centred), scaled to max entry 1 and
// rounded to multiples of 2^-16. The identity when the fit is not invertible, or when Omega is the
// projection itself (the fit is then a multiple of the identity).
std::array<Rational, 4> projection_alignment(const std::vector<LoopSide3>& loop, const DomainPolygon& D) {
  const std::array<Rational, 4> id{Rational(1), Rational(0), Rational(0), Rational(1)};
  const std::size_t n = loop.size();
  if (D.vertices.size() != n || n == 0) return id;
  std::vector<P2> q(n);
  P2 qc{Rational(0), Rational(0)}, wc{Rational(0), Rational(0)};
  for (std::size_t j = 0; j < n; ++j) {
    q[j] = {loop[j].start[D.axes[0]], loop[j].start[D.axes[1]]};
    for (int k = 0; k < 2; ++k) qc[k] += q[j][k] / n, wc[k] += D.vertices[j][k] / n;
  }
  Rational sqq[2][2] = {{Rational(0), Rational(0)}, {Rational(0), Rational(0)}}, swq[2][2] = {{Rational(0), Rational(0)}, {Rational(0), Rational(0)}};
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        sqq[a][b] += (q[j][a] - qc[a]) * (q[j][b] - qc[b]);
        swq[a][b] += (D.vertices[j][a] - wc[a]) * (q[j][b] - qc[b]);
      }
  const Rational det = sqq[0][0] * sqq[1][1] - sqq[0][1] * sqq[1][0];
  if (det == 0) return id;
  // M = swq sqq^-1
  const Rational i00 = sqq[1][1] / det, i01 = -sqq[0][1] / det, i10 = -sqq[1][0] / det, i11 = sqq[0][0] / det;
  std::array<Rational, 4> M{swq[0][0] * i00 + swq[0][1] * i10, swq[0][0] * i01 + swq[0][1] * i11, swq[1][0] * i00 + swq[1][1] * i10,
                            swq[1][0] * i01 + swq[1][1] * i11};
  if (M[1] == 0 && M[2] == 0 && M[0] == M[3] && M[0] > 0) return id;
  Rational mx(0);
  for (const auto& m : M) mx = std::max(mx, rabs(m));
  if (mx == 0) return id;
  for (auto& m : M) m = round_to_grid(Rational(m / mx), 16);
  if (!(M[0] * M[3] - M[1] * M[2] != 0)) return id;
  return M;
}

P3 eval3(const BSpline<Rational>& S, const P2& w) {
  const auto v = evaluate(S, std::vector<Rational>{w[0], w[1]});
  return {v[0], v[1], v[2]};
}

// The piece of the patch (extract_bezier) whose box holds w.
const BezierPiece<Rational>& piece_at(const std::vector<BezierPiece<Rational>>& pieces, const P2& w) {
  for (const auto& p : pieces)
    if (p.box[0].first <= w[0] && w[0] <= p.box[0].second && p.box[1].first <= w[1] && w[1] <= p.box[1].second) return p;
  throw std::logic_error("piece_at: outside the patch");
}

// The edge W0 -> W1 cut at the patch's knot lines: the parameters s in [0, 1] of the crossings.
std::vector<Rational> edge_breaks(const P2& W0, const P2& W1, const std::vector<Rational>& knots) {
  std::vector<Rational> s{Rational(0), Rational(1)};
  for (int d = 0; d < 2; ++d) {
    const Rational e = W1[d] - W0[d];
    if (e == 0) continue;
    for (const auto& k : knots) {
      const Rational t = (k - W0[d]) / e;
      if (t > 0 && t < 1) s.push_back(t);
    }
  }
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

// A parameter interval [lo, hi] of a loop side with a polynomial on it in Bernstein form, and its
// halving (the tangent check of certify_cutting_surface).
struct SideArc {
  Bernstein<Rational> h;
  Rational lo, hi;
};
struct HalveArc {
  template <class Emit>
  void operator()(SideArc&& a, int, Emit&& emit) const {
    auto [h1, h2] = bern_split(a.h, 0, Rational(1, 2));
    const Rational m = (a.lo + a.hi) / 2;
    emit(SideArc{std::move(h1), a.lo, m});
    emit(SideArc{std::move(h2), m, a.hi});
  }
};

// A phase line on stderr when o.progress is set, with the seconds since t0.
void phase(const SurfaceFacetOptions& o, std::chrono::steady_clock::time_point t0, const std::string& what) {
  if (o.progress)
    std::cerr << "[cut facet] " << what << " (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s)\n";
}

// The certificate's inputs checked (typed errors): one vertex of Omega per loop side, a polynomial
// surface in R^3, Omega inside the patch's parameter domain, simple and counter-clockwise. Returns
// Omega as CGAL's polygon.
std::vector<K::Point_2> checked_omega(const std::vector<LoopSide3>& loop, const DomainPolygon& domain, const BSpline<Rational>& patch) {
  const auto& W = domain.vertices;
  const std::size_t ns = loop.size();
  if (W.size() != ns) throw UsageError("domain", "has " + std::to_string(W.size()) + " vertices for " + std::to_string(ns) + " loop sides", "give one vertex per loop side");
  if (patch.dim() != 2 || patch.q != 3 || patch.is_rational())
    throw UsageError("patch", "must be a polynomial surface in R^3", "give a tensor-product B-spline surface with 3 coordinates");
  for (const auto& w : W)
    if (!(w[0] >= patch.domain_lo(0) && w[0] <= patch.domain_hi(0) && w[1] >= patch.domain_lo(1) && w[1] <= patch.domain_hi(1)))
      throw DomainError("domain", "a vertex of Omega lies outside the patch's parameter domain", "give Omega inside the patch's domain");
  const auto poly = cg_polygon(W);
  if (!CGAL::is_simple_2(poly.begin(), poly.end(), K()) || CGAL::orientation_2(poly.begin(), poly.end(), K()) != CGAL::COUNTERCLOCKWISE)
    throw DomainError("domain", "Omega is not a simple counter-clockwise polygon", "give its vertices counter-clockwise without self-intersection");
  return poly;
}

// The vertices: p(W_j) = L_j exactly, else the largest error.
void certify_vertices(SurfaceValidity& V, const std::vector<LoopSide3>& loop, const std::vector<P2>& W, const BSpline<Rational>& patch) {
  const std::size_t ns = loop.size();
  V.vertices_exact = true;
  for (std::size_t j = 0; j < ns; ++j) {
    const Rational e = max_abs3(sub(eval3(patch, W[j]), loop[j].start));
    if (e > 0) V.vertices_exact = false;
    V.vertex_error = std::max(V.vertex_error, e);
  }
}

// Loop side j (L, the edge W0 -> W1 of Omega), piece by piece: the boundary deviation from the
// Bernstein coefficients of p o e_j minus the side, and t . (dp/dm) > 0 by halving its Bernstein
// form (an exact point with <= 0 is the witness).
void certify_side(SurfaceValidity& V, std::size_t j, const P2& W0, const P2& W1, const LoopSide3& L, const BSpline<Rational>& patch,
                  const std::vector<BezierPiece<Rational>>& pieces, const std::vector<Rational>& knots_all, const SurfaceFacetOptions& o) {
  const P2 e{W1[0] - W0[0], W1[1] - W0[1]};
  const Rational em = std::max(rabs(e[0]), rabs(e[1]));
  const P2 inward{-e[1] / em, e[0] / em};
  const auto br = edge_breaks(W0, W1, knots_all);
  for (std::size_t b = 0; b + 1 < br.size() && !V.witness; ++b) {
    const Rational s0 = br[b], s1 = br[b + 1];
    const P2 a{W0[0] + s0 * e[0], W0[1] + s0 * e[1]}, c{W0[0] + s1 * e[0], W0[1] + s1 * e[1]};
    const auto& cell = piece_at(pieces, {(a[0] + c[0]) / 2, (a[1] + c[1]) / 2});
    const auto seg = bezier<Rational>({1}, 2, {a[0], a[1], c[0], c[1]});
    const auto pc = compose_bezier(cell.spline, seg);
    const int p = pc.degrees[0];
    for (int k = 0; k <= p; ++k) {
      const Rational s = s0 + (s1 - s0) * Rational(k, p);
      for (int cc = 0; cc < 3; ++cc)
        V.boundary_deviation = std::max(V.boundary_deviation, rabs(pc.points[3 * k + cc] - (L.start[cc] + s * (L.end[cc] - L.start[cc]))));
    }
    // g(s) = t . (p_u m_u + p_v m_v) along the piece
    const auto du = compose_bezier(hodograph(cell.spline, 0), seg), dv = compose_bezier(hodograph(cell.spline, 1), seg);
    if (du.degrees != dv.degrees) throw std::logic_error("certify_cutting_surface: derivative degrees differ");
    Bernstein<Rational> g;
    g.deg = du.degrees;
    g.c.assign(du.count(0), Rational(0));
    for (std::size_t k = 0; k < g.c.size(); ++k)
      for (int cc = 0; cc < 3; ++cc) g.c[k] += L.tangent[cc] * (du.points[3 * k + cc] * inward[0] + dv.points[3 * k + cc] * inward[1]);
    // halving on [lo, hi] of the local parameter (no box budget: the depth bounds it)
    using Arc = SideArc;
    auto positive = [&](const Arc& a, int) {
      if (bern_sign(a.h) > 0) return Examined::settled;
      const Rational mid = bern_value(a.h, std::vector<Rational>{Rational(1, 2)});
      if (mid > 0) return Examined::split;
      const Rational tau = (a.lo + a.hi) / 2, s = s0 + (s1 - s0) * tau;
      const P2 w{W0[0] + s * e[0], W0[1] + s * e[1]};
      V.witness = SurfaceValidity::Witness{"tangent", w, eval3(patch, w), mid,
                                           "t . (dp/dm) <= 0 on loop side " + std::to_string(j) + ": the prescribed tangent does not point into the patch"};
      V.tangents = Verdict::refuted(V.witness->detail);
      return Examined::refuted;
    };
    Budget depth_only;
    depth_only.max_depth = o.max_depth;
    const Subdivision run = subdivide(std::vector<Arc>{Arc{g, Rational(0), Rational(1)}}, Walk{}, depth_only, positive, HalveArc{}, [](Arc&&, Left) {});
    if (run.stop != Subdivision::Stop::refuted && run.left > 0)
      V.tangents = Verdict::undecided("t . (dp/dm) > 0 not decided on loop side " + std::to_string(j) + " within --max-depth halvings");
  }
}

// Boundary deviation and tangents, edge by edge (certify_side), until a witness is found.
void certify_boundary_and_tangents(SurfaceValidity& V, const std::vector<LoopSide3>& loop, const std::vector<P2>& W, const BSpline<Rational>& patch,
                                   const std::vector<BezierPiece<Rational>>& pieces, const std::vector<Rational>& knots_all, const SurfaceFacetOptions& o) {
  const std::size_t ns = loop.size();
  V.tangents = Verdict::proved("t . (dp/dm) > 0 along every loop side (Bernstein signs)");
  for (std::size_t j = 0; j < ns && !V.witness; ++j) certify_side(V, j, W[j], W[(j + 1) % ns], loop[j], patch, pieces, knots_all, o);
}

// A cell of the regularity certificate: on the parameter box [lo, hi], the Bernstein forms of dP1/du
// (A), of 4 dP1/du dP2/dv - (dP1/dv + dP2/du)^2 (Q) and of det DP (det).
struct JacobianCell {
  Bernstein<Rational> A, Q, det;
  P2 lo, hi;
};

// The cells of the regularity certificate: every patch piece that meets the bounding box [blo, bhi]
// of Omega, with the Jacobian of P = M (x_a0, x_a1) composed with p, restricted to that box.
std::vector<JacobianCell> jacobian_cells(const std::vector<BezierPiece<Rational>>& pieces, const P2& blo, const P2& bhi, int a0, int a1,
                                         const std::array<Rational, 4>& M) {
  std::vector<JacobianCell> cells;
  for (const auto& pc : pieces) {
    const P2 lo{pc.box[0].first, pc.box[1].first}, hi{pc.box[0].second, pc.box[1].second};
    if (!(lo[0] < bhi[0] && blo[0] < hi[0] && lo[1] < bhi[1] && blo[1] < hi[1])) continue;
    const Rational hu = hi[0] - lo[0], hv = hi[1] - lo[1];
    const auto X0 = bern_coordinate(pc.spline, a0), Y0 = bern_coordinate(pc.spline, a1);
    const auto X = bern_combine(scaled(X0, M[0]), scaled(Y0, M[1]), false), Y = bern_combine(scaled(X0, M[2]), scaled(Y0, M[3]), false);
    const auto A = scaled(bern_derivative(X, 0), 1 / hu), B1 = scaled(bern_derivative(X, 1), 1 / hv);
    const auto B2 = scaled(bern_derivative(Y, 0), 1 / hu), C = scaled(bern_derivative(Y, 1), 1 / hv);
    const auto AC = bern_product(A, C);
    const auto S = bern_combine(B1, B2, false);
    JacobianCell cl;
    cl.A = A;
    cl.Q = bern_combine(scaled(AC, Rational(4)), bern_product(S, S), true);
    cl.det = bern_combine(AC, bern_product(B1, B2), true);
    // restricted to the bounding box of Omega
    const P2 rlo{std::max(lo[0], blo[0]), std::max(lo[1], blo[1])}, rhi{std::min(hi[0], bhi[0]), std::min(hi[1], bhi[1])};
    for (int d = 0; d < 2; ++d) {
      const Rational h = hi[d] - lo[d], fa = (rlo[d] - lo[d]) / h, fc = (rhi[d] - lo[d]) / h;
      if (fa > 0 || fc < 1) {
        cl.A = bern_restrict(cl.A, d, fa, fc);
        cl.Q = bern_restrict(cl.Q, d, fa, fc);
        cl.det = bern_restrict(cl.det, d, fa, fc);
      }
    }
    cl.lo = rlo, cl.hi = rhi;
    cells.push_back(cl);
  }
  return cells;
}

// Whether the cells are certified by halving them (Bernstein signs; u and v in turn): monotone,
// dP1/du > 0 and Q > 0 on every cell; else det DP > 0 on every cell that meets Omega.
bool jacobian_certified(const std::vector<JacobianCell>& cells, const std::vector<K::Point_2>& poly, bool monotone, const SurfaceFacetOptions& o) {
  using Cell = JacobianCell;
  auto positive = [&](const Cell& c, int) {
    if (!monotone && !box_meets_polygon(c.lo, c.hi, poly)) return Examined::settled;
    if (monotone ? (bern_sign(c.A) > 0 && bern_sign(c.Q) > 0) : bern_sign(c.det) > 0) return Examined::settled;
    const std::vector<Rational> half{Rational(1, 2), Rational(1, 2)};
    if (monotone ? (!(bern_value(c.A, half) > 0) || !(bern_value(c.Q, half) > 0)) : !(bern_value(c.det, half) > 0)) return Examined::refuted;
    return Examined::split;
  };
  auto halve = [](Cell&& c, int depth, auto&& emit) {  // u and v in turn
    const int d = depth % 2;
    const Rational mid = (c.lo[d] + c.hi[d]) / 2;
    auto [A1, A2] = bern_split(c.A, d, Rational(1, 2));
    auto [Q1, Q2] = bern_split(c.Q, d, Rational(1, 2));
    auto [D1, D2] = bern_split(c.det, d, Rational(1, 2));
    Cell l{A1, Q1, D1, c.lo, c.hi}, r{A2, Q2, D2, c.lo, c.hi};
    l.hi[d] = mid, r.lo[d] = mid;
    emit(std::move(l));
    emit(std::move(r));
  };
  Budget budget;
  budget.max_boxes = o.max_pieces;
  budget.max_depth = o.max_depth;
  return subdivide(cells, Walk{Order::breadth_first, 2, true}, budget, positive, halve, [](Cell&&, Left) {}).decided();
}

// Regularity and injectivity: the projection P of Step 1 (aligned to Omega by projection_alignment)
// monotone on the bounding box of Omega, else the grid of monotone windows, else det DP > 0 on Omega
// (regularity alone). Sets V.regular, V.injective and V.regularity_method; returns whether the
// certificate is left undecided.
bool certify_regularity(SurfaceValidity& V, const std::vector<LoopSide3>& loop, const DomainPolygon& domain,
                        const std::vector<BezierPiece<Rational>>& pieces, const std::vector<K::Point_2>& poly, const SurfaceFacetOptions& o,
                        std::chrono::steady_clock::time_point t0) {
  const auto& W = domain.vertices;
  bool undecided = false;
  // regularity and injectivity: the projection's Jacobian
  P2 blo = W[0], bhi = W[0];
  for (const auto& w : W)
    for (int k = 0; k < 2; ++k) blo[k] = std::min(blo[k], w[k]), bhi[k] = std::max(bhi[k], w[k]);
  const int a0 = domain.axes[0], a1 = domain.axes[1];
  const auto M = projection_alignment(loop, domain);
  const std::vector<JacobianCell> cells = jacobian_cells(pieces, blo, bhi, a0, a1, M);
  auto certify_cells = [&](bool monotone) { return jacobian_certified(cells, poly, monotone, o); };
  const bool aligned = !(M[0] == 1 && M[1] == 0 && M[2] == 0 && M[3] == 1);
  GridCertificate G;
  const std::string axes = aligned ? "M (" + std::string("xyz").substr(a0, 1) + std::string("xyz").substr(a1, 1) + "), M = [[" + M[0].str() + ", " + M[1].str() +
                                         "], [" + M[2].str() + ", " + M[3].str() + "]] the loop's projection fitted to Omega"
                                   : std::string("xyz").substr(a0, 1) + std::string("xyz").substr(a1, 1);
  if (certify_cells(true)) {
    V.regularity_method = "P = (" + axes + ") of p has DP + DP^T positive definite on the bounding box of Omega (Bernstein signs): P is a monotone map "
                          "on a convex set, so injective, and p's normal has a non-zero " + std::string("xyz").substr(3 - a0 - a1, 1) + " component";
    V.regular = V.injective = Verdict::proved(V.regularity_method);
  } else if (phase(o, t0, "certificate: regularity and injectivity on a grid of windows"),
             G = grid_injectivity(pieces, poly, std::min(o.max_depth / 2, 4), std::min<std::size_t>(o.max_pieces, 65536)), G.proved) {
    V.regularity_method = "no single projection is monotone (" + axes + "); on a grid of " + std::to_string(G.cells) + " cells meeting Omega (level " +
                          std::to_string(G.level) + "), every window of 3 x 3 cells is mapped injectively with a regular Jacobian (A p monotone, A the "
                          "left inverse of Dp at the window's centre, Bernstein signs), and cells 3 or more apart have disjoint boxes";
    V.regular = V.injective = Verdict::proved(V.regularity_method);
  } else if (certify_cells(false)) {
    V.regularity_method = "det DP > 0 on Omega for P = (" + axes + ") of p (Bernstein signs); the monotone criterion for injectivity does not hold, "
                          "nor the grid of windows (" + G.why + ")";
    V.regular = Verdict::proved(V.regularity_method);
    V.injective = Verdict::undecided(V.regularity_method);
    undecided = true;
  } else {
    V.regularity_method = "neither DP + DP^T positive definite nor det DP > 0 could be certified for P = (" + axes + ") of p, nor the grid of windows (" +
                          G.why + ")";
    V.regular = V.injective = Verdict::undecided(V.regularity_method);
    undecided = true;
  }
  return undecided;
}

// A facet's Bezier piece: its facet and control box (lo x, y, z, then hi x, y, z).
struct FacetBox {
  std::size_t facet;
  std::array<Rational, 6> box;
};

// Collision: the patch's pieces that meet Omega, halved, against the control boxes of the facets'
// Bezier pieces, those inside the strip around the loop excluded; a piece's centre outside the solid
// or on a facet (exact ray parity) is a witness. Sets V.membership, the counts, the witness and
// V.collision; returns whether pieces were left undecided.
bool certify_collision(SurfaceValidity& V, const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const BSpline<Rational>& patch,
                       const std::vector<BezierPiece<Rational>>& pieces, const std::vector<K::Point_2>& poly, const SurfaceFacetOptions& o) {
  // collision
  std::string why;
  const auto triangles = cut_detail::membership_model(solid, why);
  const bool membership = triangles.has_value();
  V.membership = !membership ? "not available: " + why
                 : triangles->bilinears.empty()
                     ? "exact ray parity (planar convex quadrilateral facets)"
                     : "exact ray parity (bilinear quadrilateral facets: planar convex ones as two triangles, the others by the exact quadratic-irrational "
                       "roots of their ray equations)";
  std::vector<FacetBox> fboxes;
  for (std::size_t i = 0; i < solid.facets.size(); ++i)
    for (const auto& bz : extract_bezier(solid.facets[i])) fboxes.push_back({i, control_bounds(bz.spline)});
  bool collided = false, col_undecided = false;
  if (!V.witness) {
    // Breadth first on the engine: a piece that meets Omega is examined against the budget of
    // o.max_pieces (pieces outside Omega are not counted) and split until o.max_depth; a piece left
    // at either limit is counted undecided.
    std::size_t examined = 0;
    Budget budget;
    budget.max_depth = o.max_depth;
    auto examine = [&](const BSpline<Rational>& pc, int) {
      const P2 lo{pc.domain_lo(0), pc.domain_lo(1)}, hi{pc.domain_hi(0), pc.domain_hi(1)};
      if (!box_meets_polygon(lo, hi, poly)) return Examined::settled;
      if (++examined > o.max_pieces) return Examined::left;
      const auto box = control_bounds(pc);
      if (box_in_loop_strip(loop, {box[0], box[1], box[2]}, {box[3], box[4], box[5]}, o.strip)) {
        ++V.collision_excluded;
        return Examined::settled;
      }
      bool meets = false;
      for (const auto& fb : fboxes)
        if (box[0] <= fb.box[3] && fb.box[0] <= box[3] && box[1] <= fb.box[4] && fb.box[1] <= box[4] && box[2] <= fb.box[5] && fb.box[2] <= box[5]) {
          meets = true;
          break;
        }
      if (!meets) {
        ++V.collision_pieces;
        return Examined::settled;
      }
      if (membership) {
        const P2 w{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
        if (in_polygon(w, poly)) {
          const P3 x = eval3(patch, w);
          if (!in_loop_strip(loop, x, o.strip)) {
            const auto mb = cut_detail::membership_of(*triangles, x);
            if (mb && *mb != Membership::inside) {
              V.witness = SurfaceValidity::Witness{"collision", w, x, Rational(0),
                                                   *mb == Membership::outside ? "p(w) lies outside the solid (exact ray parity): the surface crosses the boundary"
                                                                              : "p(w) lies on a facet, away from the loop"};
              collided = true;
              return Examined::refuted;
            }
          }
        }
      }
      return Examined::split;
    };
    auto split = [](BSpline<Rational>&& pc, int, auto&& emit) {
      const P2 lo{pc.domain_lo(0), pc.domain_lo(1)}, hi{pc.domain_hi(0), pc.domain_hi(1)};
      const int d = (hi[0] - lo[0] >= hi[1] - lo[1]) ? 0 : 1;
      auto [l, r] = split_at(pc, d, Rational((lo[d] + hi[d]) / 2));
      emit(std::move(l));
      emit(std::move(r));
    };
    auto leave = [&](BSpline<Rational>&&, Left) {
      ++V.collision_undecided;
      col_undecided = true;
    };
    std::vector<BSpline<Rational>> roots;
    for (const auto& pc : pieces) roots.push_back(pc.spline);
    subdivide(std::move(roots), Walk{Order::breadth_first, 2, false}, budget, examine, split, leave);
  }
  V.collision = collided       ? Verdict::refuted(V.witness->detail)
                : col_undecided ? Verdict::undecided(std::to_string(V.collision_undecided) + " pieces left undecided at --max-depth")
                : V.witness     ? Verdict::undecided("not examined (another condition failed)")
                                : Verdict::proved("no piece of the patch outside the strip meets the solid's outside (exact ray parity)");
  return col_undecided;
}

}  // namespace

SurfaceValidity certify_cutting_surface(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const DomainPolygon& domain,
                                        const BSpline<Rational>& patch, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto t0 = std::chrono::steady_clock::now();
  SurfaceValidity V;
  const auto& W = domain.vertices;
  const auto poly = checked_omega(loop, domain, patch);
  const auto pieces = extract_bezier(patch);
  std::vector<Rational> knots_all;
  for (int d = 0; d < 2; ++d)
    for (const auto& k : patch.knots[d]) knots_all.push_back(k);
  bool undecided = false;

  phase(o, t0, "certificate: vertices, boundary and tangents");
  certify_vertices(V, loop, W, patch);
  // boundary deviation and tangents, edge by edge, piece by piece
  certify_boundary_and_tangents(V, loop, W, patch, pieces, knots_all, o);
  if (V.tangents.is_undecided()) undecided = true;

  phase(o, t0, "certificate: regularity and injectivity");
  if (certify_regularity(V, loop, domain, pieces, poly, o, t0)) undecided = true;

  phase(o, t0, "certificate: collision");
  if (certify_collision(V, solid, loop, patch, pieces, poly, o)) undecided = true;
  if (V.witness) V.verdict = Verdict::refuted("a condition fails at the witness, an exact point (" + V.witness->condition + ")");
  else if (undecided || !V.vertices_exact)
    V.verdict = Verdict::undecided(V.vertices_exact ? "a condition is undecided (see the conditions)" : "the patch interpolates the loop's vertices only approximately");
  else V.verdict = Verdict::proved("Section 2's conditions hold");
  V.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return V;
}

SurfaceSplit split_by_surface(const Solid3<Rational>& solid, const std::vector<std::size_t>& positive) {
  SurfaceSplit s;
  std::vector<char> b(solid.facets.size(), 0);
  for (auto i : positive) b.at(i) = 1;
  for (std::size_t i = 0; i < solid.facets.size(); ++i) (b[i] ? s.part1 : s.part2).push_back(i);
  return s;
}

}  // namespace splinex
