// The cutting surface, Step 1 (papers/004 Section 4): the domain polygon Omega by projection, by
// Eq. 5 or on the circle, the loop's Newell normal and the projection axes (cut/surface_facet.hpp).
#include <CGAL/Polygon_2_algorithms.h>
#include <mpfr.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "cut/surface_facet.hpp"
#include "cut/surface_facet_impl.hpp"

namespace splinex {

namespace surface_detail {

// Both overloads of round_to_grid live here, so that either is found wherever the other is; this
// one is local to the file.
// x rounded to the nearest multiple of 2^-bits, exactly (MPFR at the precision x needs: no double).
static Rational round_to_grid(const mpfr_t x, unsigned bits) {
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

// Declared in surface_facet_impl.hpp.
Rational round_to_grid(const Rational& q, unsigned bits) {
  mpfr_t x;
  mpfr_init2(x, 256);
  mpfr_set_q(x, q.backend().data(), MPFR_RNDN);
  const Rational r = round_to_grid(x, bits);
  mpfr_clear(x);
  return r;
}

}  // namespace surface_detail

using namespace surface_detail;

namespace {

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

}  // namespace splinex
