#include "cut/solid3.hpp"

#include <algorithm>
#include <map>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "bernstein/tensor.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

using P3 = Point3<Rational>;

std::string facet_field(std::size_t i) { return "facets[" + std::to_string(i) + "]"; }
const char* side_name(int s) {
  static const char* names[4] = {"v = v0", "u = u1", "v = v1", "u = u0"};
  return names[s];
}

P3 point(const BSpline<Rational>& C, std::size_t i) { return {C.points[3 * i], C.points[3 * i + 1], C.points[3 * i + 2]}; }

// Knots mapped affinely onto [0, 1] (a side's shape does not depend on its parameter interval).
std::vector<Rational> normalized(const std::vector<Rational>& U) {
  const Rational lo = U.front(), w = U.back() - U.front();
  std::vector<Rational> V;
  for (const auto& u : U) V.push_back((u - lo) / w);
  return V;
}

// The same curve run backwards?
bool reversed_equal(const BSpline<Rational>& A, const BSpline<Rational>& B) {
  if (A.degrees != B.degrees || A.size() != B.size()) return false;
  const auto UA = normalized(A.knots[0]), UB = normalized(B.knots[0]);
  for (std::size_t i = 0; i < UA.size(); ++i)
    if (UA[i] != 1 - UB[UB.size() - 1 - i]) return false;
  const std::size_t n = A.size();
  for (std::size_t i = 0; i < n; ++i)
    if (point(A, i) != point(B, n - 1 - i)) return false;
  return true;
}

// t . (F_u x F_v) of one Bezier piece, as a bivariate Bernstein polynomial on [0, 1]^2.
Bernstein<Rational> normal_dot(const BSpline<Rational>& piece, const P3& t) {
  std::array<Bernstein<Rational>, 3> du, dv;
  for (int c = 0; c < 3; ++c) {
    const auto x = bern_coordinate(piece, c);
    du[c] = bern_derivative(x, 0);
    dv[c] = bern_derivative(x, 1);
  }
  Bernstein<Rational> out;
  for (int c = 0; c < 3; ++c) {
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    if (t[c] == 0) continue;
    auto term = bern_sub(bern_product(du[a], dv[b]), bern_product(du[b], dv[a]));
    for (auto& v : term.c) v *= t[c];
    out = out.c.empty() ? term : bern_add(out, term);
  }
  return out;
}

// Decide g < 0 on all of [0, 1] (univariate Bernstein): 1 certified, -1 refuted (value >= 0 at a
// point, returned in `where`, a parameter in [0, 1]), 0 undecided within the depth.
int negative_on_interval(const Bernstein<Rational>& g, int depth, Rational lo, Rational hi, Rational& where) {
  if (bern_sign(g) < 0) return 1;
  if (!(g.c.front() < 0)) {
    where = lo;
    return -1;
  }
  if (!(g.c.back() < 0)) {
    where = hi;
    return -1;
  }
  if (depth == 0) {
    where = (lo + hi) / 2;
    return 0;
  }
  const auto [a, b] = bern_split(g, 0, Rational(1, 2));
  const Rational mid = (lo + hi) / 2;
  const int ra = negative_on_interval(a, depth - 1, lo, mid, where);
  if (ra <= 0) return ra;
  return negative_on_interval(b, depth - 1, mid, hi, where);
}

// Is t strictly below facet F's tangent plane along side s (t . N < 0 on the whole side)?
void check_tangent_below(const BSpline<Rational>& F, int side, const P3& t, const std::string& field, std::size_t facet) {
  for (const auto& piece : extract_bezier(F)) {
    const auto& sp = piece.spline;
    const int l = side % 2 == 0 ? 1 : 0;  // sides 0, 2 fix v (direction 1); 1, 3 fix u
    const bool at_hi = side == 1 || side == 2;
    const Rational fixed = at_hi ? F.domain_hi(l) : F.domain_lo(l);
    if ((at_hi ? sp.domain_hi(l) : sp.domain_lo(l)) != fixed) continue;
    const auto g = bern_face(normal_dot(sp, t), l, at_hi ? 1 : 0);
    Rational where;
    const int r = negative_on_interval(g, 24, Rational(0), Rational(1), where);
    if (r < 0)
      throw ValidationError(field, "does not point strictly into the solid: at least as high as " + facet_field(facet) +
                                       "'s tangent plane at a point of its side " + side_name(side),
                            "give a tangent t with t . N < 0 for both facets' outward normals N along the side");
    if (r == 0)
      throw ValidationError(field, "could not be certified to point strictly into the solid along " + facet_field(facet) + "'s side " +
                                       side_name(side) + " (t . N comes close to 0)",
                            "tilt the tangent further into the solid");
  }
}

