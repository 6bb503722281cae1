#include "vrep/boolean/ssi.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "base/errors.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/hodograph.hpp"

namespace splinex {

namespace {

using V3 = Eigen::Vector3d;

void require_surface(const BSpline<double>& S, const std::string& name) {
  validate(S);
  if (S.dim() != 2 || S.q < 3) throw ValidationError(name, "is not a surface in R^3", "give a spline surface S(u, v) with points x,y,z");
}

/// A surface's value and first partial derivatives at (u, v), in double.
struct Jet {
  V3 p, du, dv;
};
Jet jet(const BSpline<double>& S, double u, double v) {
  const std::vector<double> x{u, v};
  const auto p = evaluate(S, x), a = derivative(S, x, {1, 0}), b = derivative(S, x, {0, 1});
  return {V3(p[0], p[1], p[2]), V3(a[0], a[1], a[2]), V3(b[0], b[1], b[2])};
}

struct Domain {
  double lo[4], hi[4];
  bool inside(const SsiParams& x) const {
    for (int i = 0; i < 4; ++i)
      if (!(lo[i] <= x[i] && x[i] <= hi[i])) return false;
    return true;
  }
  void clamp(SsiParams& x) const {
    for (int i = 0; i < 4; ++i) x[i] = std::min(hi[i], std::max(lo[i], x[i]));
  }
};

class Tracer {
 public:
  Tracer(const BSpline<double>& S1, const BSpline<double>& S2, const SsiOptions& o) : S1_(S1), S2_(S2), o_(o) {
    for (int d = 0; d < 2; ++d) {
      dom_.lo[d] = S1.domain_lo(d);
      dom_.hi[d] = S1.domain_hi(d);
      dom_.lo[d + 2] = S2.domain_lo(d);
      dom_.hi[d + 2] = S2.domain_hi(d);
    }
  }

  /// Newton on S1 - S2 = 0 with the minimum-norm step (3 equations, 4 unknowns), kept in the domain.
  bool settle(SsiParams& x) const {
    double first = -1;
    for (int it = 0; it < 30; ++it) {
      const Jet a = jet(S1_, x[0], x[1]), b = jet(S2_, x[2], x[3]);
      const V3 F = a.p - b.p;
      if (F.norm() <= o_.tolerance) return true;
      // Newton that has not halved the residual in 8 steps is not converging to a simple zero.
      if (it == 0) first = F.norm();
      if (it == 8 && !(F.norm() < first / 2)) return false;
      Eigen::Matrix<double, 3, 4> J;
      J << a.du, a.dv, -b.du, -b.dv;
      const Eigen::Vector4d d = J.completeOrthogonalDecomposition().solve(-F);
      if (!d.allFinite()) return false;
      for (int i = 0; i < 4; ++i) x[i] += d[i];
      dom_.clamp(x);
    }
    const V3 F = jet(S1_, x[0], x[1]).p - jet(S2_, x[2], x[3]).p;
    return F.norm() <= o_.tolerance;
  }

  /// The unit tangent n1 x n2 at x (zero when the normals are parallel).
  V3 tangent(const SsiParams& x) const {
    const Jet a = jet(S1_, x[0], x[1]), b = jet(S2_, x[2], x[3]);
    const V3 n1 = a.du.cross(a.dv), n2 = b.du.cross(b.dv);
    const V3 t = n1.cross(n2);
    if (!(t.norm() > 1e-10 * n1.norm() * n2.norm())) return V3::Zero();
    return t.normalized();
  }

