#include "untrim/curved.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>

#include "exact/root_isolation.hpp"
#include "untrim/interval_join.hpp"
#include "untrim/poly.hpp"

namespace splinex {

namespace {

using poly::Poly;

std::string qs(const Rational& v) { return ArithTraits<Rational>::to_string(v); }

// A loop edge in the sweep's terms: a vertical segment, or a graph arc y = f(x) oriented left to right.
struct Edge {
  std::size_t loop = 0, index = 0;
  bool vertical = false;
  Rational x0, x1;            // arc: x0 < x1; vertical: x0 == x1
  std::vector<Rational> c;    // arc: Bernstein ordinates over [x0, x1]; vertical: {y_lo, y_hi}
  Poly f;                     // arc: the same polynomial in powers of x
  Rational at(const Rational& x) const { return poly::bernstein_eval(c, (x - x0) / (x1 - x0)); }
  // Does the ray from p to +y cross this edge? Arcs only, half-open in x, so a ray through a
  // vertex counts the two edges meeting there once; the parity over a loop is the crossing number.
  bool above(const Point2<Rational>& p) const { return !vertical && x0 <= p[0] && p[0] < x1 && at(p[0]) > p[1]; }
};

Edge make_edge(const TrimmedDomain& D, std::size_t l, std::size_t i) {
  const Polygon P = D.edge(l, i);
  Edge e;
  e.loop = l;
  e.index = i;
  const auto& a = P.front();
  const auto& b = P.back();
  if (a[0] == b[0]) {
    e.vertical = true;
    e.x0 = e.x1 = a[0];
    e.c = {std::min(a[1], b[1]), std::max(a[1], b[1])};
    return e;
  }
  const bool rev = b[0] < a[0];
  e.x0 = rev ? b[0] : a[0];
  e.x1 = rev ? a[0] : b[0];
  for (const auto& p : P) e.c.push_back(p[1]);
  if (rev) std::reverse(e.c.begin(), e.c.end());
  e.f = poly::from_bernstein(e.c, e.x0, e.x1);
  return e;
}

std::vector<std::vector<Edge>> all_edges(const TrimmedDomain& D) {
  std::vector<std::vector<Edge>> out;
  for (std::size_t l = 0; l < D.loops.size(); ++l) {
    out.emplace_back();
    for (std::size_t i = 0; i < D.loops[l].size(); ++i) out.back().push_back(make_edge(D, l, i));
  }
  return out;
}

// Do the two edges share a point other than the allowed ones (shared vertices of consecutive edges)?
bool edges_meet(const Edge& A, const Edge& B, const std::vector<Point2<Rational>>& allowed) {
  const auto is_allowed = [&](const Rational& x, const Rational& y) {
    for (const auto& v : allowed)
      if (v[0] == x && v[1] == y) return true;
    return false;
  };
  if (A.vertical && B.vertical) {
    if (A.x0 != B.x0) return false;
    const Rational lo = std::max(A.c[0], B.c[0]), hi = std::min(A.c[1], B.c[1]);
    if (hi < lo) return false;
    if (lo < hi) return true;
    return !is_allowed(A.x0, lo);
  }
  if (A.vertical || B.vertical) {
    const Edge& V = A.vertical ? A : B;
    const Edge& G = A.vertical ? B : A;
    if (V.x0 < G.x0 || G.x1 < V.x0) return false;
    const Rational y = G.at(V.x0);
    if (y < V.c[0] || V.c[1] < y) return false;
    return !is_allowed(V.x0, y);
  }
  const Rational c0 = std::max(A.x0, B.x0), c1 = std::min(A.x1, B.x1);
  if (c1 < c0) return false;
  if (c0 == c1) return A.at(c0) == B.at(c0) && !is_allowed(c0, A.at(c0));
  const Poly h = poly::sub(A.f, B.f);
  if (poly::is_zero(h)) return true;
  const auto roots = isolate_real_roots(h, c0, c1, 8);
  std::size_t allowed_roots = 0;
  for (const auto& v : allowed)
    if (!(v[0] < c0) && !(c1 < v[0]) && poly::eval(h, v[0]) == 0 && A.at(v[0]) == v[1]) ++allowed_roots;
  return roots.size() > allowed_roots;
}

}  // namespace

void validate_curved_domain(const TrimmedDomain& D) {
  if (D.controls.size() != D.loops.size())
    throw ValidationError("controls", "has " + std::to_string(D.controls.size()) + " entries for " +
                                          std::to_string(D.loops.size()) + " loops",
                          "give one list of edge controls per loop");
  for (std::size_t l = 0; l < D.loops.size(); ++l) {
    const auto& L = D.loops[l];
    const std::string f = loop_field(l);
    if (D.controls[l].size() != L.size())
      throw ValidationError(f, "has " + std::to_string(D.controls[l].size()) + " edge control lists for " +
                                   std::to_string(L.size()) + " edges",
                            "give one (possibly empty) list per edge");
    if (L.size() < 2) throw ValidationError(f, "is degenerate: fewer than 2 vertices", "give a closed loop of edges");
    validate_loop_vertices(D, l);
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Polygon P = D.edge(l, i);
      const int deg = static_cast<int>(P.size()) - 1;
      if (deg > 100)
        throw SizeLimitError(edge_field(l, i), "has degree " + std::to_string(deg) + ", above the limit of 100",
                             "split the edge into pieces of lower degree");
      if (deg == 1) continue;
      const auto &a = P.front(), &b = P.back();
      if (a[0] == b[0])
        throw ValidationError(edge_field(l, i), "is curved with both end points at x = " + qs(a[0]) + " (not a graph y = f(x))",
                              "split the curve into graphs over x (pieces between its x-extremes)");
      for (int j = 1; j < deg; ++j)
        if (P[j][0] != a[0] + (b[0] - a[0]) * Rational(j, deg))
          throw ValidationError(edge_field(l, i),
                                "is not a graph y = f(x): control point " + std::to_string(j) + " has x = " + qs(P[j][0]) +
                                    ", not " + qs(Rational(a[0] + (b[0] - a[0]) * Rational(j, deg))),
                                "give curved edges with control x evenly spaced between the end points (x affine in "
                                "the curve parameter); split other curves at their x-extremes and reparametrize");
    }
  }
  const auto E = all_edges(D);
  // Cheap answers first: ordinates all inside [lo, hi] keep the curve inside (convex hull); a
  // sample of the curve outside the box proves it leaves. Root isolation (costly for ordinates
  // like -1e100000) only decides what neither settles.
  for (const auto& loop : E)
    for (const auto& e : loop) {
      if (e.vertical || e.c.size() <= 2) continue;
      const int m = 16;
      for (int k = 0; k <= m; ++k) {
        const Rational x = e.x0 + (e.x1 - e.x0) * Rational(k, m), y = poly::eval(e.f, x);
        if (y < D.lo[1] || D.hi[1] < y)
          throw DomainError(edge_field(e.loop, e.index), "leaves the domain: at x = " + qs(x) + " the curve is " +
                                                            (y < D.lo[1] ? "below y = " + qs(D.lo[1]) : "above y = " + qs(D.hi[1])),
                            "keep trimming curves inside the parameter box");
      }
    }
  for (const auto& loop : E)
    for (const auto& e : loop)
      if (!e.vertical && e.c.size() > 2 &&
          !std::all_of(e.c.begin(), e.c.end(), [&](const Rational& y) { return !(y < D.lo[1]) && !(D.hi[1] < y); }) &&
          (poly::exists_positive({poly::sub(e.f, Poly{D.hi[1]})}, e.x0, e.x1) ||
           poly::exists_positive({poly::sub(Poly{D.lo[1]}, e.f)}, e.x0, e.x1)))
        throw DomainError(edge_field(e.loop, e.index), "leaves the domain: the curve crosses y = " + qs(D.lo[1]) + " or y = " + qs(D.hi[1]),
                          "keep trimming curves inside the parameter box");
  // Every pair of edges whose x-ranges meet (an interval join, not all pairs); the first meeting
  // pair in loop order is reported.
  std::vector<std::pair<Rational, Rational>> ex;
  std::vector<std::pair<std::size_t, std::size_t>> id;
  for (std::size_t l = 0; l < E.size(); ++l)
    for (std::size_t i = 0; i < E[l].size(); ++i) {
      ex.emplace_back(E[l][i].x0, E[l][i].x1);
      id.emplace_back(l, i);
    }
  const auto first = first_meeting_edges(ex, id, [&](std::size_t l, std::size_t i, std::size_t m, std::size_t j) {
    std::vector<Point2<Rational>> allowed;
    if (l == m) {
      const std::size_t n = E[l].size();
      if (j == i + 1) allowed.push_back(D.loops[l][j]);
      if ((j + 1) % n == i) allowed.push_back(D.loops[l][i]);
    }
    return edges_meet(E[l][i], E[m][j], allowed);
  });
  if (first) throw_meeting_edges(*first);
  for (std::size_t l = 0; l < D.loops.size(); ++l)
    if (loop_signed_area(D, l) == 0)
      throw ValidationError(loop_field(l), "is degenerate: encloses zero area", "give a loop that encloses a region");
}