// An integer square root scaled: r with |r - 1/sqrt(s)| <= 2^-40 / sqrt(s) roughly (s > 0).
Rational inverse_sqrt(const Rational& s) {
  const Integer p = numerator(s), q = denominator(s);
  const Integer scale = Integer(1) << 80;
  const Integer m = boost::multiprecision::sqrt(Integer(q * p * scale));
  return Rational(m) / Rational(p * (Integer(1) << 40));
}

}  // namespace

BSpline<Rational> facet_side(const BSpline<Rational>& F, int side) {
  const std::size_t n = F.count(0), m = F.count(1);
  BSpline<Rational> C;
  C.q = 3;
  const bool along_u = side % 2 == 0;
  C.degrees = {F.degrees[along_u ? 0 : 1]};
  C.knots = {F.knots[along_u ? 0 : 1]};
  const std::size_t len = along_u ? n : m;
  for (std::size_t k = 0; k < len; ++k) {
    std::size_t i = 0, j = 0;
    switch (side) {
      case 0: i = k, j = 0; break;
      case 1: i = n - 1, j = k; break;
      case 2: i = n - 1 - k, j = m - 1; break;
      default: i = 0, j = m - 1 - k; break;
    }
    for (int c = 0; c < 3; ++c) C.points.push_back(F.points[3 * (i + n * j) + c]);
  }
  if (side >= 2) {  // a side run backwards: its knots mirrored
    const auto& U = C.knots[0];
    std::vector<Rational> V;
    for (std::size_t k = U.size(); k-- > 0;) V.push_back(U.front() + U.back() - U[k]);
    C.knots[0] = V;
  }
  return C;
}

Rational signed_volume(const Solid3<Rational>& S) {
  // Divergence theorem: V = 1/3 sum of the integrals of F . (F_u x F_v) over the facets' Bezier
  // pieces on [0, 1]^2 (the integral is invariant under the pieces' reparametrization); a
  // Bernstein polynomial integrates to the mean of its coefficients.
  Rational total(0);
  for (const auto& F : S.facets)
    for (const auto& piece : extract_bezier(F)) {
      std::array<Bernstein<Rational>, 3> x, du, dv;
      for (int c = 0; c < 3; ++c) {
        x[c] = bern_coordinate(piece.spline, c);
        du[c] = bern_derivative(x[c], 0);
        dv[c] = bern_derivative(x[c], 1);
      }
      for (int c = 0; c < 3; ++c) {
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        const auto nc = bern_sub(bern_product(du[a], dv[b]), bern_product(du[b], dv[a]));
        const auto g = bern_product(x[c], nc);
        Rational sum(0);
        for (const auto& v : g.c) sum += v;
        total += sum / Rational(static_cast<long>(g.c.size()));
      }
    }
  return total / 3;
}