  /// One marching step of chord h along T from x: predictor in both parameter planes, corrector on
  /// (S1 - S2, T.(S1 - S1(x)) - h).
  bool step(const SsiParams& x, const V3& T, double h, SsiParams& out) const {
    const Jet a = jet(S1_, x[0], x[1]), b = jet(S2_, x[2], x[3]);
    Eigen::Matrix<double, 3, 2> A, B;
    A << a.du, a.dv;
    B << b.du, b.dv;
    const Eigen::Vector2d da = A.colPivHouseholderQr().solve(h * T), db = B.colPivHouseholderQr().solve(h * T);
    out = {x[0] + da[0], x[1] + da[1], x[2] + db[0], x[3] + db[1]};
    double reach = 0;  // the predictor's largest parameter move
    for (int i = 0; i < 4; ++i) reach = std::max(reach, std::abs(out[i] - x[i]));
    const V3 c = a.p;
    for (int it = 0; it < 30; ++it) {
      // Outside the domain the spline is not evaluated: the caller puts the point on the boundary
      // (a corrector that wandered far from the predictor has diverged instead: a failed step).
      SsiParams y = out;
      dom_.clamp(y);
      if (y != out) {
        double moved = 0;
        for (int i = 0; i < 4; ++i) moved = std::max(moved, std::abs(out[i] - x[i]));
        return it == 0 || moved <= 4 * reach;
      }
      const Jet p = jet(S1_, out[0], out[1]), q = jet(S2_, out[2], out[3]);
      Eigen::Vector4d G;
      G << p.p - q.p, T.dot(p.p - c) - h;
      if ((p.p - q.p).norm() <= o_.tolerance && std::abs(G[3]) <= 1e-6 * h) return true;
      Eigen::Matrix4d J;
      J.block<3, 1>(0, 0) = p.du;
      J.block<3, 1>(0, 1) = p.dv;
      J.block<3, 1>(0, 2) = -q.du;
      J.block<3, 1>(0, 3) = -q.dv;
      J(3, 0) = T.dot(p.du);
      J(3, 1) = T.dot(p.dv);
      J(3, 2) = 0;
      J(3, 3) = 0;
      const Eigen::Vector4d d = J.fullPivLu().solve(-G);
      if (!d.allFinite()) return false;
      for (int i = 0; i < 4; ++i) out[i] += d[i];
    }
    return false;
  }

  /// From inside x towards outside y: the point where the segment leaves the domain, with that
  /// parameter on the boundary and the other three settled by Newton (3 x 3).
  bool to_boundary(const SsiParams& x, const SsiParams& y, SsiParams& out) const {
    double lambda = 1;
    int which = -1;
    double value = 0;
    for (int i = 0; i < 4; ++i) {
      for (double bound : {dom_.lo[i], dom_.hi[i]}) {
        const double d = y[i] - x[i];
        if (d == 0) continue;
        const double l = (bound - x[i]) / d;
        if (l >= 0 && l < lambda && ((bound == dom_.lo[i]) ? y[i] < bound : y[i] > bound)) {
          lambda = l;
          which = i;
          value = bound;
        }
      }
    }
    if (which < 0) return false;
    for (int i = 0; i < 4; ++i) out[i] = x[i] + lambda * (y[i] - x[i]);
    out[which] = value;
    for (int it = 0; it < 30; ++it) {
      dom_.clamp(out);
      out[which] = value;
      const Jet a = jet(S1_, out[0], out[1]), b = jet(S2_, out[2], out[3]);
      const V3 F = a.p - b.p;
      if (F.norm() <= o_.tolerance) return true;
      Eigen::Matrix<double, 3, 4> J4;
      J4 << a.du, a.dv, -b.du, -b.dv;
      Eigen::Matrix3d J;
      for (int c = 0, k = 0; c < 4; ++c)
        if (c != which) J.col(k++) = J4.col(c);
      const V3 d = J.fullPivLu().solve(-F);
      if (!d.allFinite()) return false;
      for (int c = 0, k = 0; c < 4; ++c)
        if (c != which) out[c] += d[k++];
    }
    return false;
  }

  V3 point(const SsiParams& x) const { return jet(S1_, x[0], x[1]).p; }