Rational loop_signed_area(const TrimmedDomain& D, std::size_t l) {
  Rational a = 0;
  for (std::size_t i = 0; i < D.loops[l].size(); ++i) {
    const Polygon P = D.edge(l, i);
    std::vector<Rational> xs, ys;
    for (const auto& p : P) {
      xs.push_back(p[0]);
      ys.push_back(p[1]);
    }
    const Poly x = poly::from_bernstein(xs, 0, 1), y = poly::from_bernstein(ys, 0, 1);
    a += poly::integral01(poly::mul(x, poly::derivative(y)));
  }
  return a;
}

void throw_meeting_edges(const std::array<std::size_t, 4>& pair) {
  const auto [l, m, i, j] = pair;
  if (l == m)
    throw ValidationError(loop_field(l),
                          "is self-intersecting (edge " + std::to_string(i) + " and edge " + std::to_string(j) + " meet)",
                          "split it into simple loops (no edge may cross or touch another)");
  throw ValidationError(loop_field(m),
                        "meets loops[" + std::to_string(l) + "] (edge " + std::to_string(j) + " and edge " + std::to_string(i) + ")",
                        "trimming loops must be disjoint; merge them into one simple loop");
}

bool inside_loop(const TrimmedDomain& D, std::size_t l, const Point2<Rational>& p) {
  bool in = false;
  for (std::size_t i = 0; i < D.loops[l].size(); ++i) {
    if (make_edge(D, l, i).above(p)) in = !in;
  }
  return in;
}

