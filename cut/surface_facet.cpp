#include "cut/surface_facet.hpp"

#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <mpfr.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <chrono>
#include <deque>
#include <iostream>
#include <optional>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "bernstein/subdivide.hpp"
#include "bernstein/tensor.hpp"
#include "compose/compose.hpp"
#include "cut/guide.hpp"
#include "cut/membership.hpp"
#include "cut/qp.hpp"
#include "exact/linear_solve.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/hodograph.hpp"

namespace splinex {

namespace {

using P2 = Point2<Rational>;
using P3 = Point3<Rational>;
using K = CGAL::Simple_cartesian<CGAL::Gmpq>;

K::Point_2 cg(const P2& p) { return K::Point_2(CGAL::Gmpq(p[0].backend().data()), CGAL::Gmpq(p[1].backend().data())); }

std::vector<K::Point_2> cg_polygon(const std::vector<P2>& v) {
  std::vector<K::Point_2> r;
  for (const auto& p : v) r.push_back(cg(p));
  return r;
}

Rational rabs(const Rational& x) { return x < 0 ? Rational(-x) : x; }
Rational max_abs3(const P3& a) { return std::max(rabs(a[0]), std::max(rabs(a[1]), rabs(a[2]))); }

// ---- Step 1 --------------------------------------------------------------------------------------

// x rounded to the nearest multiple of 2^-bits, exactly (MPFR at the precision x needs: no double).
Rational round_to_grid(const mpfr_t x, unsigned bits) {
  mpfr_t y;
  mpfr_init2(y, mpfr_get_prec(x));
  mpfr_mul_2ui(y, x, bits, MPFR_RNDN);
  mpfr_round(y, y);
  mpz_t z;
  mpz_init(z);
  mpfr_get_z(z, y, MPFR_RNDN);
  Rational r;
  mpq_set_z(r.backend().data(), z);
  mpz_clear(z);
  mpfr_clear(y);
  return r / Rational(boost::multiprecision::mpz_int(1) << bits);
}

// The point (1/2 + cos(a) / 2, 1/2 + sin(a) / 2), a = 2 pi (phi + 1/(2n)), each coordinate rounded to
// a multiple of 2^-11 (MPFR at 160 bits, not double). Small common denominators keep the patch
// program's exact numbers short (points exactly on the circle had 100-bit denominators, and the
// exact KKT system took minutes).
P2 circle_point(const Rational& phi, std::size_t n) {
  mpfr_t a, c, sn;
  mpfr_inits2(160, a, c, sn, static_cast<mpfr_ptr>(nullptr));
  const Rational f = phi + Rational(1, static_cast<long>(2 * n));
  mpfr_set_q(a, f.backend().data(), MPFR_RNDN);
  mpfr_const_pi(c, MPFR_RNDN);
  mpfr_mul(a, a, c, MPFR_RNDN);
  mpfr_mul_2ui(a, a, 1, MPFR_RNDN);  // 2 pi f
  mpfr_sin_cos(sn, c, a, MPFR_RNDN);
  P2 r;
  mpfr_ptr v[2] = {c, sn};
  for (int k = 0; k < 2; ++k) {
    mpfr_div_2ui(v[k], v[k], 1, MPFR_RNDN);  // cos / 2, sin / 2 (exact)
    r[k] = Rational(1, 2) + round_to_grid(v[k], 11);
  }
  mpfr_clears(a, c, sn, static_cast<mpfr_ptr>(nullptr));
  return r;
}

// An approximation of |d| (relative error far below 2^-60), only used to place the circle's vertices.
Rational approximate_length(const P3& d) {
  mpfr_t a;
  mpfr_init2(a, 128);
  const Rational s = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  mpfr_set_q(a, s.backend().data(), MPFR_RNDN);
  mpfr_sqrt(a, a, MPFR_RNDN);
  const Rational r = round_to_grid(a, 64);
  mpfr_clear(a);
  return r;
}

// q rounded to the nearest multiple of 2^-bits (through MPFR at 256 bits: the callers' q are at most
// 1 in magnitude).
Rational round_to_grid(const Rational& q, unsigned bits) {
  mpfr_t x;
  mpfr_init2(x, 256);
  mpfr_set_q(x, q.backend().data(), MPFR_RNDN);
  const Rational r = round_to_grid(x, bits);
  mpfr_clear(x);
  return r;
}

// The exact unit vector (1 - t^2, 2 t) / (1 + t^2), t = tan(phi / 2) rounded to a multiple of 2^-12,
// for |phi| <= pi / 2 (|t| <= 1); other angles through phi -/+ pi and the opposite vector. A
// rational point exactly on the unit circle, within about 2^-12 rad of the direction phi.
P2 rational_direction(const mpfr_t phi_in) {
  mpfr_t phi, pi, h;
  mpfr_inits2(160, phi, pi, h, static_cast<mpfr_ptr>(nullptr));
  mpfr_set(phi, phi_in, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  // phi into (-pi, pi]
  mpfr_mul_2ui(h, pi, 1, MPFR_RNDN);
  mpfr_remainder(phi, phi, h, MPFR_RNDN);
  bool flip = false;
  mpfr_div_2ui(h, pi, 1, MPFR_RNDN);
  if (mpfr_cmpabs(phi, h) > 0) {
    flip = true;
    if (mpfr_sgn(phi) > 0)
      mpfr_sub(phi, phi, pi, MPFR_RNDN);
    else
      mpfr_add(phi, phi, pi, MPFR_RNDN);
  }
  mpfr_div_2ui(phi, phi, 1, MPFR_RNDN);
  mpfr_tan(h, phi, MPFR_RNDN);
  const Rational t = round_to_grid(h, 12);
  mpfr_clears(phi, pi, h, static_cast<mpfr_ptr>(nullptr));
  const Rational d = 1 + t * t;
  P2 u{(1 - t * t) / d, 2 * t / d};
  if (flip) u = {Rational(-u[0]), Rational(-u[1])};
  return u;
}

bool simple_polygon(const std::vector<P2>& v, std::string& why) {
  for (std::size_t j = 0; j < v.size(); ++j)
    if (v[j] == v[(j + 1) % v.size()]) {
      why = "loop side " + std::to_string(j) + " collapses to a point in the projection";
      return false;
    }
  const auto poly = cg_polygon(v);
  if (!CGAL::is_simple_2(poly.begin(), poly.end(), K())) {
    why = "the projected loop intersects itself";
    return false;
  }
  return true;
}

// Uniform scaling of the points into [0, 1]^2, centred; false when they span nothing.
bool into_unit_square(std::vector<P2>& q) {
  P2 lo = q[0], hi = q[0];
  for (const auto& p : q)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const Rational ext = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (ext == 0) return false;
  for (auto& p : q)
    for (int k = 0; k < 2; ++k) p[k] = (p[k] - lo[k]) / ext + (ext - (hi[k] - lo[k])) / (2 * ext);
  return true;
}

// Eq. 5 of papers/004. The turning angle at vertex j (from side j-1 to side j) is
// theta_j = atan2((d_{j-1} x d_j) . N / |N|, d_{j-1} . d_j), N the loop's Newell normal: the turn seen
// along N (a turn about an axis in the loop's mean plane, like the maiden's wave, counts 0). The
// alpha_j = theta_j 2 pi / sum theta (the sum must be positive), and side j's direction is
// phi_j = alpha_1 + ... + alpha_j, taken as the exact rational unit vector u_j within 2^-12 rad
// (rational_direction). With l_j the side's length (to 2^-64) and y_j = x_j / l_j, Eq. 5 is
//   min sum (y_j - 1)^2  subject to  sum y_j l_j u_j = 0,
// whose solution is y = 1 - B^T (B B^T)^-1 B 1, B = [l_j u_j] (2 x n), exactly. Every x_j must be
// positive. The vertices are the partial sums of x_j u_j (a closed polygon, exactly), scaled
// uniformly into [0, 1]^2 and rounded to multiples of 2^-11 (short numbers for the patch program,
// as for the circle), then checked simple and counter-clockwise.
std::optional<std::vector<P2>> eq5_polygon(const std::vector<LoopSide3>& loop, std::string& why) {
  const std::size_t n = loop.size();
  const P3 N = newell_normal(loop);
  const Rational NN = dot(N, N);
  if (NN == 0) {
    why = "the loop's Newell normal is zero";
    return std::nullopt;
  }
  mpfr_t nn, s, c, th, sum, tw, a;
  mpfr_inits2(160, nn, s, c, th, sum, tw, a, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(nn, NN.backend().data(), MPFR_RNDN);
  mpfr_sqrt(nn, nn, MPFR_RNDN);
  std::vector<Rational> sq(n), cq(n);
  for (std::size_t j = 0; j < n; ++j) {
    const P3 din = sub(loop[(j + n - 1) % n].end, loop[(j + n - 1) % n].start), dout = sub(loop[j].end, loop[j].start);
    sq[j] = dot(cross(din, dout), N);
    cq[j] = dot(din, dout);
  }
  // theta_j = atan2(sq_j / |N|, cq_j); sum them
  std::vector<__mpfr_struct> theta(n);
  mpfr_set_ui(sum, 0, MPFR_RNDN);
  for (std::size_t j = 0; j < n; ++j) {
    mpfr_init2(&theta[j], 160);
    mpfr_set_q(s, sq[j].backend().data(), MPFR_RNDN);
    mpfr_div(s, s, nn, MPFR_RNDN);
    mpfr_set_q(c, cq[j].backend().data(), MPFR_RNDN);
    mpfr_atan2(&theta[j], s, c, MPFR_RNDN);
    mpfr_add(sum, sum, &theta[j], MPFR_RNDN);
  }
  std::optional<std::vector<P2>> result;
  std::vector<P2> u(n);
  mpfr_const_pi(tw, MPFR_RNDN);
  mpfr_mul_2ui(tw, tw, 1, MPFR_RNDN);
  mpfr_div_2ui(a, tw, 1, MPFR_RNDN);  // pi
  if (mpfr_cmp(sum, a) <= 0) {
    why = "the loop's turning angles seen along its Newell normal sum to " + std::to_string(mpfr_get_d(sum, MPFR_RNDN)) + " (not near 2 pi)";
  } else {
    // phi_0 = 0, phi_j = phi_{j-1} + alpha_j
    mpfr_set_ui(a, 0, MPFR_RNDN);
    for (std::size_t j = 0; j < n; ++j) {
      if (j > 0) {
        mpfr_mul(th, &theta[j], tw, MPFR_RNDN);
        mpfr_div(th, th, sum, MPFR_RNDN);
        mpfr_add(a, a, th, MPFR_RNDN);
      }
      u[j] = rational_direction(a);
    }
  }
  for (auto& t : theta) mpfr_clear(&t);
  mpfr_clears(nn, s, c, th, sum, tw, a, static_cast<mpfr_ptr>(nullptr));
  if (!why.empty()) return std::nullopt;
  std::vector<Rational> len(n);
  for (std::size_t j = 0; j < n; ++j) len[j] = approximate_length(sub(loop[j].end, loop[j].start));
  // G = B B^T, r = B 1
  Rational g00(0), g01(0), g11(0), r0(0), r1(0);
  for (std::size_t j = 0; j < n; ++j) {
    const Rational b0 = len[j] * u[j][0], b1 = len[j] * u[j][1];
    g00 += b0 * b0, g01 += b0 * b1, g11 += b1 * b1, r0 += b0, r1 += b1;
  }
  const Rational det = g00 * g11 - g01 * g01;
  if (det == 0) {
    why = "the sides' directions of Eq. 5 are all parallel";
    return std::nullopt;
  }
  const Rational m0 = (g11 * r0 - g01 * r1) / det, m1 = (g00 * r1 - g01 * r0) / det;
  std::vector<P2> v(n);
  v[0] = {Rational(0), Rational(0)};
  for (std::size_t j = 0; j < n; ++j) {
    const Rational y = 1 - (len[j] * u[j][0] * m0 + len[j] * u[j][1] * m1);
    if (!(y > 0)) {
      why = "Eq. 5 gives side " + std::to_string(j) + " the length factor " + std::to_string(to_double(y)) + " <= 0";
      return std::nullopt;
    }
    if (j + 1 < n) v[j + 1] = {v[j][0] + y * len[j] * u[j][0], v[j][1] + y * len[j] * u[j][1]};
  }
  if (!into_unit_square(v)) {
    why = "Eq. 5's polygon spans nothing";
    return std::nullopt;
  }
  for (auto& p : v)
    for (int k = 0; k < 2; ++k) p[k] = round_to_grid(p[k], 11);
  if (!simple_polygon(v, why)) {
    why = "Eq. 5's polygon (vertices on the 2^-11 grid) is not simple: " + why;
    return std::nullopt;
  }
  Rational area(0);
  for (std::size_t j = 0; j < n; ++j) area += v[j][0] * v[(j + 1) % n][1] - v[(j + 1) % n][0] * v[j][1];
  if (!(area > 0)) {
    why = "Eq. 5's polygon runs clockwise";
    return std::nullopt;
  }
  return v;
}

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

// ---- Step 2 --------------------------------------------------------------------------------------

template <class T>
T from_q(const Rational& x) {
  return ArithTraits<T>::from_rational(x);
}

// x rounded to a multiple of 2^-20 (exactly, to nearest): the loop sides' unit normals carry
// 80-bit denominators from the exact inverse square root, all different; summed into the program
// they made its numbers thousands of bits long. The normal term only needs the direction.
Rational dyadic20(const Rational& x) {
  const Rational y = x * (1 << 20);
  boost::multiprecision::mpz_int q = numerator(y) / denominator(y);  // toward zero
  Rational r(q);
  if (y - r >= Rational(1, 2)) r += 1;
  else if (r - y > Rational(1, 2)) r -= 1;
  return r / (1 << 20);
}

template <class T>
void add_outer(QuadraticProgram<T>& qp, const std::vector<std::pair<std::size_t, T>>& a, const T& w) {
  for (const auto& [i, vi] : a)
    for (const auto& [j, vj] : a) qp.d(i, j) += w * vi * vj;
}

Rational sparse_dot(const std::vector<std::pair<std::size_t, Rational>>& a, const std::vector<Rational>& x) {
  Rational s(0);
  for (const auto& [i, v] : a) s += v * x[i];
  return s;
}

// ---- certificates --------------------------------------------------------------------------------

bool box_meets_polygon(const P2& lo, const P2& hi, const std::vector<K::Point_2>& poly) {
  const K::Iso_rectangle_2 box(cg(lo), cg(hi));
  for (std::size_t j = 0; j < poly.size(); ++j)
    if (CGAL::do_intersect(K::Segment_2(poly[j], poly[(j + 1) % poly.size()]), box)) return true;
  return CGAL::bounded_side_2(poly.begin(), poly.end(), cg(lo), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

bool in_polygon(const P2& w, const std::vector<K::Point_2>& poly) {
  return CGAL::bounded_side_2(poly.begin(), poly.end(), cg(w), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

P3 eval3(const BSpline<Rational>& S, const P2& w) {
  const auto v = evaluate(S, std::vector<Rational>{w[0], w[1]});
  return {v[0], v[1], v[2]};
}

Bernstein<Rational> scaled(Bernstein<Rational> b, const Rational& s) {
  for (auto& c : b.c) c *= s;
  return b;
}

// The piece of the patch (extract_bezier) whose box holds w.
const BezierPiece<Rational>& piece_at(const std::vector<BezierPiece<Rational>>& pieces, const P2& w) {
  for (const auto& p : pieces)
    if (p.box[0].first <= w[0] && w[0] <= p.box[0].second && p.box[1].first <= w[1] && w[1] <= p.box[1].second) return p;
  throw std::logic_error("piece_at: outside the patch");
}

// Injectivity and regularity by a grid of cells (the fallback when no single projection works, as
// for surfaces that turn through 90 degrees, like the maiden's wave). At level m every Bezier piece
// is cut into 2^m x 2^m cells, numbered (I, J) over the whole patch. Then
//   (a) on every window of 3 x 3 cells that holds a cell meeting Omega, F = A p is a monotone map:
//       A (2 x 3) the left inverse of Dp at the window's centre, rounded (any fixed A keeps the
//       argument), and the symmetric part of DF = A Dp positive definite on each of its 9 cells
//       (Bernstein signs of A_0 p_u and 4 (A_0 p_u)(A_1 p_v) - (A_0 p_v + A_1 p_u)^2). The window is a
//       rectangle, so F is injective on it and DF non-singular: p is injective and regular there;
//   (b) any two cells meeting Omega whose indices differ by 3 or more in I or J have disjoint boxes
//       of Bernstein coefficients (the convex hulls of their images).
// Two parameters of Omega whose cells differ by at most 2 in I and J share a window (a); all other
// pairs are separated by (b). So p is injective on Omega and regular there. Levels are tried until
// both hold or the cells exceed max_cells.
struct GridCertificate {
  bool proved = false;
  int level = -1;
  std::size_t cells = 0, windows = 0;
  std::string why;  // the last level's failure
};

GridCertificate grid_injectivity(const std::vector<BezierPiece<Rational>>& pieces, const std::vector<K::Point_2>& poly, int max_level,
                                 std::size_t max_cells) {
  GridCertificate R;
  // the pieces' columns and rows
  std::vector<Rational> us, vs;
  for (const auto& pc : pieces) us.push_back(pc.box[0].first), vs.push_back(pc.box[1].first);
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  // Every coordinate times the common denominator L of all the pieces' control points: a positive
  // factor changes no sign and no order, and the integers it leaves (with the small denominators
  // of the dyadic splits) spare the gcds of exact patches' long fractions (minutes -> seconds).
  Rational L(1);
  {
    boost::multiprecision::mpz_int l(1);
    for (const auto& pc : pieces)
      for (const auto& x : pc.spline.points) {
        const boost::multiprecision::mpz_int d = boost::multiprecision::denominator(x);
        if (d != 1) mpz_lcm(l.backend().data(), l.backend().data(), d.backend().data());
      }
    L = Rational(l);
  }
  struct Cell {
    bool meets = false, built = false;
    P2 lo, hi;
    const BezierPiece<Rational>* piece = nullptr;
    int i = 0, j = 0;  // the sub-cell within the piece
    std::array<Bernstein<Rational>, 3> pu, pv;
    std::array<std::pair<Rational, Rational>, 3> box;
  };
  for (int m = 0; m <= max_level; ++m) {
    const long k = 1L << m, GI = static_cast<long>(us.size()) * k, GJ = static_cast<long>(vs.size()) * k;
    if (GI < 3 || GJ < 3) continue;
    if (static_cast<std::size_t>(GI * GJ) > max_cells) {
      if (R.why.empty()) R.why = "the grid would exceed " + std::to_string(max_cells) + " cells";
      break;
    }
    R.level = m;
    std::vector<Cell> cells(static_cast<std::size_t>(GI * GJ));
    auto at = [&](long I, long J) -> Cell& { return cells[static_cast<std::size_t>(J * GI + I)]; };
    for (const auto& pc : pieces) {
      const long pi = std::lower_bound(us.begin(), us.end(), pc.box[0].first) - us.begin();
      const long pj = std::lower_bound(vs.begin(), vs.end(), pc.box[1].first) - vs.begin();
      const Rational hu = (pc.box[0].second - pc.box[0].first) / k, hv = (pc.box[1].second - pc.box[1].first) / k;
      for (long i = 0; i < k; ++i)
        for (long j = 0; j < k; ++j) {
          Cell& c = at(pi * k + i, pj * k + j);
          c.piece = &pc;
          c.i = static_cast<int>(i), c.j = static_cast<int>(j);
          c.lo = {pc.box[0].first + hu * i, pc.box[1].first + hv * j};
          c.hi = {c.lo[0] + hu, c.lo[1] + hv};
          c.meets = box_meets_polygon(c.lo, c.hi, poly);
        }
    }
    auto build = [&](Cell& c) {
      if (c.built) return;
      c.built = true;
      const Rational a0(c.i, k), a1(c.i + 1, k), b0(c.j, k), b1(c.j + 1, k);
      const Rational hu = c.hi[0] - c.lo[0], hv = c.hi[1] - c.lo[1];
      for (int d = 0; d < 3; ++d) {
        auto X = scaled(bern_coordinate(c.piece->spline, d), L);
        if (k > 1) X = bern_restrict(bern_restrict(X, 0, a0, a1), 1, b0, b1);
        const auto [lo, hi] = bern_range(X);
        c.box[d] = {lo, hi};
        c.pu[d] = scaled(bern_derivative(X, 0), 1 / hu);
        c.pv[d] = scaled(bern_derivative(X, 1), 1 / hv);
      }
    };
    R.cells = 0;
    for (auto& c : cells)
      if (c.meets) ++R.cells;
    // (a) the windows
    bool ok = true;
    R.windows = 0;
    for (long I = 0; ok && I + 2 < GI; ++I)
      for (long J = 0; ok && J + 2 < GJ; ++J) {
        bool any = false;
        for (long a = 0; a < 3; ++a)
          for (long b = 0; b < 3; ++b) any = any || at(I + a, J + b).meets;
        if (!any) continue;
        ++R.windows;
        Cell& mid = at(I + 1, J + 1);
        build(mid);
        const std::vector<Rational> half{Rational(1, 2), Rational(1, 2)};
        P3 u, v;
        for (int d = 0; d < 3; ++d) u[d] = bern_value(mid.pu[d], half), v[d] = bern_value(mid.pv[d], half);
        const Rational g00 = dot(u, u), g01 = dot(u, v), g11 = dot(v, v), det = g00 * g11 - g01 * g01;
        if (det == 0) {
          ok = false;
          R.why = "p_u x p_v = 0 at the centre of the window at cell (" + std::to_string(I + 1) + ", " + std::to_string(J + 1) + ")";
          break;
        }
        // A = G^-1 [u^T; v^T], rounded to 20 bits relative to its largest entry
        std::array<Rational, 6> A;
        for (int d = 0; d < 3; ++d) A[d] = (g11 * u[d] - g01 * v[d]) / det, A[3 + d] = (g00 * v[d] - g01 * u[d]) / det;
        Rational mx(0);
        for (const auto& x : A) mx = std::max(mx, rabs(x));
        for (auto& x : A) x = round_to_grid(Rational(x / mx), 20);
        for (long a = 0; ok && a < 3; ++a)
          for (long b = 0; ok && b < 3; ++b) {
            Cell& c = at(I + a, J + b);
            build(c);
            auto row = [&](int r, const std::array<Bernstein<Rational>, 3>& w) {
              Bernstein<Rational> s = scaled(w[0], A[3 * r]);
              s = bern_combine(s, scaled(w[1], A[3 * r + 1]), false);
              return bern_combine(s, scaled(w[2], A[3 * r + 2]), false);
            };
            const auto fa = row(0, c.pu), fb1 = row(0, c.pv), fb2 = row(1, c.pu), fc = row(1, c.pv);
            const auto S = bern_combine(fb1, fb2, false);
            const auto Q = bern_combine(scaled(bern_product(fa, fc), Rational(4)), bern_product(S, S), true);
            if (!(bern_sign(fa) > 0 && bern_sign(Q) > 0)) {
              ok = false;
              R.why = "the window at cell (" + std::to_string(I + 1) + ", " + std::to_string(J + 1) + ") is not certified monotone";
            }
          }
      }
    if (!ok) continue;
    // (b) far cells: disjoint boxes (sweep over the x extent)
    std::vector<std::pair<long, long>> meet;
    for (long I = 0; I < GI; ++I)
      for (long J = 0; J < GJ; ++J)
        if (at(I, J).meets) build(at(I, J)), meet.emplace_back(I, J);
    std::sort(meet.begin(), meet.end(), [&](const auto& x, const auto& y) { return at(x.first, x.second).box[0].first < at(y.first, y.second).box[0].first; });
    for (std::size_t x = 0; ok && x < meet.size(); ++x) {
      const Cell& c1 = at(meet[x].first, meet[x].second);
      for (std::size_t y = x + 1; y < meet.size(); ++y) {
        const Cell& c2 = at(meet[y].first, meet[y].second);
        if (c1.box[0].second < c2.box[0].first) break;
        if (std::abs(meet[x].first - meet[y].first) < 3 && std::abs(meet[x].second - meet[y].second) < 3) continue;
        if (c1.box[1].second < c2.box[1].first || c2.box[1].second < c1.box[1].first || c1.box[2].second < c2.box[2].first ||
            c2.box[2].second < c1.box[2].first)
          continue;
        ok = false;
        R.why = "the boxes of the far cells (" + std::to_string(meet[x].first) + ", " + std::to_string(meet[x].second) + ") and (" +
                std::to_string(meet[y].first) + ", " + std::to_string(meet[y].second) + ") meet";
        break;
      }
    }
    if (ok) {
      R.proved = true;
      R.why.clear();
      return R;
    }
  }
  return R;
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

}  // namespace

// ---- Step 1 --------------------------------------------------------------------------------------

std::array<Rational, 3> newell_normal(const std::vector<LoopSide3>& loop) {
  const std::size_t n = loop.size();
  P3 N{Rational(0), Rational(0), Rational(0)};
  for (std::size_t j = 0; j < n; ++j) {
    const auto &a = loop[j].start, &b = loop[(j + 1) % n].start;
    N[0] += (a[1] - b[1]) * (a[2] + b[2]);
    N[1] += (a[2] - b[2]) * (a[0] + b[0]);
    N[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return N;
}

std::array<int, 2> projection_axes(const std::vector<LoopSide3>& loop) {
  const P3 N = newell_normal(loop);
  int ax = 0;
  for (int k = 1; k < 3; ++k)
    if (rabs(N[k]) > rabs(N[ax])) ax = k;
  std::array<int, 2> a{(ax + 1) % 3, (ax + 2) % 3};
  if (N[ax] < 0) std::swap(a[0], a[1]);
  return a;
}

DomainPolygon domain_polygon(const std::vector<LoopSide3>& loop, const std::string& method) {
  const std::size_t n = loop.size();
  if (n < 3) throw DomainError("cut", "the loop has " + std::to_string(n) + " sides; a cutting surface needs at least 3", "choose b so that the loop has 3 or more sides");
  if (method != "auto" && method != "projection" && method != "qp" && method != "circle")
    throw UsageError("domain", "'" + method + "' is not a domain method", "give auto, projection, qp or circle");
  DomainPolygon D;
  const P3 N = newell_normal(loop);
  D.axes = projection_axes(loop);
  const int ax = 3 - D.axes[0] - D.axes[1];
  if (method == "auto" || method == "projection") {
    std::vector<P2> q;
    for (const auto& L : loop) q.push_back({L.start[D.axes[0]], L.start[D.axes[1]]});
    P2 lo = q[0], hi = q[0];
    for (const auto& p : q)
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const Rational ext = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    std::string why;
    if (N[ax] == 0 || ext == 0) {
      why = "the loop's Newell normal is zero (the loop encloses no area in any projection)";
    } else {
      for (auto& p : q)
        for (int k = 0; k < 2; ++k) p[k] = (p[k] - lo[k]) / ext + (ext - (hi[k] - lo[k])) / (2 * ext);
      if (simple_polygon(q, why)) {
        D.method = "projection";
        D.vertices = q;
        return D;
      }
    }
    if (method == "projection")
      throw DomainError("domain", "the projection of the loop is not a simple polygon: " + why, "give --domain qp, circle or auto");
    D.why_not_projection = why;
  }
  if (method == "auto" || method == "qp") {
    std::string why;
    if (auto q = eq5_polygon(loop, why)) {
      D.method = "qp";
      D.vertices = std::move(*q);
      return D;
    }
    if (method == "qp") throw DomainError("domain", "the polygon of Eq. 5 failed: " + why, "give --domain circle or auto");
    D.why_not_qp = why;
  }
  // the circle: vertices at angles proportional to arc length, exactly on the circle
  std::vector<Rational> len;
  Rational total(0);
  for (const auto& L : loop) len.push_back(approximate_length(sub(L.end, L.start))), total += len.back();
  Rational cum(0);
  for (std::size_t j = 0; j < n; ++j) {
    D.vertices.push_back(circle_point(cum / total, n));
    cum += len[j];
  }
  std::string why;
  if (!simple_polygon(D.vertices, why))
    throw DomainError("cut", "the circle's vertices (on a 2^-11 grid) do not form a simple polygon: " + why, "merge very short loop sides");
  D.method = "circle";
  return D;
}

void validate_surface_options(const SurfaceFacetOptions& o) {
  if (o.inner_knots < 0 || o.inner_knots > 15)
    throw UsageError("patch-inner-knots", "must be in 0..15 (the exact KKT system is dense: 3 (k+4)^2 unknowns)", "give 0..15 (the paper: 3)");
  if (o.boundary_samples < 1 || o.boundary_samples > 1000) throw UsageError("boundary-samples", "must be in 1..1000", "give e.g. 4");
  if (!(o.weight_boundary > 0)) throw UsageError("weight-boundary", "must be > 0", "give e.g. 1");
  if (o.weight_fair < 0) throw UsageError("weight-fair", "must be >= 0", "give e.g. 1");
  if (o.lambda < 0) throw UsageError("lambda", "must be >= 0", "give e.g. 1");
  if (o.tangent_delta < 0) throw UsageError("tangent-delta", "must be >= 0", "give e.g. 1/20");
  if (!(o.strip > 0)) throw UsageError("strip", "must be > 0", "give e.g. 1/16");
  if (o.max_depth < 0 || o.max_depth > 40) throw UsageError("max-depth", "must be in 0..40", "give e.g. 14");
  if (o.domain != "auto" && o.domain != "projection" && o.domain != "qp" && o.domain != "circle")
    throw UsageError("domain", "'" + o.domain + "' is not a domain method", "give auto, projection, qp or circle");
}

// ---- Step 2 --------------------------------------------------------------------------------------

namespace {

// Whether the vertex interpolation conditions p(W_j) = L_j are independent (exact rank).
bool vertices_independent(const DomainPolygon& D, int inner_knots) {
  const auto U = guide_knots(inner_knots);
  const std::size_t n = U.size() - 4, N = n * n, ns = D.vertices.size();
  if (ns > N) return false;
  std::vector<Rational> A(ns * N, Rational(0));
  for (std::size_t j = 0; j < ns; ++j)
    for (const auto& [i, v] : basis_row(U, n, U, n, D.vertices[j][0], D.vertices[j][1]).v) A[j * N + i] = v;
  return exact_rank(A, ns, N) == ns;
}

}  // namespace

DomainPolygon patch_domain(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  auto D = domain_polygon(loop, o.domain);
  if (o.domain == "auto" && D.method == "qp" && !vertices_independent(D, o.inner_knots)) {
    auto C = domain_polygon(loop, "circle");
    C.why_not_projection = D.why_not_projection;
    C.why_not_qp = "the interpolation conditions at its " + std::to_string(D.vertices.size()) + " vertices are dependent for " +
                   std::to_string(o.inner_knots) + " inner knots (raise --patch-inner-knots to use it)";
    return C;
  }
  return D;
}

void check_patch_program(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto D = patch_domain(loop, o);
  const auto U = guide_knots(o.inner_knots);
  const std::size_t N = (U.size() - 4) * (U.size() - 4), ns = D.vertices.size();
  if (ns > N)
    throw DomainError("patch-inner-knots", "the loop has " + std::to_string(ns) + " vertices, more than the patch's " + std::to_string(N) + " control points",
                      "raise --patch-inner-knots");
  if (!vertices_independent(D, o.inner_knots))
    throw DomainError("patch-inner-knots",
                      "the interpolation conditions at the loop's " + std::to_string(ns) + " vertices (domain " + D.method + ") are dependent for " +
                          std::to_string(o.inner_knots) + " inner knots (too few basis functions around some vertices)",
                      "raise --patch-inner-knots");
}

template <class T>
CuttingSurface<T> cutting_surface(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto t0 = std::chrono::steady_clock::now();
  CuttingSurface<T> R;
  R.domain = patch_domain(loop, o);
  const auto& W = R.domain.vertices;
  const std::size_t ns = loop.size();
  const auto Uq = guide_knots(o.inner_knots);
  std::vector<T> U;
  for (const auto& k : Uq) U.push_back(from_q<T>(k));
  const std::size_t n = Uq.size() - 4, N = n * n, nv = 3 * N;
  QuadraticProgram<T> qp;
  qp.n = nv;
  qp.D.assign(nv * nv, T(0));
  qp.c.assign(nv, T(0));
  const auto M = regularization_matrix(U, U);
  const T wf = from_q<T>(o.weight_fair);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) qp.d(c * N + i, c * N + j) += wf * M[i * N + j];
  const int m = o.boundary_samples;
  const T omega = from_q<T>(o.weight_boundary / Rational(static_cast<long>(ns) * m));
  const T lam = from_q<T>(o.lambda);
  using Row = typename QuadraticProgram<T>::Row;
  std::vector<Row> eq, ineq;
  for (std::size_t j = 0; j < ns; ++j) {
    const P2 &W0 = W[j], &W1 = W[(j + 1) % ns];
    const P2 e{W1[0] - W0[0], W1[1] - W0[1]};
    const Rational em = std::max(rabs(e[0]), rabs(e[1]));
    const P2 inward{-e[1] / em, e[0] / em};
    const auto& L = loop[j];
    // equality: the vertex
    {
      const auto row = basis_row(U, n, U, n, from_q<T>(W0[0]), from_q<T>(W0[1]));
      for (std::size_t c = 0; c < 3; ++c) {
        Row r;
        for (const auto& [i, v] : row.v) r.a.emplace_back(c * N + i, v);
        r.b = from_q<T>(L.start[c]);
        eq.push_back(r);
      }
    }
    for (int k = 0; k < m; ++k) {
      const Rational s(2 * k + 1, 2 * m);
      const P2 w{W0[0] + s * e[0], W0[1] + s * e[1]};
      const auto row = basis_row(U, n, U, n, from_q<T>(w[0]), from_q<T>(w[1]));
      for (std::size_t c = 0; c < 3; ++c) {
        const T Lc = from_q<T>(L.start[c] + s * (L.end[c] - L.start[c]));
        for (const auto& [i, vi] : row.v) {
          for (const auto& [i2, v2] : row.v) qp.d(c * N + i, c * N + i2) += omega * vi * v2;
          qp.c[c * N + i] += T(-2) * omega * Lc * vi;
        }
        qp.c0 += omega * Lc * Lc;
      }
      std::vector<std::pair<std::size_t, T>> au, av, at;
      for (std::size_t c = 0; c < 3; ++c) {
        const T nc = from_q<T>(dyadic20(L.normal[c])), tc = from_q<T>(L.tangent[c]);
        for (std::size_t q = 0; q < row.v.size(); ++q) {
          const std::size_t i = row.v[q].first;
          au.emplace_back(c * N + i, nc * row.dx[q].second);
          av.emplace_back(c * N + i, nc * row.dy[q].second);
          at.emplace_back(c * N + i, tc * (row.dx[q].second * from_q<T>(inward[0]) + row.dy[q].second * from_q<T>(inward[1])));
        }
      }
      add_outer(qp, au, T(omega * lam));
      add_outer(qp, av, T(omega * lam));
      Row r;
      r.a = at;
      r.b = from_q<T>(o.tangent_delta);
      ineq.push_back(r);
    }
  }
  R.variables = nv, R.equalities = eq.size(), R.inequalities = ineq.size();
  if (o.progress)
    std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": assembled " << nv << " variables, " << eq.size() << " equalities, " << ineq.size()
              << " inequalities (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s); solving\n";
  // the full program: each equality as a pair of rows, then the inequalities
  for (const auto& r : eq) {
    qp.rows.push_back(r);
    Row le = r;
    le.at_least = false;
    qp.rows.push_back(le);
  }
  for (const auto& r : ineq) qp.rows.push_back(r);

  // A primal active-set method on exact (or double) KKT systems: the equalities and a working set
  // of inequalities held as equalities, [2D A^T; A 0] [x; mu] = [-c; b]. A violated inequality
  // joins the working set (the most violated first), a working row whose multiplier -mu is
  // negative leaves it; at most `active_set_steps` steps, then CGAL's QP solver on the whole
  // program. Whatever solves it, the KKT conditions of the full program are checked exactly below.
  const auto exact_qp = [&] {
    if constexpr (std::is_same_v<T, Rational>) return qp;
    else return exact_program(qp);
  }();
  const std::size_t ne = eq.size();
  auto solve_kkt = [&](const std::vector<std::size_t>& work, std::vector<Rational>& x, std::vector<Rational>& mu) {
    std::vector<const Row*> rows;
    for (const auto& r : eq) rows.push_back(&r);
    for (auto w : work) rows.push_back(&ineq[w]);
    const std::size_t nr = rows.size(), nk = nv + nr;
    x.clear(), mu.clear();
    if constexpr (std::is_same_v<T, Rational>) {
      std::vector<Rational> A(nk * nk, Rational(0)), B(nk, Rational(0));
      for (std::size_t i = 0; i < nv; ++i) {
        for (std::size_t j = 0; j < nv; ++j) A[i * nk + j] = 2 * qp.d(i, j);
        B[i] = -qp.c[i];
      }
      for (std::size_t r = 0; r < nr; ++r) {
        for (const auto& [i, v] : rows[r]->a) A[(nv + r) * nk + i] = v, A[i * nk + nv + r] = v;
        B[nv + r] = rows[r]->b;
      }
      const auto X = solve_linear_exact(A, nk, B, 1);
      if (!X) return false;
      x.assign(X->begin(), X->begin() + nv);
      mu.assign(X->begin() + nv, X->end());
      return true;
    } else {
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nk, nk);
      Eigen::VectorXd B = Eigen::VectorXd::Zero(nk);
      for (std::size_t i = 0; i < nv; ++i) {
        for (std::size_t j = 0; j < nv; ++j) A(i, j) = 2 * qp.d(i, j);
        B(i) = -qp.c[i];
      }
      for (std::size_t r = 0; r < nr; ++r) {
        for (const auto& [i, v] : rows[r]->a) A(nv + r, i) = v, A(i, nv + r) = v;
        B(nv + r) = rows[r]->b;
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
      if (!lu.isInvertible()) return false;
      const Eigen::VectorXd X = lu.solve(B);
      for (std::size_t i = 0; i < nk; ++i)
        if (!std::isfinite(X(i))) return false;
      for (std::size_t i = 0; i < nv; ++i) x.push_back(exact_from_double(X(i)));
      for (std::size_t r = 0; r < nr; ++r) mu.push_back(exact_from_double(X(nv + r)));
      return true;
    }
  };
  std::vector<std::size_t> work;
  std::vector<Rational> x, mu;
  if (!solve_kkt(work, x, mu))
    throw DomainError("patch-inner-knots",
                      "the interpolation conditions at the loop's " + std::to_string(ns) + " vertices are singular for " +
                          std::to_string(o.inner_knots) + " inner knots (too few basis functions for the vertices)",
                      "raise --patch-inner-knots");
  const std::string kind = std::is_same_v<T, Rational> ? "exact (FLINT, Dixon p-adic solves)" : "double (Eigen FullPivLU)";
  bool optimal = false;
  int steps = 0;
  for (; steps <= o.active_set_steps; ++steps) {
    // a working row with a negative multiplier (y = -mu < 0) leaves
    std::size_t drop = work.size();
    for (std::size_t k = 0; k < work.size(); ++k)
      if (mu[ne + k] > 0 && (drop == work.size() || mu[ne + k] > mu[ne + drop])) drop = k;
    if (drop < work.size()) {
      work.erase(work.begin() + static_cast<long>(drop));
    } else {
      std::size_t add = ineq.size();
      Rational worst(0);
      for (std::size_t r = 0; r < ineq.size(); ++r) {
        if (std::find(work.begin(), work.end(), r) != work.end()) continue;
        const auto& row = exact_qp.rows[2 * ne + r];
        const Rational gap = row.b - sparse_dot(row.a, x);
        if (gap > worst) worst = gap, add = r;
      }
      if (add == ineq.size()) {
        optimal = true;
        break;
      }
      work.push_back(add);
    }
    if (o.progress && steps % 10 == 9)
      std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": active set step " << steps + 1 << ", " << work.size() << " tangent rows active\n";
    std::vector<Rational> x2, mu2;
    if (!solve_kkt(work, x2, mu2)) break;  // dependent rows: leave it to CGAL
    x = std::move(x2), mu = std::move(mu2);
  }
  QPSolution sol;
  if (optimal) {
    R.solver = (work.empty() ? "KKT system of the equality-constrained program, " : "active set (" + std::to_string(steps) + " steps) on KKT systems, ") + kind;
    sol.status = QPStatus::optimal;
    sol.x = x;
    sol.y.assign(qp.rows.size(), Rational(0));
    // 2 D x + c = -A^T mu = sum_r y_r s_r a_r: an equality's >= row takes -mu, its <= row +mu;
    // a working inequality (a >= row) takes -mu
    for (std::size_t r = 0; r < ne; ++r) {
      if (mu[r] < 0) sol.y[2 * r] = -mu[r];
      else sol.y[2 * r + 1] = mu[r];
    }
    for (std::size_t k = 0; k < work.size(); ++k) sol.y[2 * ne + work[k]] = -mu[ne + k];
  } else {
    if (o.progress) std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": the active set did not finish; CGAL's QP solver on the whole program\n";
    sol = solve_qp(qp);
    R.solver = std::string("CGAL's QP solver ") + (std::is_same_v<T, Rational> ? "(exact, Gmpz)" : "on doubles (Gmpzf)") +
               " after the active set did not finish";
    if (sol.status != QPStatus::optimal)
      throw DomainError("tangent-delta", "the patch program is " + to_string(sol.status) + ": no patch with t . dp/dm >= tangent_delta at every boundary sample",
                        "lower --tangent-delta or raise --patch-inner-knots");
    x = sol.x;
  }
  const auto kkt = check_kkt(exact_qp, sol);
  R.kkt_holds = kkt.holds;
  R.kkt_failed = kkt.failed;
  R.active_inequalities = 0;
  for (std::size_t r = 0; r < ineq.size(); ++r)
    if (sparse_dot(exact_qp.rows[2 * ne + r].a, x) == exact_qp.rows[2 * ne + r].b) ++R.active_inequalities;
  R.coefficients = x;
  R.program = exact_qp;
  std::vector<Rational> pts(3 * N);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < N; ++i) pts[3 * i + c] = x[c * N + i];
  R.patch = make_spline<Rational>({3, 3}, {Uq, Uq}, 3, pts);
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

template CuttingSurface<Rational> cutting_surface(const std::vector<LoopSide3>&, const SurfaceFacetOptions&);
template CuttingSurface<double> cutting_surface(const std::vector<LoopSide3>&, const SurfaceFacetOptions&);

// ---- the guided refinement (Eq. 6), double ------------------------------------------------------------

void validate_guided_options(const GuidedOptions& go) {
  if (!(go.weight_guide >= 0) || !std::isfinite(go.weight_guide)) throw UsageError("weight-guide", "must be a finite number >= 0", "give e.g. 10");
  if (go.grid < 2 || go.grid > 200) throw UsageError("guide-grid", "must be in 2..200", "give e.g. 16");
  if (go.iterations < 0 || go.iterations > 1000) throw UsageError("guide-iterations", "must be in 0..1000", "give e.g. 30");
}

GuidedResult refine_with_guide(const CuttingSurface<Rational>& init, const BSpline<double>& f, const GuidedOptions& go) {
  validate_guided_options(go);
  const auto t0 = std::chrono::steady_clock::now();
  const auto& qp = init.program;
  const std::size_t nv = qp.n;
  const std::size_t N = nv / 3;
  const auto& U = init.patch.knots[0];
  std::vector<double> Ud;
  for (const auto& k : U) Ud.push_back(to_double(k));
  const std::size_t n = U.size() - 4;
  Eigen::MatrixXd D(nv, nv);
  Eigen::VectorXd c(nv), x(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    c(i) = to_double(qp.c[i]);
    x(i) = to_double(init.coefficients[i]);
    for (std::size_t j = 0; j < nv; ++j) D(i, j) = to_double(qp.d(i, j));
  }
  const double c0 = to_double(qp.c0);
  // the equalities (every other row of the first 2 * equalities) and the active tangent rows
  std::vector<const QuadraticProgram<Rational>::Row*> held;
  for (std::size_t r = 0; r < init.equalities; ++r) held.push_back(&qp.rows[2 * r]);
  for (std::size_t r = 2 * init.equalities; r < qp.rows.size(); ++r) {
    Rational s(0);
    for (const auto& [i, v] : qp.rows[r].a) s += v * init.coefficients[i];
    if (s == qp.rows[r].b) held.push_back(&qp.rows[r]);
  }
  const std::size_t m = held.size();
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(m, nv);
  Eigen::VectorXd e(m);
  for (std::size_t r = 0; r < m; ++r) {
    for (const auto& [i, v] : held[r]->a) E(r, i) = to_double(v);
    e(r) = to_double(held[r]->b);
  }
  // the samples of Eq. 6 and their weights
  const auto poly = cg_polygon(init.domain.vertices);
  std::vector<std::array<double, 2>> W;
  for (const auto& w : init.domain.vertices) W.push_back({to_double(w[0]), to_double(w[1])});
  double lo[2] = {W[0][0], W[0][1]}, hi[2] = {W[0][0], W[0][1]};
  for (const auto& w : W)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], w[k]), hi[k] = std::max(hi[k], w[k]);
  struct Sample {
    std::vector<std::pair<std::size_t, double>> phi;
    double omega;
  };
  std::vector<Sample> samples;
  double dmax = 0;
  for (int j = 0; j < go.grid; ++j)
    for (int i = 0; i < go.grid; ++i) {
      const double u = lo[0] + (hi[0] - lo[0]) * (i + 0.5) / go.grid, v = lo[1] + (hi[1] - lo[1]) * (j + 0.5) / go.grid;
      if (!in_polygon({exact_from_double(u), exact_from_double(v)}, poly)) continue;
      double dist = 1e300;
      for (std::size_t k = 0; k < W.size(); ++k) {
        const auto &a = W[k], &b = W[(k + 1) % W.size()];
        const double ex = b[0] - a[0], ey = b[1] - a[1], L2 = ex * ex + ey * ey;
        const double t = std::clamp(((u - a[0]) * ex + (v - a[1]) * ey) / L2, 0.0, 1.0);
        dist = std::min(dist, std::hypot(u - a[0] - t * ex, v - a[1] - t * ey));
      }
      const auto row = basis_row(Ud, n, Ud, n, u, v);
      samples.push_back({row.v, dist});
      dmax = std::max(dmax, dist);
    }
  for (auto& s : samples) s.omega = dmax > 0 ? s.omega / dmax : 0;
  const double wk = samples.empty() ? 0 : go.weight_guide / samples.size();
  auto point = [&](const Sample& s, const Eigen::VectorXd& X) {
    std::vector<double> p(3, 0.0);
    for (const auto& [i, v] : s.phi)
      for (int k = 0; k < 3; ++k) p[k] += v * X(k * N + i);
    for (auto& t : p) t = std::clamp(t, 0.0, 1.0);
    return p;
  };
  auto objective = [&](const Eigen::VectorXd& X, double* fmax) {
    double val = X.dot(D * X) + c.dot(X) + c0;
    if (fmax) *fmax = 0;
    for (const auto& s : samples) {
      const double fv = evaluate(f, point(s, X))[0];
      val += wk * s.omega * fv * fv;
      if (fmax) *fmax = std::max(*fmax, std::abs(fv));
    }
    return val;
  };
  GuidedResult R;
  R.samples = samples.size();
  double fe = objective(x, &R.max_abs_f_before);
  R.objective_before = fe;
  for (int it = 0; it < go.iterations; ++it) {
    // Gauss-Newton: H = 2 D + 2 J^T J, g = 2 D x + c + 2 J^T r
    Eigen::MatrixXd H = 2 * D;
    Eigen::VectorXd g = 2 * D * x + c;
    for (const auto& s : samples) {
      const double w = wk * s.omega;
      if (w == 0) continue;
      const auto p = point(s, x);
      const double fv = evaluate(f, p)[0];
      double grad[3];
      for (int k = 0; k < 3; ++k) {
        std::vector<int> ord(3, 0);
        ord[k] = 1;
        grad[k] = derivative(f, p, ord)[0];
      }
      Eigen::VectorXd Jrow = Eigen::VectorXd::Zero(nv);
      for (const auto& [i, v] : s.phi)
        for (int k = 0; k < 3; ++k) Jrow(k * N + i) = grad[k] * v;
      H += 2 * w * Jrow * Jrow.transpose();
      g += 2 * w * fv * Jrow;
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + m, nv + m);
    K.topLeftCorner(nv, nv) = H;
    K.topRightCorner(nv, m) = E.transpose();
    K.bottomLeftCorner(m, nv) = E;
    Eigen::VectorXd rhs(nv + m);
    rhs.head(nv) = -g;
    rhs.tail(m) = e - E * x;
    const Eigen::VectorXd step = Eigen::FullPivLU<Eigen::MatrixXd>(K).solve(rhs).head(nv);
    if (!step.allFinite()) break;
    double a = 1;
    bool better = false;
    for (int h = 0; h < 30; ++h, a /= 2) {
      const Eigen::VectorXd xn = x + a * step;
      const double fn = objective(xn, nullptr);
      if (fn < fe) {
        x = xn, better = fn < fe * (1 - 1e-12), fe = fn;
        break;
      }
    }
    R.iterations = it + 1;
    if (!better) break;
  }
  R.objective_after = objective(x, &R.max_abs_f_after);
  // The doubles interpolate the vertices only within rounding: projected exactly onto the vertex
  // equalities (the least change in the Euclidean norm: x - E^T (E E^T)^-1 (E x - e), exactly).
  std::vector<Rational> xq(nv);
  for (std::size_t i = 0; i < nv; ++i) xq[i] = exact_from_double(x(i));
  const std::size_t me = init.equalities;
  std::vector<Rational> G(me * me, Rational(0)), res(me, Rational(0));
  for (std::size_t r = 0; r < me; ++r) {
    const auto& a = qp.rows[2 * r].a;
    res[r] = -qp.rows[2 * r].b;
    for (const auto& [i, v] : a) res[r] += v * xq[i];
    for (std::size_t t = 0; t < me; ++t) {
      const auto& b = qp.rows[2 * t].a;
      for (const auto& [i, v] : a)
        for (const auto& [j, w] : b)
          if (i == j) G[r * me + t] += v * w;
    }
  }
  const auto lam = solve_linear_exact(G, me, res, 1);
  if (!lam) throw DomainError("patch-inner-knots", "the vertex equalities are dependent", "raise --patch-inner-knots");
  for (std::size_t r = 0; r < me; ++r)
    for (const auto& [i, v] : qp.rows[2 * r].a) xq[i] -= v * (*lam)[r];
  std::vector<Rational> pts(3 * N);
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t i = 0; i < N; ++i) pts[3 * i + k] = xq[k * N + i];
  R.patch = make_spline<Rational>({3, 3}, {init.patch.knots[0], init.patch.knots[1]}, 3, pts);
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

// ---- certificates --------------------------------------------------------------------------------

/// A parameter interval [lo, hi] of a loop side with a polynomial on it in Bernstein form, and its
/// halving (the tangent check of certify_cutting_surface).
namespace {
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
}  // namespace

SurfaceValidity certify_cutting_surface(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const DomainPolygon& domain,
                                        const BSpline<Rational>& patch, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto t0 = std::chrono::steady_clock::now();
  SurfaceValidity V;
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
  const auto pieces = extract_bezier(patch);
  std::vector<Rational> knots_all;
  for (int d = 0; d < 2; ++d)
    for (const auto& k : patch.knots[d]) knots_all.push_back(k);
  bool undecided = false;

  auto progress = [&](const std::string& what) {
    if (o.progress)
      std::cerr << "[cut facet] " << what << " (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s)\n";
  };
  progress("certificate: vertices, boundary and tangents");
  // vertices
  V.vertices_exact = true;
  for (std::size_t j = 0; j < ns; ++j) {
    const Rational e = max_abs3(sub(eval3(patch, W[j]), loop[j].start));
    if (e > 0) V.vertices_exact = false;
    V.vertex_error = std::max(V.vertex_error, e);
  }

  // boundary deviation and tangents, edge by edge, piece by piece
  V.tangents = "certified";
  for (std::size_t j = 0; j < ns && !V.witness; ++j) {
    const P2 &W0 = W[j], &W1 = W[(j + 1) % ns];
    const P2 e{W1[0] - W0[0], W1[1] - W0[1]};
    const Rational em = std::max(rabs(e[0]), rabs(e[1]));
    const P2 inward{-e[1] / em, e[0] / em};
    const auto& L = loop[j];
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
        V.tangents = "violated";
        V.witness = SurfaceValidity::Witness{"tangent", w, eval3(patch, w), mid,
                                             "t . (dp/dm) <= 0 on loop side " + std::to_string(j) + ": the prescribed tangent does not point into the patch"};
        return Examined::refuted;
      };
      Budget depth_only;
      depth_only.max_depth = o.max_depth;
      const Subdivision run = subdivide(std::vector<Arc>{Arc{g, Rational(0), Rational(1)}}, Walk{}, depth_only, positive, HalveArc{}, [](Arc&&, Left) {});
      if (run.stop != Subdivision::Stop::refuted && run.left > 0) V.tangents = "undecided";
    }
  }
  if (V.tangents == "undecided") undecided = true;

  progress("certificate: regularity and injectivity");
  // regularity and injectivity: the projection's Jacobian
  P2 blo = W[0], bhi = W[0];
  for (const auto& w : W)
    for (int k = 0; k < 2; ++k) blo[k] = std::min(blo[k], w[k]), bhi[k] = std::max(bhi[k], w[k]);
  const int a0 = domain.axes[0], a1 = domain.axes[1];
  const auto M = projection_alignment(loop, domain);
  struct Cell {
    Bernstein<Rational> A, Q, det;
    P2 lo, hi;
  };
  std::vector<Cell> cells;
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
    Cell cl;
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
  auto certify_cells = [&](bool monotone) {
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
  };
  const bool aligned = !(M[0] == 1 && M[1] == 0 && M[2] == 0 && M[3] == 1);
  GridCertificate G;
  const std::string axes = aligned ? "M (" + std::string("xyz").substr(a0, 1) + std::string("xyz").substr(a1, 1) + "), M = [[" + M[0].str() + ", " + M[1].str() +
                                         "], [" + M[2].str() + ", " + M[3].str() + "]] the loop's projection fitted to Omega"
                                   : std::string("xyz").substr(a0, 1) + std::string("xyz").substr(a1, 1);
  if (certify_cells(true)) {
    V.regular = V.injective = "proved";
    V.regularity_method = "P = (" + axes + ") of p has DP + DP^T positive definite on the bounding box of Omega (Bernstein signs): P is a monotone map "
                          "on a convex set, so injective, and p's normal has a non-zero " + std::string("xyz").substr(3 - a0 - a1, 1) + " component";
  } else if (progress("certificate: regularity and injectivity on a grid of windows"),
             G = grid_injectivity(pieces, poly, std::min(o.max_depth / 2, 4), std::min<std::size_t>(o.max_pieces, 65536)), G.proved) {
    V.regular = V.injective = "proved";
    V.regularity_method = "no single projection is monotone (" + axes + "); on a grid of " + std::to_string(G.cells) + " cells meeting Omega (level " +
                          std::to_string(G.level) + "), every window of 3 x 3 cells is mapped injectively with a regular Jacobian (A p monotone, A the "
                          "left inverse of Dp at the window's centre, Bernstein signs), and cells 3 or more apart have disjoint boxes";
  } else if (certify_cells(false)) {
    V.regular = "proved";
    V.injective = "undecided";
    V.regularity_method = "det DP > 0 on Omega for P = (" + axes + ") of p (Bernstein signs); the monotone criterion for injectivity does not hold, "
                          "nor the grid of windows (" + G.why + ")";
    undecided = true;
  } else {
    V.regular = V.injective = "undecided";
    V.regularity_method = "neither DP + DP^T positive definite nor det DP > 0 could be certified for P = (" + axes + ") of p, nor the grid of windows (" +
                          G.why + ")";
    undecided = true;
  }

  progress("certificate: collision");
  // collision
  std::string why;
  const auto triangles = cut_detail::membership_model(solid, why);
  const bool membership = triangles.has_value();
  V.membership = !membership ? "not available: " + why
                 : triangles->bilinears.empty()
                     ? "exact ray parity (planar convex quadrilateral facets)"
                     : "exact ray parity (bilinear quadrilateral facets: planar convex ones as two triangles, the others by the exact quadratic-irrational "
                       "roots of their ray equations)";
  struct FacetBox {
    std::size_t facet;
    std::array<Rational, 6> box;
  };
  std::vector<FacetBox> fboxes;
  for (std::size_t i = 0; i < solid.facets.size(); ++i)
    for (const auto& bz : extract_bezier(solid.facets[i])) fboxes.push_back({i, control_bounds(bz.spline)});
  bool collided = false, col_undecided = false;
  if (!V.witness) {
    std::deque<std::pair<BSpline<Rational>, int>> q;
    for (const auto& pc : pieces) q.emplace_back(pc.spline, 0);
    std::size_t examined = 0;
    while (!q.empty()) {
      auto [pc, depth] = q.front();
      q.pop_front();
      const P2 lo{pc.domain_lo(0), pc.domain_lo(1)}, hi{pc.domain_hi(0), pc.domain_hi(1)};
      if (!box_meets_polygon(lo, hi, poly)) continue;
      if (++examined > o.max_pieces) {
        ++V.collision_undecided;
        col_undecided = true;
        continue;
      }
      const auto box = control_bounds(pc);
      if (box_in_loop_strip(loop, {box[0], box[1], box[2]}, {box[3], box[4], box[5]}, o.strip)) {
        ++V.collision_excluded;
        continue;
      }
      bool meets = false;
      for (const auto& fb : fboxes)
        if (box[0] <= fb.box[3] && fb.box[0] <= box[3] && box[1] <= fb.box[4] && fb.box[1] <= box[4] && box[2] <= fb.box[5] && fb.box[2] <= box[5]) {
          meets = true;
          break;
        }
      if (!meets) {
        ++V.collision_pieces;
        continue;
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
              break;
            }
          }
        }
      }
      if (depth >= o.max_depth) {
        ++V.collision_undecided;
        col_undecided = true;
        continue;
      }
      const int d = (hi[0] - lo[0] >= hi[1] - lo[1]) ? 0 : 1;
      auto [l, r] = split_at(pc, d, Rational((lo[d] + hi[d]) / 2));
      q.emplace_back(std::move(l), depth + 1);
      q.emplace_back(std::move(r), depth + 1);
    }
  }
  V.collision = collided ? "violated" : col_undecided ? "undecided" : V.witness ? "not examined (another condition failed)" : "none outside the strip (certified)";
  if (col_undecided) undecided = true;
  if (V.witness) V.verdict = "invalid";
  else if (undecided || !V.vertices_exact) V.verdict = "undecided";
  else V.verdict = "valid";
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

std::vector<GuidedStep> refine_with_guide_sweep(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const CuttingSurface<Rational>& initial,
                                                const BSpline<double>& f, const GuidedOptions& base, const std::vector<double>& weights,
                                                const SurfaceFacetOptions& o) {
  if (weights.empty()) throw UsageError("weight-guide", "the sweep has no weights", "give at least one weight");
  std::vector<GuidedStep> steps;
  for (const double w : weights) {
    GuidedOptions go = base;
    go.weight_guide = w;
    validate_guided_options(go);
    if (o.progress) std::cerr << "[cut facet] the guided refinement at weight " << w << "\n";
    GuidedStep st;
    st.weight = w;
    st.result = refine_with_guide(initial, f, go);
    st.validity = certify_cutting_surface(solid, loop, initial.domain, st.result.patch, o);
    const bool valid = st.validity.verdict == "valid";
    steps.push_back(std::move(st));
    if (valid) break;
  }
  return steps;
}

}  // namespace splinex