  /// Marches from the seed in one direction (sign) and appends the points (the seed excluded).
  void march(const SsiParams& seed, double sign, std::vector<SsiParams>& pts, bool& closed, bool& tangential, std::size_t& budget) const {
    SsiParams x = seed;
    V3 prev = sign * tangent(seed);
    const V3 start = point(seed);
    double travelled = 0;
    while (budget > 0) {
      V3 T = tangent(x);
      if (T.isZero()) {
        tangential = true;
        return;
      }
      if (T.dot(prev) < 0) T = -T;
      double h = o_.step;
      SsiParams y;
      bool ok = false;
      while (h >= o_.step / 64) {
        if (step(x, T, h, y)) {
          ok = true;
          break;
        }
        h /= 2;
      }
      if (!ok) return;
      if (!dom_.inside(y)) {
        SsiParams b;
        if (to_boundary(x, y, b)) {
          pts.push_back(b);
          --budget;
        }
        return;
      }
      const V3 p = point(y), q = point(x);
      travelled += (p - q).norm();
      // Closed when the step passes the start again (its chord within 0.6 of the chord length of
      // it) after more than three chords: small loops, a few steps round, close as well as large ones.
      if (travelled > 3 * h) {
        const V3 d = p - q;
        const double t = d.squaredNorm() > 0 ? std::clamp((start - q).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        if ((q + t * d - start).norm() < 0.6 * h) {
          closed = true;
          return;
        }
      }
      pts.push_back(y);
      --budget;
      prev = T;
      x = y;
    }
  }

 private:
  const BSpline<double>& S1_;
  const BSpline<double>& S2_;
  const SsiOptions& o_;
  Domain dom_;
};

struct Cell {
  double lo[3], hi[3];
  double u, v;  // centre parameters
};

std::vector<Cell> cells_of(const BSpline<double>& S, int n) {
  const double u0 = S.domain_lo(0), u1 = S.domain_hi(0), v0 = S.domain_lo(1), v1 = S.domain_hi(1);
  std::vector<V3> grid((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto p = evaluate(S, {u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n});
      grid[j * (n + 1) + i] = V3(p[0], p[1], p[2]);
    }
  std::vector<Cell> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Cell c;
      const V3* q[4] = {&grid[j * (n + 1) + i], &grid[j * (n + 1) + i + 1], &grid[(j + 1) * (n + 1) + i], &grid[(j + 1) * (n + 1) + i + 1]};
      double edge = 0;
      for (int a = 0; a < 3; ++a) {
        c.lo[a] = c.hi[a] = (*q[0])[a];
        for (auto* p : q) {
          c.lo[a] = std::min(c.lo[a], (*p)[a]);
          c.hi[a] = std::max(c.hi[a], (*p)[a]);
        }
        edge = std::max(edge, c.hi[a] - c.lo[a]);
      }
      // The cell bulges between its corners: a margin of half its largest extent.
      for (int a = 0; a < 3; ++a) {
        c.lo[a] -= edge / 2;
        c.hi[a] += edge / 2;
      }
      c.u = u0 + (u1 - u0) * (i + 0.5) / n;
      c.v = v0 + (v1 - v0) * (j + 0.5) / n;
      out.push_back(c);
    }
  return out;
}

}  // namespace

SsiResult intersect_surfaces(const BSpline<double>& S1, const BSpline<double>& S2, const SsiOptions& o) {
  require_surface(S1, "first");
  require_surface(S2, "second");
  if (!(o.step > 0) || !std::isfinite(o.step)) throw ValidationError("step", "must be positive and finite", "give a marching step > 0");
  if (!(o.tolerance > 0) || !std::isfinite(o.tolerance)) throw ValidationError("tolerance", "must be positive and finite", "give a Newton tolerance > 0");
  if (o.grid < 1 || o.grid > 128) throw ValidationError("grid", "must be 1..128 (the seed search compares grid^4 cell pairs)", "give a seed grid of 1..128 cells per direction");
  {
    // Limits before the work: a branch of the first surface's size takes about diag / step points.
    const auto b = control_bounds(S1);
    const double diag = std::hypot(b[3] - b[0], b[4] - b[1], b[5] - b[2]);
    if (!std::isfinite(diag)) throw ValidationError("first", "has control points too large for double arithmetic", "scale the model down");
    if (o.step * 1e5 < diag)
      throw ValidationError("step", "is below 10^-5 of the first surface's size (" + std::to_string(diag) + "): too many points per branch",
                            "give a larger marching step");
  }
  Tracer tr(S1, S2, o);
  SsiResult out;
  const auto c1 = cells_of(S1, o.grid), c2 = cells_of(S2, o.grid);
  std::size_t budget = o.max_points;
  // Every point of the branches so far, hashed on a grid of cell `step` (a start within 0.75 step
  // of one is on a traced branch: only the 27 cells about it are searched).
  std::unordered_map<std::uint64_t, std::vector<V3>> traced;
  auto key = [&](long i, long j, long k) {
    return (static_cast<std::uint64_t>(i) * 73856093u) ^ (static_cast<std::uint64_t>(j) * 19349663u) ^ (static_cast<std::uint64_t>(k) * 83492791u);
  };
  auto cell_of = [&](const V3& p, int a) {  // clamped before the conversion (far points share buckets)
    const double c = std::floor(p[a] / o.step);
    return std::isfinite(c) ? static_cast<long>(std::clamp(c, -1e15, 1e15)) : 0L;
  };
  auto add_traced = [&](const V3& p) { traced[key(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2))].push_back(p); };
  auto near_traced = [&](const V3& p) {
    const long i = cell_of(p, 0), j = cell_of(p, 1), k = cell_of(p, 2);
    for (long a = i - 1; a <= i + 1; ++a)
      for (long b = j - 1; b <= j + 1; ++b)
        for (long c = k - 1; c <= k + 1; ++c) {
          const auto it = traced.find(key(a, b, c));
          if (it == traced.end()) continue;
          for (const auto& q : it->second)
            if ((p - q).norm() < 0.75 * o.step) return true;
        }
    return false;
  };
  for (const auto& a : c1)
    for (const auto& b : c2) {
      bool meet = true;
      for (int k = 0; k < 3 && meet; ++k) meet = !(a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]);
      if (!meet) continue;
      ++out.candidates;
      if (out.seeds + out.newton_failures + out.known >= o.max_starts) {
        ++out.skipped;
        continue;
      }
      SsiParams x{a.u, a.v, b.u, b.v};
      if (!tr.settle(x)) {
        ++out.newton_failures;
        continue;
      }
      if (near_traced(tr.point(x))) {
        ++out.known;
        continue;
      }
      ++out.seeds;
      SsiBranch br;
      std::vector<SsiParams> fwd, bwd;
      bool closed = false, tangential = false;
      tr.march(x, 1, fwd, closed, tangential, budget);
      if (!closed) tr.march(x, -1, bwd, closed, tangential, budget);
      br.points.assign(bwd.rbegin(), bwd.rend());
      br.points.push_back(x);
      br.points.insert(br.points.end(), fwd.begin(), fwd.end());
      br.closed = closed;
      br.tangential_stop = tangential;
      br.ends_meet = !closed && br.points.size() >= 3 && (tr.point(br.points.front()) - tr.point(br.points.back())).norm() <= o.step / 4;
      for (const auto& y : br.points) add_traced(tr.point(y));
      // Points between the stored ones count as traced too (the chord's midpoints).
      for (std::size_t i = 0; i + 1 < br.points.size(); ++i) add_traced((tr.point(br.points[i]) + tr.point(br.points[i + 1])) / 2);
      out.branches.push_back(std::move(br));
      if (budget == 0) return out;
    }
  return out;
}