std::vector<Tile<Rational>> untrim_curved(const TrimmedDomain& D, const std::array<std::vector<Rational>, 2>& knot_lines,
                                          int approx_bits) {
  struct Arc {
    Rational x0, x1;
    std::vector<Rational> c;
    bool loop;
  };
  std::vector<Arc> arcs;
  std::vector<Rational> xs{D.lo[0], D.hi[0]};
  for (const auto& k : knot_lines[0])
    if (D.lo[0] < k && k < D.hi[0]) xs.push_back(k);
  std::vector<Rational> hs{D.lo[1], D.hi[1]};
  for (const auto& k : knot_lines[1])
    if (D.lo[1] < k && k < D.hi[1]) hs.push_back(k);
  for (const auto& loop : all_edges(D))
    for (const auto& e : loop) {
      xs.push_back(e.x0);
      if (e.vertical) continue;
      xs.push_back(e.x1);
      arcs.push_back({e.x0, e.x1, e.c, true});
      for (const auto& k : hs) {
        const Poly g = poly::sub(e.f, Poly{k});
        if (poly::is_zero(g)) continue;  // the edge lies on the line: merged in the slabs
        for (const auto& r : classify_real_roots(g, e.x0, e.x1)) {
          if (r.exact) {
            xs.push_back(*r.exact);
            continue;
          }
          if (approx_bits > 0) {
            for (const auto& a : isolate_real_roots(g, r.root.lo, r.root.hi, approx_bits))
              xs.push_back(simplest_rational(a.lo, a.hi));
            continue;
          }
          const bool box = k == D.lo[1] || k == D.hi[1];
          throw DomainError(edge_field(e.loop, e.index),
                            std::string(box ? "touches the domain's edge" : "crosses the knot line") + " y = " + qs(k) +
                                " at an irrational x in [" + qs(r.root.lo) + ", " + qs(r.root.hi) + "]",
                            "exact untrimming ends tiles at rational points only: choose a curve (or knot line) whose "
                            "crossings are rational, or split the tile boundary there yourself");
        }
      }
    }
  for (const auto& k : hs) arcs.push_back({D.lo[0], D.hi[0], {k, k}, false});
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  // The straight sweep's bookkeeping (TileAssembler): trapezoids continue the open tile whose right
  // side is their left side; every tile has label 0.
  TileAssembler<Rational> tiles;
  for (std::size_t s = 0; s + 1 < xs.size(); ++s) {
    const Rational &xa = xs[s], &xb = xs[s + 1];
    struct Active {
      Rational mid;
      std::vector<Rational> c;  // ordinates over [xa, xb]
      bool loop;
    };
    std::vector<Active> act;
    for (const auto& a : arcs) {
      if (xa < a.x0 || a.x1 < xb) continue;
      const Rational w = a.x1 - a.x0;
      auto c = poly::bernstein_restrict(a.c, (xa - a.x0) / w, (xb - a.x0) / w);
      const Rational mid = poly::bernstein_eval(c, Rational(1, 2));
      act.push_back({mid, std::move(c), a.loop});
    }
    std::sort(act.begin(), act.end(), [](const Active& p, const Active& q) { return p.mid < q.mid || (p.mid == q.mid && p.loop && !q.loop); });
    std::vector<Active> merged;
    for (auto& a : act)
      if (!merged.empty() && merged.back().mid == a.mid)
        merged.back().loop = merged.back().loop || a.loop;
      else
        merged.push_back(std::move(a));
    int parity = 0;
    for (std::size_t m = 0; m + 1 < merged.size(); ++m) {
      parity ^= merged[m].loop ? 1 : 0;
      if (!parity) continue;
      const auto &lo = merged[m].c, &hi = merged[m + 1].c;
      const std::size_t t = tiles.open_at(0, xa, lo.front(), hi.front());
      auto& tl = tiles.tiles()[t];
      tl.x.push_back(xb);
      tl.yb.push_back(lo.back());
      tl.yt.push_back(hi.back());
      tl.bottom.push_back(lo.size() < 2 ? std::vector<Rational>{lo.front(), lo.front()} : lo);
      tl.top.push_back(hi.size() < 2 ? std::vector<Rational>{hi.front(), hi.front()} : hi);
      tiles.close(t, xb, lo.back(), hi.back());
    }
  }
  return std::move(tiles.tiles());
}