Adjacency3 validate_solid(const Solid3<Rational>& S) {
  if (S.facets.size() < 2) throw ValidationError("facets", "has " + std::to_string(S.facets.size()) + " facet(s)", "give the closed set of facets bounding the solid");
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    const std::string f = facet_field(i);
    validate(F);
    if (F.dim() != 2) throw ValidationError(f, "is not a surface (" + std::to_string(F.dim()) + " parameters)", "give tensor-product surfaces (two parameters)");
    if (F.q != 3) throw ValidationError(f, "has " + std::to_string(F.q) + " coordinates", "give surfaces in R^3 (3 coordinates)");
    if (F.is_rational()) throw ValidationError(f, "is rational", "give polynomial facets (rational facets are not supported yet)");
    for (int d = 0; d < 2; ++d) {
      if (F.degrees[d] < 1) throw ValidationError(f, "has degree 0 in direction " + std::to_string(d), "give surfaces of degree >= 1 in both directions");
      if (!is_clamped(F.knots[d], F.degrees[d], F.count(d)))
        throw ValidationError(f + ".knots", "is not clamped in direction " + std::to_string(d), "clamp the knot vectors so the facet's sides are its boundary control points");
      if (F.domain_lo(d) == F.domain_hi(d)) throw ValidationError(f + ".knots", "has an empty domain", "give a domain of positive width");
    }
  }
  Adjacency3 adj;
  const std::size_t none = S.facets.size();
  adj.facet.assign(S.facets.size(), {none, none, none, none});
  adj.side.assign(S.facets.size(), {-1, -1, -1, -1});
  // Sides keyed by their (unordered) end points, then matched exactly.
  std::map<std::pair<P3, P3>, std::vector<std::pair<std::size_t, int>>> by_ends;
  std::vector<std::array<BSpline<Rational>, 4>> sides(S.facets.size());
  for (std::size_t i = 0; i < S.facets.size(); ++i)
    for (int s = 0; s < 4; ++s) {
      sides[i][s] = facet_side(S.facets[i], s);
      const auto& C = sides[i][s];
      P3 a = point(C, 0), b = point(C, C.size() - 1);
      if (a == b) throw ValidationError(facet_field(i), std::string("has a side whose ends coincide (") + side_name(s) + ": collapsed to a point or closed)",
                                        "give facets with four sides of distinct ends (degenerate and periodic patches are not supported yet)");
      if (b < a) std::swap(a, b);
      by_ends[{a, b}].push_back({i, s});
    }
  for (std::size_t i = 0; i < S.facets.size(); ++i)
    for (int s = 0; s < 4; ++s) {
      const auto& C = sides[i][s];
      P3 a = point(C, 0), b = point(C, C.size() - 1);
      if (b < a) std::swap(a, b);
      std::size_t found = 0;
      for (const auto& [j, t] : by_ends[{a, b}]) {
        if (j == i && t == s) continue;
        if (!reversed_equal(C, sides[j][t])) continue;
        ++found;
        adj.facet[i][s] = j;
        adj.side[i][s] = t;
      }
      if (found == 0)
        throw ValidationError(facet_field(i), std::string("has a side (") + side_name(s) + ") that no other facet shares, run in the opposite direction",
                              "close the solid: every side must equal a side of one other facet as a curve (same degree and knots), "
                              "with the facets oriented so that F_u x F_v points outwards");
      if (found > 1)
        throw ValidationError(facet_field(i), std::string("has a side (") + side_name(s) + ") shared by " + std::to_string(found) + " other facets",
                              "give a solid whose every side bounds exactly two facets (a manifold boundary)");
    }
  const Rational v = signed_volume(S);
  if (v == 0) throw ValidationError("facets", "enclose zero signed volume", "give the boundary of a solid");
  if (v < 0) throw ValidationError("facets", "are oriented inwards (signed volume " + to_fraction_string(v) + ")",
                                   "orient every facet so that F_u x F_v points out of the solid (swap u and v, or reverse one direction)");
  return adj;
}