namespace {

Rational rabs(const Rational& x) { return x < 0 ? Rational(-x) : x; }

/// judge_point's steps on what they share: the surfaces, the point x~ and the domains, F(x~), the
/// square system's unknowns and direction, and Y = F'(x~)^-1 taken exactly.
class PointJudge {
 public:
  PointJudge(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const Limits& limits) : S1_(S1), S2_(S2), limits_(limits) {}

  /// The gap, then Krawczyk's test at radii from 4 |Y F| up (see judge_point).
  SsiJudgement judge(const SsiParams& xd, const SsiParams& dir) {
    measure_gap(xd);
    if (!derivatives_ranged() || !choose_system(dir) || !invert_derivative()) return out_;
    // Radii from 4 |Y F| up, by factors of 4.
    if (!std::isfinite(yf_max_) || yf_max_ > 1) {
      out_.why_not = "the point is too far from the intersection (|F'(x)^-1 F(x)| > 1/16)";
      return out_;
    }
    int e = -44;
    if (yf_max_ > 0) e = std::max(e, static_cast<int>(std::ceil(std::log2(4 * yf_max_))));
    if (e > -2) out_.why_not = "the point is too far from the intersection (|F'(x)^-1 F(x)| > 1/16)";
    for (int attempt = 0; attempt < 4; ++attempt, e += 2) {
      if (e > -2) break;
      const Rational r = exact_from_double(std::ldexp(1.0, e), "radius");
      std::array<Rational, 4> lo, hi;
      if (!box_inside(r, lo, hi)) {
        out_.why_not = "the box of radius 2^" + std::to_string(e) + " leaves a domain (a point near the boundary)";
        break;
      }
      const auto R1 = restrict_to_box(S1_, &lo[0], &hi[0], limits_), R2 = restrict_to_box(S2_, &lo[2], &hi[2], limits_);
      Rational rho[4];  // K(X) about x~: the root lies within |YF_i| + r sum_i of x~ in unknown i
      if (!krawczyk(r, R1, R2, rho)) {
        out_.why_not = "Krawczyk's test fails up to radius 2^" + std::to_string(e);
        continue;
      }
      out_.certified = true;
      out_.radius = r;
      out_.why_not.clear();
      out_.distance2_bound = distance_bound(R1, lo, hi, rho);
      return out_;
    }
    return out_;
  }

