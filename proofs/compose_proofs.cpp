// Composition's proofs (papers/000): Bezier composition by both methods, R = T(S) for Bezier and
// B-spline composition, Algorithm 1's trimmed patches, and the exact end points of trimming curves.
#include <algorithm>
#include <random>

#include "compose/trimmed_compose.hpp"
#include "compose/trimming_end_points.hpp"
#include "exact/root_isolation.hpp"
#include "fixtures/random_spline.hpp"
#include "proofs/suite_detail.hpp"
#include "spline/kernel.hpp"

namespace splinex::proof_detail {

namespace {

// The shape of T(S) read from the inputs: S's breakpoints, degree D_l = d_l * sum_j e_j per
// direction of S, rational (denominator of the same degree) iff S or T is.
PiecewiseShape composed_shape(const BSpline<Rational>& T, const BSpline<Rational>& S) {
  PiecewiseShape s = shape_of(S);
  int E = 0;
  for (int e : T.degrees) E += e;
  for (int l = 0; l < S.dim(); ++l) {
    s.numerator[l] = S.degrees[l] * E;
    s.denominator[l] = (S.is_rational() || T.is_rational()) ? S.degrees[l] * E : 0;
  }
  return s;
}

// A random Bezier composition: inner S: R^k -> R^n, outer T: R^n -> R^q, rational or not.
std::pair<BSpline<Rational>, BSpline<Rational>> random_composition(std::mt19937_64& rng, bool inside) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  const int k = pick(1, 3), n = pick(1, 3);
  RandomSplineSpec inner_spec, outer_spec;
  for (int l = 0; l < k; ++l) {
    inner_spec.degrees.push_back(pick(1, k == 3 ? 1 : 2));
    inner_spec.counts.push_back(inner_spec.degrees.back() + 1);
  }
  for (int j = 0; j < n; ++j) {
    outer_spec.degrees.push_back(pick(1, n == 3 ? 2 : 3));
    outer_spec.counts.push_back(outer_spec.degrees.back() + 1);
  }
  inner_spec.q = n;
  outer_spec.q = pick(1, 3);
  inner_spec.rational = pick(0, 2) == 0;
  outer_spec.rational = pick(0, 2) == 0;
  BSpline<Rational> S = random_spline(inner_spec, rng), T = random_spline(outer_spec, rng);
  for (int l = 0; l < k; ++l) S = reparametrize(S, l, Rational(pick(-3, 0), 2), Rational(pick(1, 4), 3));
  for (int j = 0; j < n; ++j) T = reparametrize(T, j, Rational(pick(-4, 0), 5), Rational(pick(1, 5), 4));
  // Inner points in [-2, 2]; inside: mapped into the outer box instead (rational outer splines
  // need it for positive composed weights).
  if (inside || T.is_rational())
    for (std::size_t i = 0; i < S.size(); ++i)
      for (int j = 0; j < n; ++j) {
        Rational& x = S.points[i * n + j];
        x = T.domain_lo(j) + (T.domain_hi(j) - T.domain_lo(j)) * (x + 2) / 4;
      }
  return std::make_pair(T, S);
}

void compose_methods_agree(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const auto [T, S] = random_composition(rng, false);
  const auto A = compose_bezier(T, S, CompositionMethod::symbolic);
  const auto B = planted(compose_bezier(T, S, CompositionMethod::interpolation));
  if (A.degrees != composed_degrees(T, S)) acc.fail("wrong composed degrees", i);
  compare_nets(acc, A, B, "the two composition methods differ", i);
}

void compose_identity(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const auto [T, S] = random_composition(rng, false);
  const auto R = planted(compose_bezier(T, S, CompositionMethod::symbolic));
  // T(S) from the inputs: degree D_l = d_l * sum e_j, rational iff S or T is;
  // R as it is. Cells: both sides' breakpoints on S's domain.
  const PiecewiseShape ts = composed_shape(T, S);
  const auto cuts = union_cuts(ts, shape_of(R), domain_box(S));
  const auto bound = identity_bound(ts, shape_of(R));
  acc.add(prove_by_samples(cuts, bound,
                           [&](const std::vector<Rational>& x) {
                             const auto s = evaluate(S, x);
                             auto t = evaluate_bezier_anywhere(T, s);
                             if (T.is_rational())
                               for (int c = 0; c < T.q; ++c) t[c] /= t[T.q];
                             t.resize(T.q);
                             return evaluate(R, x) == t ? std::string() : std::string("R(r) != T(S(r))");
                           },
                           ""),
          i);
}

void compose_bspline(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  const int n = pick(1, 2);
  RandomSplineSpec outer_spec;
  for (int j = 0; j < n; ++j) {
    outer_spec.degrees.push_back(pick(0, 3));
    outer_spec.counts.push_back(outer_spec.degrees.back() + 1 + pick(0, 2));
  }
  outer_spec.q = pick(1, 3);
  outer_spec.rational = pick(0, 2) == 0;
  BSpline<Rational> T = random_spline(outer_spec, rng);
  // Half the cases: T jumps at one interior knot (raised to multiplicity e+1, then
  // the first control point after it moved).
  const bool outer_jumps = pick(0, 1) == 1;
  if (outer_jumps)
    for (int j = 0; j < n; ++j) {
      const auto bp = breakpoints(T.knots[j], T.degrees[j], T.count(j));
      if (bp.size() < 3) continue;
      const Rational x = bp[1 + pick(0, static_cast<int>(bp.size()) - 3)];
      const int room = T.degrees[j] + 1 - static_cast<int>(multiplicity(T.knots[j], x));
      if (room > 0) T = insert_knot(T, j, x, room);
      std::size_t first = 0;
      while (T.knots[j][first] < x) ++first;  // the jump's first control point in direction j
      const auto f = fibre_layout(T, j);
      for (std::size_t a = 0; a < f.after; ++a)
        for (std::size_t b = 0; b < f.before; ++b)
          T.points[((a * f.n + first) * f.before + b) * T.q] += Rational(pick(1, 9), 7);
      break;
    }
  // S(r) = (phi_0(r_0), ..., phi_{n-1}(r_{n-1})): per direction a quadratic that maps
  // each cell of T into itself: C^0 and onto (middle control point strictly inside),
  // or (half the cases) C^-1 with random end values in the cell, never reaching the
  // cell's upper line at a parameter it owns.
  const bool inner_jumps = pick(0, 1) == 1;
  BSpline<Rational> S;
  S.q = n;
  std::vector<std::vector<Rational>> coord(n);
  for (int j = 0; j < n; ++j) {
    const auto bp = breakpoints(T.knots[j], T.degrees[j], T.count(j));
    std::vector<Rational> U{bp.front(), bp.front(), bp.front()};
    if (!inner_jumps) coord[j].push_back(bp.front());
    for (std::size_t c = 0; c + 1 < bp.size(); ++c) {
      if (inner_jumps) {
        coord[j].push_back(pick(0, 2) == 0 ? bp[c] : random_inside(bp[c], bp[c + 1], rng));
        coord[j].push_back(random_inside(bp[c], bp[c + 1], rng));
        coord[j].push_back(pick(0, 2) == 0 ? bp[c + 1] : random_inside(bp[c], bp[c + 1], rng));
        U.insert(U.end(), 3, bp[c + 1]);
        continue;
      }
      coord[j].push_back(random_inside(bp[c], bp[c + 1], rng));
      coord[j].push_back(bp[c + 1]);
      U.insert(U.end(), c + 2 < bp.size() ? 2 : 3, bp[c + 1]);
    }
    S.degrees.push_back(2);
    S.knots.push_back(std::move(U));
  }
  std::size_t total = 1;
  for (int j = 0; j < n; ++j) total *= coord[j].size();
  for (std::size_t g = 0; g < total; ++g) {
    std::size_t rem = g;
    for (int j = 0; j < n; ++j) {
      S.points.push_back(coord[j][rem % coord[j].size()]);
      rem /= coord[j].size();
    }
  }
  validate(S);
  std::vector<std::string> tags;
  if (outer_jumps) tags.push_back("outer C^-1 (jumps)");
  if (inner_jumps) tags.push_back("inner C^-1 (jumps)");
  if (T.is_rational()) tags.push_back("rational outer");
  for (int e : T.degrees)
    if (e == 0) tags.push_back("outer degree 0");
  acc.structures(tags);
  const auto R = planted(compose(T, S));
  // T(S) is one polynomial (rational) map per piece of S (each piece in one cell
  // of T, checked by compose): cells from S's and R's breakpoints, bound from the
  // inputs' degrees and R's.
  const PiecewiseShape ts = composed_shape(T, S);
  const auto cuts = union_cuts(ts, shape_of(R), domain_box(S));
  const auto bound = identity_bound(ts, shape_of(R));
  acc.add(prove_by_samples(cuts, bound,
                           [&](const std::vector<Rational>& x) {
                             return evaluate(R, x) == evaluate(T, evaluate(S, x)) ? std::string()
                                                                                 : std::string("R(r) != T(S(r))");
                           },
                           "", SampleEnds{true, true}),
          i);
}

void compose_trimmed(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  // Curves, surfaces and trivariates on both sides (trimmed trivariates: k = n = 3;
  // surfaces into trivariates: k = 2, n = 3).
  const int n = pick(1, 3), k = pick(1, 3);
  RandomSplineSpec outer_spec, inner_spec;
  for (int j = 0; j < n; ++j) {
    outer_spec.degrees.push_back(pick(1, n == 3 ? 2 : 3));
    outer_spec.counts.push_back(outer_spec.degrees.back() + 1 + pick(1, n == 3 ? 2 : 3));
  }
  outer_spec.q = pick(1, 3);
  outer_spec.rational = pick(0, 2) == 0;
  const bool affine = pick(0, 2) == 0;
  for (int l = 0; l < k; ++l) {
    inner_spec.degrees.push_back(affine || k == 3 ? 1 : pick(1, 2));
    inner_spec.counts.push_back(inner_spec.degrees.back() + 1 + (affine || k == 3 ? 0 : pick(0, 1)));
  }
  inner_spec.q = n;
  inner_spec.rational = !affine && pick(0, 3) == 0;
  const BSpline<Rational> T = random_spline(outer_spec, rng);
  BSpline<Rational> S = random_spline(inner_spec, rng);
  for (auto& x : S.points) x = (x + 2) / 4;  // [-2, 2] -> [0, 1], T's domain
  if (affine) {
    // Degree 1 and no interior knots per direction: make the map affine (not just
    // multilinear), P_i = P_0 + sum_l i_l (P_{e_l} - P_0), scaled to stay in [0, 1].
    std::vector<std::size_t> unit(k);
    std::size_t st = 1;
    for (int l = 0; l < k; ++l) { unit[l] = st; st *= 2; }
    for (std::size_t g = 0; g < S.size(); ++g)
      for (int c = 0; c < n; ++c) {
        Rational v = S.points[c];
        for (int l = 0; l < k; ++l)
          if ((g / unit[l]) % 2) v += (S.points[unit[l] * n + c] - S.points[c]) / k;
        if (g != 0 && __builtin_popcountll(g) > 1) S.points[g * n + c] = v;
      }
    for (int l = 0; l < k; ++l)
      for (int c = 0; c < n; ++c)
        S.points[unit[l] * n + c] = S.points[c] + (S.points[unit[l] * n + c] - S.points[c]) / k;
  }
  auto C = compose_trimmed(T, S);
  for (auto& patch : C.patches) patch.patch.net = planted(patch.patch.net);
  std::size_t checked = 0;
  auto check = [&](const std::vector<Rational>& r) -> bool {
    ++checked;
    const std::size_t piece = C.locate_piece(r);
    std::size_t owners = 0;
    for (const auto& p : C.patches)
      if (p.inner_piece == piece && C.in_region(p, r)) ++owners;
    if (owners != 1) {
      acc.fail(std::to_string(owners) + " regions own a point", i);
      return false;
    }
    if (C.evaluate(r) != evaluate(T, evaluate(S, r))) {
      acc.fail("R(r) != T(S(r))", i);
      return false;
    }
    return true;
  };
  // Grid points over S's domain, and bisection across every cell change between neighbours.
  const int G = k == 3 ? 6 : 13;
  std::vector<int> idx(k, 0);
  auto point = [&](const std::vector<int>& id) {
    std::vector<Rational> r(k);
    for (int l = 0; l < k; ++l) r[l] = S.domain_lo(l) + (S.domain_hi(l) - S.domain_lo(l)) * Rational(id[l], G - 1);
    return r;
  };
  bool ok = true;
  while (ok) {
    const auto r = point(idx);
    ok = check(r);
    for (int l = 0; l < k && ok; ++l) {
      if (idx[l] + 1 == G) continue;
      auto id2 = idx;
      ++id2[l];
      std::vector<Rational> a = r, b = point(id2);
      auto owner = [&](const std::vector<Rational>& x) { return C.locate(x); };
      if (owner(a) == owner(b)) continue;
      for (int it = 0; it < 40; ++it) {
        std::vector<Rational> m(k);
        for (int e = 0; e < k; ++e) m[e] = (a[e] + b[e]) / 2;
        (owner(m) == owner(a) ? a : b) = m;
      }
      ok = check(a) && check(b);
    }
    int l = 0;
    while (l < k && ++idx[l] == G) { idx[l] = 0; ++l; }
    if (l == k) break;
  }
  // Affine S: points exactly on knot lines (and, k = n = 2, at their crossings).
  if (ok && affine) {
    for (int j = 0; j < n && ok; ++j)
      for (const auto& u : breakpoints(T.knots[j], T.degrees[j], T.count(j))) {
        // s_j(r) = u along r_0 with the other parameters at their domain middle.
        std::vector<Rational> r(k);
        for (int l = 0; l < k; ++l) r[l] = (S.domain_lo(l) + S.domain_hi(l)) / 2;
        auto at = [&](const Rational& t) { r[0] = t; return evaluate(S, r)[j]; };
        const Rational a0 = at(S.domain_lo(0)), a1 = at(S.domain_hi(0));
        if (a0 == a1 || (u - a0) * (u - a1) > 0) continue;
        r[0] = S.domain_lo(0) + (u - a0) / (a1 - a0) * (S.domain_hi(0) - S.domain_lo(0));
        if (evaluate(S, r)[j] != u) { acc.fail("on-curve point is not on the knot line", i); ok = false; break; }
        ok = check(r);
      }
    if (ok && k == 2 && n == 2) {
      // Corners: S(r) = (u, v) solved exactly for every pair of breakpoints inside S's image.
      const Rational x0 = S.domain_lo(0), x1 = S.domain_hi(0), y0 = S.domain_lo(1), y1 = S.domain_hi(1);
      const auto s00 = evaluate(S, {x0, y0}), s10 = evaluate(S, {x1, y0}), s01 = evaluate(S, {x0, y1});
      const Rational a = s10[0] - s00[0], b = s01[0] - s00[0], c = s10[1] - s00[1], d = s01[1] - s00[1];
      const Rational det = a * d - b * c;
      if (det != 0)
        for (const auto& u : breakpoints(T.knots[0], T.degrees[0], T.count(0)))
          for (const auto& v : breakpoints(T.knots[1], T.degrees[1], T.count(1))) {
            const Rational du = u - s00[0], dv = v - s00[1];
            const Rational s = (d * du - b * dv) / det, t = (a * dv - c * du) / det;
            if (s < 0 || s > 1 || t < 0 || t > 1) continue;
            const std::vector<Rational> r{x0 + s * (x1 - x0), y0 + t * (y1 - y0)};
            if (evaluate(S, r) != std::vector<Rational>{u, v}) { acc.fail("corner point misses the crossing", i); ok = false; break; }
            if (!(ok = check(r))) break;
          }
    }
  }
  acc.rep.points += checked;
}

void trimming_endpoints(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  RandomSplineSpec outer_spec, inner_spec;
  outer_spec.degrees = {pick(1, 3), pick(1, 3)};
  outer_spec.counts = {static_cast<std::size_t>(outer_spec.degrees[0] + 1 + pick(1, 3)), static_cast<std::size_t>(outer_spec.degrees[1] + 1 + pick(1, 3))};
  outer_spec.q = 3;
  inner_spec.degrees = {pick(1, 3), pick(1, 3)};
  inner_spec.counts = {static_cast<std::size_t>(inner_spec.degrees[0] + 1), static_cast<std::size_t>(inner_spec.degrees[1] + 1)};
  inner_spec.q = 2;
  inner_spec.rational = pick(0, 2) == 0;
  const auto T = random_spline(outer_spec, rng);
  auto S = random_spline(inner_spec, rng);
  for (auto& x : S.points) x = (x + 2) / 4;
  const auto C = compose_trimmed(T, S);
  for (std::size_t pi = 0; pi < C.patches.size(); ++pi) {
    const auto& P = C.patches[pi];
    const auto X = trimming_edge_crossings(C, pi);
    auto f = [&](const EdgeCrossing& e, const Rational& t) -> Rational {  // not an expression template
      std::vector<Rational> r = e.fixed;
      r[e.free_dir] = t;
      const auto& cond = P.region[e.condition];
      return evaluate(S, r)[cond.coord] - (e.at_upper_bound ? cond.hi : cond.lo);
    };
    for (const auto& e : X) {
      const Rational a = f(e, e.root.lo), b = f(e, e.root.hi);
      const bool ok = e.root.lo == e.root.hi ? a == 0 : (e.root.multiplicity % 2 == 0 || a * b < 0);
      if (!ok) acc.fail("an isolating interval has no certificate", i);
      acc.rep.points += 2;
    }
    // Completeness along each edge and condition: 65 samples.
    for (int free = 0; free < 2; ++free)
      for (int side = 0; side < 2; ++side)
        for (std::size_t ci = 0; ci < P.region.size(); ++ci)
          for (bool upper : {false, true}) {
            const auto& cond = P.region[ci];
            if ((upper && !cond.check_hi) || (!upper && !cond.check_lo)) continue;
            EdgeCrossing probe;
            probe.condition = static_cast<int>(ci);
            probe.at_upper_bound = upper;
            probe.free_dir = free;
            probe.fixed.assign(2, Rational(0));
            probe.fixed[1 - free] = side ? S.domain_hi(1 - free) : S.domain_lo(1 - free);
            const Rational lo = S.domain_lo(free), w = S.domain_hi(free) - lo;
            Rational prev_t = lo, prev = f(probe, lo);
            for (int s = 1; s <= 64; ++s) {
              const Rational t = lo + w * Rational(s, 64), v = f(probe, t);
              if ((prev < 0 && v > 0) || (prev > 0 && v < 0)) {
                bool covered = false;
                for (const auto& e : X)
                  covered = covered || (e.condition == probe.condition && e.at_upper_bound == upper &&
                                        e.free_dir == free && e.fixed[1 - free] == probe.fixed[1 - free] &&
                                        !(e.root.hi < prev_t) && !(t < e.root.lo));
                if (!covered) acc.fail("a sign change along an edge has no isolated root", i);
              }
              prev = v;
              prev_t = t;
            }
          }
  }
}

}  // namespace