std::vector<LoopSide3> validate_cut(const Solid3<Rational>& S, const CutData3& cut) {
  const auto adj = validate_solid(S);
  const std::size_t n = S.facets.size();
  std::vector<char> in_b(n, 0);
  for (std::size_t k = 0; k < cut.positive.size(); ++k) {
    const auto i = cut.positive[k];
    const std::string f = "positive[" + std::to_string(k) + "]";
    if (i >= n) throw ValidationError(f, "is " + std::to_string(i) + ", the solid has " + std::to_string(n) + " facets", "give facet indices from 0 to " + std::to_string(n - 1));
    if (in_b[i]) throw ValidationError(f, "repeats facet " + std::to_string(i), "name each facet of b once");
    in_b[i] = 1;
  }
  if (cut.positive.empty() || cut.positive.size() == n)
    throw ValidationError("positive", "names " + std::string(cut.positive.empty() ? "no facet" : "every facet"),
                          "name the facets on one side of the cutting loop (b), at least one and not all");
  // The loop: sides of b facets whose neighbour is in b-bar.
  std::vector<LoopSide3> loop;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_b[i]) continue;
    for (int s = 0; s < 4; ++s) {
      const auto j = adj.facet[i][s];
      if (in_b[j]) continue;
      const auto C = facet_side(S.facets[i], s);
      LoopSide3 L;
      L.facet_a = i, L.side_a = s, L.facet_b = j, L.side_b = adj.side[i][s];
      L.start = point(C, 0), L.end = point(C, C.size() - 1);
      // straight: every control point on the segment, in order
      const P3 d = sub(L.end, L.start);
      Rational last(0);
      for (std::size_t k = 0; k < C.size(); ++k) {
        const P3 e = sub(point(C, k), L.start);
        const Rational lam = dot(e, d) / dot(d, d);
        if (cross(e, d) != P3{Rational(0), Rational(0), Rational(0)} || lam < last || lam > 1)
          throw ValidationError(facet_field(i), std::string("has a curved side on the cutting loop (") + side_name(s) + ")",
                                "cutting loops along straight sides only are built; split the facets so the loop runs along segments");
        last = lam;
      }
      loop.push_back(L);
    }
  }
  if (loop.empty())
    throw ValidationError("positive", "shares no side with the other facets (no cutting loop)", "name facets of b that border the rest of the boundary");
  // One closed cycle: each loop vertex is the start of one side and the end of one.
  std::map<P3, std::size_t> next;
  for (std::size_t m = 0; m < loop.size(); ++m) {
    if (next.count(loop[m].start))
      throw ValidationError("positive", "makes a cutting loop that passes a vertex twice", "choose b so that its border with b-bar is one simple closed loop");
    next[loop[m].start] = m;
  }
  std::vector<LoopSide3> cycle{loop[0]};
  std::vector<char> used(loop.size(), 0);
  used[0] = 1;
  for (;;) {
    const auto it = next.find(cycle.back().end);
    if (it == next.end()) throw DomainError("positive", "gives a cutting loop that does not close", "report this with the input (a closed solid's border is closed)");
    if (it->second == 0) break;
    if (used[it->second]) throw ValidationError("positive", "makes a cutting loop that passes a vertex twice", "choose b so that its border with b-bar is one simple closed loop");
    used[it->second] = 1;
    cycle.push_back(loop[it->second]);
  }
  if (cycle.size() != loop.size())
    throw ValidationError("positive", "makes " + std::string("a border with b-bar of several loops (") + std::to_string(loop.size()) + " sides, " +
                                          std::to_string(cycle.size()) + " in the first loop)",
                          "choose b so that its border with b-bar is one closed loop");
  loop = cycle;
  // Tangents: one per loop side.
  std::vector<char> has(loop.size(), 0);
  for (std::size_t k = 0; k < cut.tangents.size(); ++k) {
    const auto& T = cut.tangents[k];
    const std::string f = "tangents[" + std::to_string(k) + "]";
    std::size_t idx = loop.size();
    for (std::size_t m = 0; m < loop.size(); ++m)
      if (loop[m].facet_a == T.facet && loop[m].side_a == T.side) idx = m;
    if (idx == loop.size())
      throw ValidationError(f, "names facet " + std::to_string(T.facet) + " side " + std::to_string(T.side) + ", which is not a side of b on the cutting loop",
                            "give a tangent for each side shared by a facet of b and a facet of b-bar, named by the b facet and its side (0..3)");
    if (has[idx]) throw ValidationError(f, "repeats a loop side", "give one tangent per loop side");
    if (T.tangent == P3{Rational(0), Rational(0), Rational(0)}) throw ValidationError(f + ".tangent", "is zero", "give a non-zero tangent pointing into the solid");
    has[idx] = 1;
    auto& L = loop[idx];
    L.tangent = T.tangent;
    check_tangent_below(S.facets[L.facet_a], L.side_a, T.tangent, f + ".tangent", L.facet_a);
    check_tangent_below(S.facets[L.facet_b], L.side_b, T.tangent, f + ".tangent", L.facet_b);
    // n = d x t turned towards b: d_A, the direction from the side into facet a, has n . d_A > 0.
    const auto& A = S.facets[L.facet_a];
    const int l = L.side_a % 2 == 0 ? 1 : 0;
    const bool at_hi = L.side_a == 1 || L.side_a == 2;
    std::vector<Rational> mid{(A.domain_lo(0) + A.domain_hi(0)) / 2, (A.domain_lo(1) + A.domain_hi(1)) / 2};
    mid[l] = at_hi ? A.domain_hi(l) : A.domain_lo(l);
    std::vector<int> order{0, 0};
    order[l] = 1;
    const auto du = derivative(A, mid, order);
    P3 into{du[0], du[1], du[2]};
    if (at_hi) into = {-into[0], -into[1], -into[2]};
    P3 nn = cross(sub(L.end, L.start), T.tangent);
    const Rational side = dot(nn, into);
    if (side == 0)
      throw ValidationError(f + ".tangent", "lies in facet " + std::to_string(L.facet_a) + "'s tangent plane", "give a tangent pointing into the solid");
    if (side < 0) nn = {-nn[0], -nn[1], -nn[2]};
    const Rational r = inverse_sqrt(dot(nn, nn));
    L.normal = {nn[0] * r, nn[1] * r, nn[2] * r};
  }
  for (std::size_t m = 0; m < loop.size(); ++m)
    if (!has[m])
      throw ValidationError("tangents", "has no tangent for facet " + std::to_string(loop[m].facet_a) + "'s side " + std::to_string(loop[m].side_a) + " on the cutting loop",
                            "give a tangent for every loop side");
  return loop;
}