 private:
  // The point exactly, inside both domains, and its gap |S1 - S2|^2 (F(x~)).
  void measure_gap(const SsiParams& xd) {
    for (int i = 0; i < 4; ++i) x_[i] = exact_from_double(xd[i], "point");
    for (int d = 0; d < 2; ++d) {
      dlo_[d] = S1_.domain_lo(d);
      dhi_[d] = S1_.domain_hi(d);
      dlo_[d + 2] = S2_.domain_lo(d);
      dhi_[d + 2] = S2_.domain_hi(d);
    }
    for (int i = 0; i < 4; ++i)
      if (x_[i] < dlo_[i] || dhi_[i] < x_[i])
        throw ValidationError("point", "lies outside the surfaces' domains", "give parameters inside both domains");
    p1_ = evaluate(S1_, {x_[0], x_[1]});
    const auto p2 = evaluate(S2_, {x_[2], x_[3]});
    for (int c = 0; c < 3; ++c) {
      F_[c] = p1_[c] - p2[c];
      out_.gap2 += F_[c] * F_[c];
    }
    F_[3] = 0;
  }

  // The derivative ranges are built for polynomial surfaces with a tangent plane.
  bool derivatives_ranged() {
    if (S1_.is_rational() || S2_.is_rational()) {
      out_.why_not = "rational surfaces: the derivative ranges are not built";
      return false;
    }
    for (int d = 0; d < 2; ++d)
      if (S1_.degrees[d] == 0 || S2_.degrees[d] == 0) {
        out_.why_not = "a surface of degree 0 in a direction has no tangent plane";
        return false;
      }
    return true;
  }