CoverCertificate certify_cover(const TrimmedDomain& D, const std::vector<Tile<Rational>>& tiles) {
  CoverCertificate cc;
  cc.tiles = tiles.size();
  const auto fail = [&](const std::string& why) {
    if (cc.ok) {
      cc.ok = false;
      cc.failure = why;
    }
  };
  // A tile piece as polynomials in x.
  struct Piece {
    std::size_t tile;
    Rational x0, x1;
    Poly b, t;
  };
  std::vector<Piece> pieces;
  for (std::size_t k = 0; k < tiles.size(); ++k)
    for (std::size_t i = 0; i + 1 < tiles[k].x.size(); ++i) {
      const Rational &x0 = tiles[k].x[i], &x1 = tiles[k].x[i + 1];
      if (!(x0 < x1)) {
        fail("tile " + std::to_string(k) + ": chain x not increasing at piece " + std::to_string(i));
        continue;
      }
      pieces.push_back({k, x0, x1, poly::from_bernstein(tiles[k].bottom_piece(i), x0, x1),
                        poly::from_bernstein(tiles[k].top_piece(i), x0, x1)});
    }
  // The pairs below are found by interval joins on x (untrim/interval_join.hpp), so the work grows
  // with the number of pairs whose x-ranges meet, not with the product of the counts.
  std::vector<std::pair<Rational, Rational>> piece_x;
  for (const auto& P : pieces) piece_x.emplace_back(P.x0, P.x1);
  // 1. Interior-disjoint: no x in a common open interval with max(bottoms) < min(tops).
  for_overlapping_pairs(piece_x, [&](std::size_t p, std::size_t q) {
    const auto &A = pieces[p], &B = pieces[q];
    if (!cc.ok || A.tile == B.tile) return;  // pieces of one tile have disjoint x-ranges
    const Rational u = std::max(A.x0, B.x0), v = std::min(A.x1, B.x1);
    if (!(u < v)) return;
    ++cc.pair_checks;
    if (poly::exists_positive({poly::sub(A.t, A.b), poly::sub(B.t, B.b), poly::sub(A.t, B.b), poly::sub(B.t, A.b)}, u, v))
      fail("tiles " + std::to_string(A.tile) + " and " + std::to_string(B.tile) + " overlap over x in (" + qs(u) + ", " + qs(v) + ")");
  });
  // 2. No loop edge enters a tile's interior.
  std::vector<Edge> E;
  for (auto& loop : all_edges(D))
    for (auto& e : loop) E.push_back(std::move(e));
  std::vector<std::pair<Rational, Rational>> edge_x;
  for (const auto& e : E) edge_x.emplace_back(e.x0, e.x1);
  for_overlapping_pairs(edge_x, piece_x, [&](std::size_t ei, std::size_t pi) {
    const Edge& e = E[ei];
    const Piece& P = pieces[pi];
    if (!cc.ok) return;
    if (e.vertical) {
      if (!(P.x0 < e.x0 && e.x0 < P.x1)) return;
      ++cc.edge_checks;
      const Rational b = poly::eval(P.b, e.x0), t = poly::eval(P.t, e.x0);
      if (std::max(b, e.c[0]) < std::min(t, e.c[1]))
        fail(edge_field(e.loop, e.index) + " passes through the interior of tile " + std::to_string(P.tile));
      return;
    }
    const Rational u = std::max(P.x0, e.x0), v = std::min(P.x1, e.x1);
    if (!(u < v)) return;
    ++cc.edge_checks;
    if (poly::exists_positive({poly::sub(e.f, P.b), poly::sub(P.t, e.f)}, u, v))
      fail(edge_field(e.loop, e.index) + " enters the interior of tile " + std::to_string(P.tile) + " over x in (" + qs(u) +
           ", " + qs(v) + ")");
  });
  // 3. Every connected part of every tile is in the region: a sample between consecutive roots of
  //    t - b (where the part is open) in every piece. In the region means an odd number of loop
  //    edges above the sample (even-odd rule; the loops are disjoint, so this is the depth's parity),
  //    edges half-open in x so a vertical ray through a vertex counts the two edges meeting there once.
  struct Sample {
    std::size_t tile;
    Point2<Rational> p;
    bool in = false;
  };
  std::vector<Sample> samples;
  for (const auto& P : pieces) {
    if (!cc.ok) break;
    const Poly h = poly::sub(P.t, P.b);
    if (poly::is_zero(h)) continue;  // zero thickness: no interior
    std::vector<Rational> cuts{P.x0};
    if (h.size() <= 2) {
      // Constant or linear: its root, if any, is exact.
      if (h.size() == 2 && h[1] != 0) {
        const Rational r = -h[0] / h[1];
        if (P.x0 < r && r < P.x1) {
          cuts.push_back(r);
          cuts.push_back(r);
        }
      }
    } else {
      for (const auto& r : isolate_real_roots(h, P.x0, P.x1, 16)) {
        cuts.push_back(r.lo);
        cuts.push_back(r.hi);
      }
    }
    cuts.push_back(P.x1);
    for (std::size_t j = 0; j + 1 < cuts.size(); j += 2) {
      if (!(cuts[j] < cuts[j + 1])) continue;
      const Rational x = (cuts[j] + cuts[j + 1]) / 2;
      const Rational b = poly::eval(P.b, x), t = poly::eval(P.t, x);
      if (!(b < t)) {
        if (t < b) fail("tile " + std::to_string(P.tile) + " has its top below its bottom at x = " + qs(x));
        continue;
      }
      ++cc.samples;
      samples.push_back({P.tile, {x, (b + t) / 2}});
    }
  }
  std::vector<std::pair<Rational, Rational>> sample_x;
  for (const auto& q : samples) sample_x.emplace_back(q.p[0], q.p[0]);
  for_overlapping_pairs(edge_x, sample_x, [&](std::size_t ei, std::size_t si) {
    if (E[ei].above(samples[si].p)) samples[si].in = !samples[si].in;
  });
  for (const auto& q : samples)
    if (!q.in) fail("tile " + std::to_string(q.tile) + " has the point (" + qs(q.p[0]) + ", " + qs(q.p[1]) + ") outside the region");
  // 4. No gap: the areas add up.
  for (const auto& t : tiles) cc.tile_area_sum += tile_area(t);
  cc.region_area = region_area(D);
  if (cc.ok && cc.tile_area_sum != cc.region_area)
    fail("tile areas add up to " + qs(cc.tile_area_sum) + ", the region's area is " + qs(cc.region_area));
  return cc;
}

}  // namespace splinex