Frame3 unit_frame(const Solid3<Rational>& S) {
  Frame3 f;
  P3 lo = point(S.facets[0], 0), hi = lo;
  for (const auto& F : S.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const Rational& x = F.points[3 * i + c];
        if (x < lo[c]) lo[c] = x;
        if (hi[c] < x) hi[c] = x;
      }
  f.lo = lo;
  f.scale = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (f.scale == 0) f.scale = 1;
  return f;
}

Solid3<Rational> to_frame(const Solid3<Rational>& S, const Frame3& f) {
  Solid3<Rational> out = S;
  for (auto& F : out.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int c = 0; c < 3; ++c) F.points[3 * i + c] = (F.points[3 * i + c] - f.lo[c]) / f.scale;
  return out;
}

bool within_segment(const P3& x, const P3& a, const P3& b, const Rational& r) {
  // exists lam in [0, 1] with |a + lam (b - a) - x|_c <= r for c = 0, 1, 2: intersect intervals.
  Rational lo(0), hi(1);
  for (int c = 0; c < 3; ++c) {
    const Rational d = b[c] - a[c], l = x[c] - r - a[c], h = x[c] + r - a[c];
    if (d == 0) {
      if (l > 0 || h < 0) return false;
      continue;
    }
    Rational p = l / d, q = h / d;
    if (d < 0) std::swap(p, q);
    if (lo < p) lo = p;
    if (q < hi) hi = q;
  }
  return lo <= hi;
}

bool in_loop_strip(const std::vector<LoopSide3>& loop, const P3& x, const Rational& r) {
  for (const auto& L : loop)
    if (within_segment(x, L.start, L.end, r)) return true;
  return false;
}

bool box_in_loop_strip(const std::vector<LoopSide3>& loop, const P3& lo, const P3& hi, const Rational& r) {
  for (const auto& L : loop) {
    bool all = true;
    for (int m = 0; m < 8 && all; ++m)
      all = within_segment(P3{(m & 1) ? hi[0] : lo[0], (m & 2) ? hi[1] : lo[1], (m & 4) ? hi[2] : lo[2]}, L.start, L.end, r);
    if (all) return true;
  }
  return false;
}

}  // namespace splinex