std::vector<ProofEntry> composition_proofs() {
  return {
      entry("compose-methods-agree",
            "Bezier composition T(S) by symbolic Bernstein products (Elber) = by exact interpolation, "
            "coefficient for coefficient; degrees d_l * sum e_j",
            "none (coefficient equality)",
            compose_methods_agree, own_inputs),
      entry("compose-identity",
            "R(r) = T(S(r)) for the composed Bezier piece R, T evaluated pointwise (also outside its box, "
            "Observation 1)",
            "D_l = d_l * sum e_j per direction (2 D_l for rational: cross-multiplied)",
            compose_identity, own_inputs),
      entry("compose-bspline",
            "R(r) = T(S(r)) for B-splines T and S whose pieces meet T's knot lines only along S's own "
            "knots (each piece of S in one piece of T), R joined from the composed pieces; T and S continuous "
            "or discontinuous (C^-1 knots where T jumps, inner pieces that jump within a cell)",
            "max(D_l + den R, deg R + den T(S)) per direction, D_l = d_l * sum e_j (from the inputs)",
            compose_bspline, own_inputs),
      entry("compose-trimmed",
            "Algorithm 1 across knot lines (curves, surfaces, trivariates; inner and outer dimension 1-3): "
            "R(r) = T(S(r)) (Definition 1) and exactly one region owns r "
            "(property 2), at grid points, on both sides of trimming curves within 2^-40, and (affine S) "
            "exactly on knot lines and at their crossings",
            "none: pointwise exact checks only (R is piecewise by semi-algebraic regions; no identity argument "
            "covers the regions' boundaries), so the verdict is 'checked at N points'",
            compose_trimmed, own_inputs_sampled),
  };
}

std::vector<ProofEntry> trimming_end_point_proofs() {
  return {
      entry("trimming-endpoints",
            "every isolated crossing of a trimming curve with an inner piece's edge (CGAL root isolation) is "
            "certified (exact rational root on the knot line, or a sign change of s_c - u at the interval's "
            "ends; roots of even multiplicity are taken from CGAL's isolation without a sign certificate), and "
            "completeness is sampled: every sign change between 65 points per edge lies in a reported interval. "
            "Sampled, not proved: a pair of crossings between two samples is not seen",
            "none (certificates checked exactly; completeness at 65 samples per edge)",
            trimming_endpoints, own_inputs_sampled),
  };
}

}  // namespace splinex::proof_detail