  // A point on a domain boundary (where a branch ends): that parameter is fixed there and the
  // three equations S1 - S2 = 0 are solved for the other three; inside, the fourth equation
  // a.(x - x~) = 0 fixes the point along the curve.
  bool choose_system(const SsiParams& dir) {
    for (int i = 0; i < 4 && fixed_ < 0; ++i)
      if (x_[i] == dlo_[i] || x_[i] == dhi_[i]) fixed_ = i;
    for (int i = 0; i < 4; ++i)
      if (i != fixed_) vars_.push_back(i);
    n_ = static_cast<int>(vars_.size());  // unknowns and equations
    if (fixed_ < 0) {
      double an = 0;
      for (int i = 0; i < 4; ++i) an = std::max(an, std::abs(dir[i]));
      if (!(an > 0) || !std::isfinite(an)) {
        out_.why_not = "no direction along the curve";
        return false;
      }
      for (int i = 0; i < 4; ++i) a_[i] = dir[i] / an;
    }
    return true;
  }

  // F'(x~) in double (the columns of the unknowns) and its inverse Y, taken exactly.
  bool invert_derivative() {
    Eigen::Matrix4d J4;
    {
      const std::vector<Rational> u1{x_[0], x_[1]}, u2{x_[2], x_[3]};
      const auto d1u = derivative(S1_, u1, {1, 0}), d1v = derivative(S1_, u1, {0, 1}), d2s = derivative(S2_, u2, {1, 0}),
                 d2t = derivative(S2_, u2, {0, 1});
      for (int c = 0; c < 3; ++c) {
        J4(c, 0) = to_double(d1u[c]);
        J4(c, 1) = to_double(d1v[c]);
        J4(c, 2) = -to_double(d2s[c]);
        J4(c, 3) = -to_double(d2t[c]);
      }
      for (int j = 0; j < 4; ++j) J4(3, j) = a_[j];
    }
    Eigen::MatrixXd Jd(n_, n_);
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) Jd(i, j) = J4(i, vars_[j]);
    if (!Jd.allFinite()) {
      out_.why_not = "F' is beyond double's range at the point";
      return false;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Jd);
    if (!lu.isInvertible()) {
      out_.why_not = "F' is singular at the point (tangential intersection?)";
      return false;
    }
    const Eigen::MatrixXd Yd = lu.inverse();
    if (!Yd.allFinite()) {
      out_.why_not = "F' is beyond double's range at the point";
      return false;
    }
    Y_.assign(n_, std::vector<Rational>(n_));
    for (int i = 0; i < 4; ++i) A_[i] = exact_from_double(a_[i], "direction");
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) Y_[i][j] = exact_from_double(Yd(i, j), "Y");
    YF_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      for (int k = 0; k < n_; ++k) YF_[i] += Y_[i][k] * F_[k];
      yf_max_ = std::max(yf_max_, std::abs(to_double(YF_[i])));
    }
    return true;
  }

  // The box: x~ +- r in the unknowns; the fixed parameter's side of width r inside the domain
  // (a superset of the line it is fixed on: the ranges stay valid).
  bool box_inside(const Rational& r, std::array<Rational, 4>& lo, std::array<Rational, 4>& hi) const {
    bool in = true;
    for (int i = 0; i < 4; ++i) {
      if (i == fixed_) {
        lo[i] = x_[i] == dlo_[i] ? x_[i] : Rational(x_[i] - r);
        hi[i] = x_[i] == dlo_[i] ? Rational(x_[i] + r) : x_[i];
      } else {
        lo[i] = x_[i] - r;
        hi[i] = x_[i] + r;
      }
      in = in && !(lo[i] < dlo_[i]) && !(dhi_[i] < hi[i]);
    }
    return in;
  }

  // Krawczyk's test on the box x~ +- r (R1, R2: the surfaces restricted to it): K(X) inside the box,
  // with rho its reach from x~ in each unknown.
  bool krawczyk(const Rational& r, const BSpline<Rational>& R1, const BSpline<Rational>& R2, Rational rho[4]) const {
    // Interval Jacobian over the box: rows 0-2 the hodographs' coefficient ranges, row 3 the direction.
    Rational Jlo[4][4], Jhi[4][4];
    {
      const BSpline<Rational> H[4] = {hodograph(R1, 0), hodograph(R1, 1), hodograph(R2, 0), hodograph(R2, 1)};
      for (int j = 0; j < 4; ++j) {
        const auto b = control_bounds(H[j]);
        for (int c = 0; c < 3; ++c) {
          Jlo[c][j] = j < 2 ? b[c] : Rational(-b[c + 3]);
          Jhi[c][j] = j < 2 ? b[c + 3] : Rational(-b[c]);
        }
      }
      for (int j = 0; j < 4; ++j) Jlo[3][j] = Jhi[3][j] = A_[j];
    }
    bool ok = true;
    for (int i = 0; i < n_ && ok; ++i) {
      Rational sum(0);
      for (int j = 0; j < n_; ++j) {
        Rational slo(0), shi(0);  // the range of sum_k Y_ik J_k,vars[j]
        for (int k = 0; k < n_; ++k) {
          const Rational p = Y_[i][k] * Jlo[k][vars_[j]], q = Y_[i][k] * Jhi[k][vars_[j]];
          slo += std::min(p, q);
          shi += std::max(p, q);
        }
        const Rational delta(i == j ? 1 : 0);
        sum += std::max(rabs(delta - slo), rabs(delta - shi));
      }
      // K_i lies in x~_i - YF_i + [-r sum, r sum]; inside (x~_i - r, x~_i + r) when |YF_i| + r sum < r.
      rho[vars_[i]] = rabs(YF_[i]) + r * sum;
      ok = rho[vars_[i]] < r;
    }
    return ok;
  }

  // The true point S1(u*, v*): (u*, v*) in K(X) (the fixed parameter at its value); the hull of
  // S1 on that smaller box bounds its distance from S1(u~, v~).
  Rational distance_bound(const BSpline<Rational>& R1, const std::array<Rational, 4>& lo, const std::array<Rational, 4>& hi,
                          const Rational rho[4]) const {
    Rational klo[2], khi[2];
    bool point_box = false;
    for (int d = 0; d < 2; ++d) {
      if (d == fixed_) {
        klo[d] = lo[d];
        khi[d] = hi[d];
      } else {
        klo[d] = x_[d] - rho[d];
        khi[d] = x_[d] + rho[d];
        point_box = point_box || rho[d] == 0;
      }
    }
    const BSpline<Rational> RK = point_box ? R1 : restrict_to_box(R1, klo, khi, limits_);
    const auto box = control_bounds(RK);
    Rational bound(0);
    for (int c = 0; c < 3; ++c) {
      const Rational m = std::max(rabs(box[c] - p1_[c]), rabs(box[c + 3] - p1_[c]));
      bound += m * m;
    }
    return bound;
  }

  const BSpline<Rational>& S1_;
  const BSpline<Rational>& S2_;
  const Limits& limits_;
  SsiJudgement out_;
  std::array<Rational, 4> x_, dlo_, dhi_;  // the point and the domains of (u, v, s, t)
  std::vector<Rational> p1_;               // S1(u~, v~)
  Rational F_[4];                          // F(x~)
  int fixed_ = -1;                         // the parameter fixed on a domain boundary, or -1
  std::vector<int> vars_;                  // the unknowns
  int n_ = 0;                              // unknowns and equations
  std::array<double, 4> a_{};              // the direction along the curve (inside)
  Rational A_[4];                          // a, exactly
  std::vector<std::vector<Rational>> Y_;   // F'(x~)^-1, exactly
  std::vector<Rational> YF_;               // Y F(x~)
  double yf_max_ = 0;                      // max |Y F(x~)|, in double
};

}  // namespace

SsiJudgement judge_point(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiParams& xd, const SsiParams& dir,
                         const Limits& limits) {
  for (const auto* S : {&S1, &S2}) {
    validate(*S, limits);
    if (S->dim() != 2 || S->q < 3) throw ValidationError(S == &S1 ? "first" : "second", "is not a surface in R^3", "give a spline surface with points x,y,z");
  }
  return PointJudge(S1, S2, limits).judge(xd, dir);
}

}  // namespace splinex
