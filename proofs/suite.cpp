#include "proofs/suite.hpp"
#include "proofs/suite_detail.hpp"

#include <algorithm>
#include <random>

#include "exact/bpt.hpp"
#include "exact/flint_rational.hpp"
#include "exact/random_spline.hpp"
#include "exact/root_isolation.hpp"
#include "spline/hodograph.hpp"
#include "spline/untrim_integrate.hpp"
#include "untrim/algorithm2.hpp"
#include "untrim/curved.hpp"
#include "untrim/polygon.hpp"
#include "spline/kernel.hpp"

namespace splinex {

namespace proof_detail {

namespace {
PlantedBug& planted_bug() {
  static PlantedBug bug;
  return bug;
}
}  // namespace

ScopedPlantedBug::ScopedPlantedBug(PlantedBug bug) : previous_(std::move(planted_bug())) { planted_bug() = std::move(bug); }
ScopedPlantedBug::~ScopedPlantedBug() { planted_bug() = std::move(previous_); }

BSpline<Rational> planted(BSpline<Rational> R) {
  if (planted_bug()) planted_bug()(R);
  return R;
}

// Aggregates the identity checks of one named proof over its cases.
void Accumulator::add(const IdentityCheck& c, std::size_t case_no) {
  rep.points += c.points;
  rep.cells += c.cells;
  for (int b : c.degree_bound) max_bound = std::max(max_bound, b);
  if (!c.holds && rep.holds) {
    rep.holds = false;
    rep.counterexample = "case " + std::to_string(case_no) + ": " + c.counterexample;
  }
  if (!c.decided()) undecided("an identity check had no cell to compare (an empty or inverted box)", case_no);
}

void Accumulator::fail(const std::string& why, std::size_t case_no) {
  if (rep.holds) {
    rep.holds = false;
    rep.counterexample = "case " + std::to_string(case_no) + ": " + why;
  }
}

void Accumulator::undecided(const std::string& why, std::size_t case_no) {
  if (rep.undecided.empty()) rep.undecided = "case " + std::to_string(case_no) + ": " + why;
}

void Accumulator::structures(const std::vector<std::string>& tags) {
  for (const auto& t : tags)
    if (std::find(rep.structures.begin(), rep.structures.end(), t) == rep.structures.end()) rep.structures.push_back(t);
}

void compare_nets(Accumulator& acc, const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& what,
                  std::size_t case_no) {
  const bool same = A.degrees == B.degrees && A.knots == B.knots && A.q == B.q && A.points == B.points &&
                    A.weights == B.weights;
  if (!same) return acc.fail(what, case_no);
  std::size_t n = A.points.size() + A.weights.size();
  for (const auto& K : A.knots) n += K.size();
  acc.compared(n);
}

ProofEntry entry(std::string name, std::string identity, std::string bound, CaseFn fn, std::uint64_t seed,
                 EntryOptions options) {
  ProofEntry e;
  e.name = name;
  e.identity = identity;
  e.run = [=](std::size_t cases) {
    Accumulator acc;
    acc.rep.name = name;
    acc.rep.identity = identity;
    acc.rep.expect_proved = options.expect_proved;
    acc.rep.sampled = options.sampled;
    std::mt19937_64 rng(seed);
    for (std::size_t i = 0; i < cases; ++i) {
      const StructuredCase c = structured_case(rng);
      if (options.uses_case) acc.structures(c.structures);
      fn(c.spline, rng, acc, i);
      ++acc.rep.cases;
    }
    if (cases == 0) acc.rep.undecided = "no case was run (--cases 0)";
    else if (acc.rep.points == 0) acc.rep.undecided = "nothing was compared";
    acc.rep.degree_bound = bound + ", largest used: " + std::to_string(acc.max_bound);
    return acc.rep;
  };
  return e;
}

}  // namespace proof_detail

namespace {

using proof_detail::Accumulator;
using proof_detail::entry;


int random_dir(const BSpline<Rational>& S, std::mt19937_64& rng) {
  return static_cast<int>(std::uniform_int_distribution<int>(0, S.dim() - 1)(rng));
}

// A random knot to insert in direction d and how often it may go in: up to multiplicity p+1 (a
// C^-1 knot), so insertion is proved on discontinuous results too.
std::pair<Rational, int> random_knot(const BSpline<Rational>& S, int d, std::mt19937_64& rng) {
  const auto& U = S.knots[d];
  const int p = S.degrees[d];
  // Half the time reuse an existing interior knot, else a fresh value.
  std::vector<Rational> interior;
  for (std::size_t i = p + 1; i < S.count(d); ++i)
    if (multiplicity(U, U[i]) < static_cast<std::size_t>(p) + 1) interior.push_back(U[i]);
  Rational x = (!interior.empty() && rng() % 2) ? interior[rng() % interior.size()]
                                                 : random_inside(S.domain_lo(d), S.domain_hi(d), rng);
  const int room = p + 1 - static_cast<int>(multiplicity(U, x));
  if (room <= 0) return {x, 0};  // already of multiplicity p+1 (degree 0: every knot)
  return {x, 1 + static_cast<int>(rng() % room)};
}

// The knots of X that can go into direction d together: each value at most up to multiplicity
// p+1 (degree 0 takes only new values, once).
std::vector<Rational> legal_insertions(const BSpline<Rational>& S, int d, const std::vector<Rational>& X) {
  std::vector<Rational> out;
  for (const auto& x : X) {
    const std::size_t have = multiplicity(S.knots[d], x) + static_cast<std::size_t>(std::count(out.begin(), out.end(), x));
    if (have < static_cast<std::size_t>(S.degrees[d]) + 1) out.push_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}

using proof_detail::compare_nets;
using proof_detail::planted;

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

std::vector<ProofEntry> make_registry() {
  std::vector<ProofEntry> r;
  const std::string same = "max(p, p') per direction (p' p for rational: cross-multiplied numerators)";
  r.push_back(entry("knot-insertion-boehm", "S with a knot inserted r times (A5.1) = S on the whole domain", same,
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      auto [x, times] = random_knot(S, d, rng);
                      acc.add(prove_same_function(S, planted(insert_knot(S, d, x, times)), ""), i);
                    }, 101));
  r.push_back(entry("knot-refinement-a54", "S refined by a knot list in one pass (A5.4) = S", same,
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      std::vector<Rational> X;
                      const std::size_t nx = 1 + rng() % 8;
                      for (std::size_t j = 0; j < nx; ++j) X.push_back(random_inside(S.domain_lo(d), S.domain_hi(d), rng));
                      X.push_back(X.front());  // a repeated knot
                      X = legal_insertions(S, d, X);
                      acc.add(prove_same_function(S, planted(refine_knots(S, d, X)), ""), i);
                    }, 102));
  r.push_back(entry("insertion-agreement", "A5.1 applied knot by knot and A5.4 give identical knots and control points",
                    "none (coefficient equality)",
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      std::vector<Rational> X;
                      for (std::size_t j = 0; j < 1 + rng() % 6; ++j) X.push_back(random_inside(S.domain_lo(d), S.domain_hi(d), rng));
                      BSpline<Rational> B = S;
                      X = legal_insertions(S, d, X);
                      for (const auto& x : X) B = insert_knot(B, d, x, 1);
                      compare_nets(acc, B, planted(refine_knots(S, d, X)), "the control nets differ", i);
                    }, 103));
  r.push_back(entry("degree-elevation-a59", "S elevated by t in a direction (A5.9, via Bezier pieces) = S", "p + t per direction",
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      const int t = 1 + static_cast<int>(rng() % 3);
                      acc.add(prove_same_function(S, planted(elevate_degree(S, d, t, ElevationMethod::bezier_pieces)), ""), i);
                    }, 104));
  r.push_back(entry("degree-elevation-blossom", "S elevated by t (blossom / Cohen-Lyche-Schumaker) = S", "p + t per direction",
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      const int t = 1 + static_cast<int>(rng() % 3);
                      acc.add(prove_same_function(S, planted(elevate_degree(S, d, t, ElevationMethod::blossom)), ""), i);
                    }, 105));
  r.push_back(entry("elevation-agreement", "A5.9 and the blossom elevation give identical knots and control points",
                    "none (coefficient equality)",
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      const int t = 1 + static_cast<int>(rng() % 3);
                      compare_nets(acc, elevate_degree(S, d, t, ElevationMethod::bezier_pieces),
                                   planted(elevate_degree(S, d, t, ElevationMethod::blossom)), "the control nets differ", i);
                    }, 106));
  r.push_back(entry("bezier-extraction", "every Bezier piece = S on its box, and the boxes tile the domain", same,
                    [](const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
                      const auto pieces = extract_bezier(S);
                      // Tiling: the boxes are exactly the products of consecutive breakpoints of S
                      // (from the input), each once, direction 0 fastest.
                      std::vector<std::vector<Rational>> bp;
                      std::size_t expected = 1;
                      for (int d = 0; d < S.dim(); ++d) {
                        bp.push_back(breakpoints(S.knots[d], S.degrees[d], S.count(d)));
                        expected *= bp.back().size() - 1;
                      }
                      if (pieces.size() != expected) acc.fail("wrong number of pieces", i);
                      for (std::size_t k = 0; k < std::min(expected, pieces.size()); ++k) {
                        std::size_t rem = k;
                        std::vector<std::pair<Rational, Rational>> box;
                        for (int d = 0; d < S.dim(); ++d) {
                          const std::size_t c = rem % (bp[d].size() - 1);
                          rem /= bp[d].size() - 1;
                          box.emplace_back(bp[d][c], bp[d][c + 1]);
                        }
                        if (pieces[k].box != box) acc.fail("piece " + std::to_string(k) + " has the wrong box", i);
                        acc.compared(1);
                      }
                      for (const auto& pc : pieces) {
                        for (int d = 0; d < S.dim(); ++d)
                          if (!is_clamped(pc.spline.knots[d], pc.spline.degrees[d], pc.spline.count(d)) ||
                              pc.spline.count(d) != static_cast<std::size_t>(pc.spline.degrees[d]) + 1)
                            acc.fail("a piece is not in Bezier form", i);
                        acc.add(prove_equal_on_box(S, planted(pc.spline), pc.box, {}, ""), i);
                      }
                    }, 107));
  r.push_back(entry("split", "the two halves of S at x equal S on [lo, x] and [x, hi]", same,
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      const Rational x = random_inside(S.domain_lo(d), S.domain_hi(d), rng);
                      auto [L0, R0] = split_at(S, d, x);
                      const auto L = planted(L0), R = planted(R0);
                      auto bl = domain_box(S), br = domain_box(S);
                      bl[d].second = x;
                      br[d].first = x;
                      if (domain_box(L) != bl || domain_box(R) != br) acc.fail("the halves have the wrong domains", i);
                      acc.add(prove_equal_on_box(S, L, bl, {}, ""), i);
                      acc.add(prove_equal_on_box(S, R, br, {}, ""), i);
                    }, 108));
  r.push_back(entry("reparametrize", "R(phi(x)) = S(x), phi affine from the domain onto [lo, hi]", same,
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      const Rational lo(static_cast<long>(rng() % 2001) - 1000, 7), hi = lo + Rational(1 + rng() % 50, 3);
                      const BSpline<Rational> R = planted(reparametrize(S, d, lo, hi));
                      std::vector<AffineMap1> phi(S.dim());
                      phi[d].scale = (hi - lo) / (S.domain_hi(d) - S.domain_lo(d));
                      phi[d].shift = lo - phi[d].scale * S.domain_lo(d);
                      acc.add(prove_equal_on_box(S, R, domain_box(S), phi, ""), i);
                    }, 109));
  r.push_back(entry("reverse", "R(a + b - x) = S(x) on the open cells of the domain [a, b] (where S jumps, R takes the "
                    "other one-sided value), and reverse(reverse(S)) = S exactly", same,
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const int d = random_dir(S, rng);
                      std::vector<AffineMap1> phi(S.dim());
                      phi[d].scale = -1;
                      phi[d].shift = S.domain_lo(d) + S.domain_hi(d);
                      acc.add(prove_equal_on_box(S, planted(reverse(S, d)), domain_box(S), phi, ""), i);
                      // And reversing twice gives S back, coefficient for coefficient.
                      compare_nets(acc, reverse(reverse(S, d), d), S, "reverse(reverse(S)) != S", i);
                    }, 110));
  r.push_back(entry("clamp", "S with clamped end knots in every direction = S on the domain", same,
                    [](const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
                      acc.add(prove_same_function(S, planted(clamp_all(S)), ""), i);
                    }, 111));
  r.push_back(entry("derivative-hodograph",
                    "dS/dx_d by A2.3 basis derivatives = the hodograph B-spline (A3.3) of polynomial S",
                    "p - 1 per direction d, p elsewhere",
                    [](const BSpline<Rational>& S0, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      BSpline<Rational> S = S0;
                      S.weights.clear();  // polynomial version of the case
                      std::vector<int> dirs;  // directions of degree >= 1 (degree 0 has no hodograph)
                      for (int e = 0; e < S.dim(); ++e)
                        if (S.degrees[e] > 0) dirs.push_back(e);
                      if (dirs.empty()) return;
                      const int d = dirs[rng() % dirs.size()];
                      const BSpline<Rational> H = planted(hodograph(S, d));
                      std::vector<int> orders(S.dim(), 0);
                      orders[d] = 1;
                      // Cells: both sides' breakpoints; bound: the larger of both sides' degrees (dS/dx_d
                      // from the input: p - 1 in d, p elsewhere; H: its own degrees).
                      PiecewiseShape dS = shape_of(S);
                      dS.numerator[d] = std::max(0, S.degrees[d] - 1);
                      const auto cuts = union_cuts(dS, shape_of(H), domain_box(S));
                      const auto bound = identity_bound(dS, shape_of(H));
                      acc.add(prove_by_samples(cuts, bound,
                                               [&](const std::vector<Rational>& x) {
                                                 return derivative(S, x, orders) == evaluate(H, x)
                                                            ? std::string()
                                                            : std::string("A2.3 and the hodograph differ");
                                               },
                                               "", SampleEnds{true, true}),
                              i);
                    }, 112));
  r.push_back(entry("evaluation-deboor",
                    "de Boor's algorithm (A3.1, direction by direction) = the basis-function sum (A2.2), exactly",
                    "p per direction (2p for rational: cross-multiplied)",
                    [](const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
                      const BSpline<Rational> Sd = planted(S);  // the spline de Boor's triangle evaluates
                      // Both sides' cells and degrees (the same spline unless a bug is planted).
                      const auto cuts = union_cuts(shape_of(S), shape_of(Sd), domain_box(S));
                      const auto bound = identity_bound(shape_of(S), shape_of(Sd));
                      acc.add(prove_by_samples(cuts, bound,
                                               [&](const std::vector<Rational>& x) {
                                                 return evaluate(S, x) == evaluate_de_boor(Sd, x)
                                                            ? std::string()
                                                            : std::string("A2.2 and de Boor differ");
                                               },
                                               "", SampleEnds{true, true}),
                              i);
                    }, 114));
  {
    // Random Bezier compositions: inner S: R^k -> R^n, outer T: R^n -> R^q, rational or not.
    auto random_composition = [](std::mt19937_64& rng, bool inside) {
      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
      const int k = pick(1, 3), n = pick(1, 3);
      RandomSplineSpec si, so;
      for (int l = 0; l < k; ++l) {
        si.degrees.push_back(pick(1, k == 3 ? 1 : 2));
        si.counts.push_back(si.degrees.back() + 1);
      }
      for (int j = 0; j < n; ++j) {
        so.degrees.push_back(pick(1, n == 3 ? 2 : 3));
        so.counts.push_back(so.degrees.back() + 1);
      }
      si.q = n;
      so.q = pick(1, 3);
      si.rational = pick(0, 2) == 0;
      so.rational = pick(0, 2) == 0;
      BSpline<Rational> S = random_spline(si, rng), T = random_spline(so, rng);
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
    };
    r.push_back(entry("compose-methods-agree",
                      "Bezier composition T(S) by symbolic Bernstein products (Elber) = by exact interpolation, "
                      "coefficient for coefficient; degrees d_l * sum e_j",
                      "none (coefficient equality)",
                      [random_composition](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                        const auto [T, S] = random_composition(rng, false);
                        const auto A = compose_bezier(T, S, CompositionMethod::symbolic);
                        const auto B = planted(compose_bezier(T, S, CompositionMethod::interpolation));
                        if (A.degrees != composed_degrees(T, S)) acc.fail("wrong composed degrees", i);
                        compare_nets(acc, A, B, "the two composition methods differ", i);
                      }, 115, {true, false, false}));
    r.push_back(entry("compose-identity",
                      "R(r) = T(S(r)) for the composed Bezier piece R, T evaluated pointwise (also outside its box, "
                      "Observation 1)",
                      "D_l = d_l * sum e_j per direction (2 D_l for rational: cross-multiplied)",
                      [random_composition](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
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
                      }, 116, {true, false, false}));
  }
  r.push_back(entry("compose-bspline",
                    "R(r) = T(S(r)) for B-splines T and S whose pieces meet T's knot lines only along S's own "
                    "knots (each piece of S in one piece of T), R joined from the composed pieces; T and S continuous "
                    "or discontinuous (C^-1 knots where T jumps, inner pieces that jump within a cell)",
                    "max(D_l + den R, deg R + den T(S)) per direction, D_l = d_l * sum e_j (from the inputs)",
                    [](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
                      const int n = pick(1, 2);
                      RandomSplineSpec so;
                      for (int j = 0; j < n; ++j) {
                        so.degrees.push_back(pick(0, 3));
                        so.counts.push_back(so.degrees.back() + 1 + pick(0, 2));
                      }
                      so.q = pick(1, 3);
                      so.rational = pick(0, 2) == 0;
                      BSpline<Rational> T = random_spline(so, rng);
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
                    }, 117, {true, false, false}));
  r.push_back(entry("compose-trimmed",
                    "Algorithm 1 across knot lines (curves, surfaces, trivariates; inner and outer dimension 1-3): "
                    "R(r) = T(S(r)) (Definition 1) and exactly one region owns r "
                    "(property 2), at grid points, on both sides of trimming curves within 2^-40, and (affine S) "
                    "exactly on knot lines and at their crossings",
                    "none: pointwise exact checks only (R is piecewise by semi-algebraic regions; no identity argument "
                    "covers the regions' boundaries), so the verdict is 'checked at N points'",
                    [](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
                      // Curves, surfaces and trivariates on both sides (trimmed trivariates: k = n = 3;
                      // surfaces into trivariates: k = 2, n = 3).
                      const int n = pick(1, 3), k = pick(1, 3);
                      RandomSplineSpec so, si;
                      for (int j = 0; j < n; ++j) {
                        so.degrees.push_back(pick(1, n == 3 ? 2 : 3));
                        so.counts.push_back(so.degrees.back() + 1 + pick(1, n == 3 ? 2 : 3));
                      }
                      so.q = pick(1, 3);
                      so.rational = pick(0, 2) == 0;
                      const bool affine = pick(0, 2) == 0;
                      for (int l = 0; l < k; ++l) {
                        si.degrees.push_back(affine || k == 3 ? 1 : pick(1, 2));
                        si.counts.push_back(si.degrees.back() + 1 + (affine || k == 3 ? 0 : pick(0, 1)));
                      }
                      si.q = n;
                      si.rational = !affine && pick(0, 3) == 0;
                      const BSpline<Rational> T = random_spline(so, rng);
                      BSpline<Rational> S = random_spline(si, rng);
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
                      for (auto& patch : C.patches) patch.patch = planted(patch.patch);
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
                    }, 118, {true, false, true}));
  r.push_back(entry("untrim-cover",
                    "Algorithm 2, exact, for affine S in T: the tiles of each inner piece cover its box with no gap and "
                    "no overlap (exact union area by CGAL = box area = sum of tile areas), each region's tiles have the "
                    "area of the region's polygon (the box clipped independently by the region's half-planes), and "
                    "every tile patch R equals T(S(Q)) on its tile",
                    "per tile cell (chain piece x [0, 1]): max(deg R, p_0 + p_1 of T) per direction",
                    [](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
                      auto frac = [&](int lo, int hi, int den) { return Rational(pick(lo, hi), den); };
                      RandomSplineSpec so;
                      so.degrees = {pick(1, 3), pick(1, 3)};
                      so.counts = {static_cast<std::size_t>(so.degrees[0] + 1 + pick(1, 3)), static_cast<std::size_t>(so.degrees[1] + 1 + pick(1, 3))};
                      so.q = 3;
                      const auto T = random_spline(so, rng);
                      // S(r, t) = c + r e1 + t e2, its image inside (0, 1)^2.
                      const Rational c[2] = {frac(100, 250, 1000), frac(100, 250, 1000)};
                      const Rational e1[2] = {frac(300, 600, 1000), frac(-50, 50, 1000)}, e2[2] = {frac(-50, 50, 1000), frac(300, 600, 1000)};
                      BSpline<Rational> S;
                      S.degrees = {1, 1};
                      S.q = 2;
                      S.knots = {{0, 0, 1, 1}, {0, 0, 1, 1}};
                      for (int b = 0; b <= 1; ++b)
                        for (int a = 0; a <= 1; ++a)
                          for (int d = 0; d < 2; ++d) S.points.push_back(c[d] + e1[d] * a + e2[d] * b);
                      auto A = compose_tensor(T, S);
                      for (auto& tile : A.tiles) tile.R = planted(tile.R);
                      if (A.curved_boundaries != 0) acc.fail("a curved trimming curve for affine S", i);
                      // Cover: per inner piece.
                      std::vector<std::vector<Polygon>> polys(A.trimmed.inner_pieces.size());
                      std::vector<Rational> sums(A.trimmed.inner_pieces.size(), Rational(0)), per_patch(A.trimmed.patches.size(), Rational(0));
                      for (const auto& t : A.tiles) {
                        const std::size_t piece = A.trimmed.patches[t.patch].inner_piece;
                        polys[piece].push_back(tile_polygon(t.tile));
                        sums[piece] += t.area;
                        per_patch[t.patch] += t.area;
                      }
                      for (std::size_t k = 0; k < polys.size(); ++k) {
                        const auto& box = A.trimmed.inner_pieces[k].box;
                        const Rational area = (box[0].second - box[0].first) * (box[1].second - box[1].first);
                        const Rational u = polygon_union_area(polys[k]);
                        if (u != area) acc.fail("inner piece " + std::to_string(k) + ": gap of area " + to_fraction_string(Rational(area - u)), i);
                        if (sums[k] != u) acc.fail("inner piece " + std::to_string(k) + ": overlap of area " + to_fraction_string(Rational(sums[k] - u)), i);
                        acc.rep.points += polys[k].size();
                      }
                      // Regions: the box clipped by the region's half-planes s_c >= lo, s_c < hi.
                      for (std::size_t k = 0; k < A.trimmed.patches.size(); ++k) {
                        const auto& p = A.trimmed.patches[k];
                        const Polygon poly = affine_region_polygon(A.trimmed.inner_pieces[p.inner_piece].box, p.region, c, e1, e2);
                        if (per_patch[k] != polygon_area(poly))
                          acc.fail("region " + std::to_string(k) + ": tiles " + to_fraction_string(per_patch[k]) + " vs clipped polygon " +
                                       to_fraction_string(polygon_area(poly)), i);
                      }
                      // R = T(S(Q)) on every tile, by identity on its cells.
                      const int dT = T.degrees[0] + T.degrees[1];
                      for (std::size_t k = 0; k < A.tiles.size(); ++k) {
                        const auto& t = A.tiles[k];
                        // Both sides: T(S(Q)) (Q's cells, degree dT) and R (its own cells and degrees).
                        PiecewiseShape tsq{{t.tile.x, {Rational(0), Rational(1)}}, {dT, dT}, {0, 0}};
                        const auto cuts = union_cuts(tsq, shape_of(t.R), {{t.tile.x.front(), t.tile.x.back()}, {Rational(0), Rational(1)}});
                        acc.add(prove_by_samples(cuts, identity_bound(tsq, shape_of(t.R)),
                                                 [&](const std::vector<Rational>& xl) -> std::string {
                                                   const auto a = A.evaluate_tile(k, xl);
                                                   const auto b = evaluate(T, evaluate(S, evaluate(t.Q, xl)));
                                                   if (a == b) return "";
                                                   return "tile " + std::to_string(k) + " at (" + to_fraction_string(xl[0]) + ", " +
                                                          to_fraction_string(xl[1]) + ")";
                                                 },
                                                 "R = T(S(Q))"),
                                i);
                      }
                    }, 120, {true, false, false}));
  r.push_back(entry("untrim-curved-cover",
                    "exact untrimming of a random lens of two polynomial graph arcs (degrees 2-4) with a triangular "
                    "hole, split by random vertical knot lines and y = 1/2: certify_cover proves the curved tiles cover "
                    "the region (pairwise interior-disjoint, inside, areas add up to Green's area); the tile integrals of "
                    "x^a y^b (a, b <= 2) equal Green's theorem on the loops; every tile patch R equals T(Q) on its tile",
                    "per tile cell (chain piece x [0, 1]): max(deg R, (p_0 + p_1) (d, 1)) per direction",
                    [](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
                      const Rational h(1, 2);
                      const Rational a(pick(1, 3), 20), b(pick(17, 19), 20);
                      // Top arc (right to left) above y = 1/2, bottom arc (left to right) below: interior ordinates
                      // in [3/4, 19/20] and [1/20, 1/4], so they meet only at their shared end points.
                      const int dt = pick(2, 4), db = pick(2, 4);
                      TrimmedDomain D{{0, 0}, {1, 1}, {{{a, h}, {b, h}}}};
                      Polygon bottom, top;
                      for (int j = 1; j < db; ++j) bottom.push_back({a + (b - a) * Rational(j, db), Rational(pick(1, 5), 20)});
                      for (int j = 1; j < dt; ++j) top.push_back({b - (b - a) * Rational(j, dt), Rational(pick(15, 19), 20)});
                      const Rational e(pick(0, 4), 100), f(pick(0, 4), 100);
                      D.loops.push_back({{Rational(2, 5) + e, Rational(9, 20)}, {Rational(3, 5), Rational(9, 20) + f}, {h, Rational(11, 20)}});
                      D.controls = {{bottom, top}, {{}, {}, {}}};
                      validate_domain(D);
                      std::vector<Rational> kx;
                      for (int k = pick(0, 3); k > 0; --k) kx.push_back(Rational(pick(3, 17), 20));
                      std::sort(kx.begin(), kx.end());
                      kx.erase(std::unique(kx.begin(), kx.end()), kx.end());
                      const auto tiles = untrim_curved(D, {kx, {h}});
                      const auto cc = certify_cover(D, tiles);
                      if (!cc.ok) acc.fail("cover: " + cc.failure, i);
                      acc.rep.points += cc.samples + cc.pair_checks + cc.edge_checks;
                      for (int ea = 0; ea <= 2; ++ea)
                        for (int eb = 0; eb <= 2; ++eb) {
                          const auto dens = monomial_density(ea, eb, D);
                          Rational sum = 0;
                          for (const auto& t : tiles) sum += integrate_over_tile(dens, t)[0];
                          if (sum != green_integral(D, dens))
                            acc.fail("integral of x^" + std::to_string(ea) + " y^" + std::to_string(eb) + ": tiles " + to_fraction_string(sum) +
                                         ", Green " + to_fraction_string(green_integral(D, dens)), i);
                        }
                      // T with the knot lines, random small integer control points.
                      const int p0 = pick(1, 3), p1 = pick(1, 2);
                      BSpline<Rational> T;
                      T.degrees = {p0, p1};
                      T.q = 3;
                      std::vector<Rational> U(p0 + 1, Rational(0));
                      U.insert(U.end(), kx.begin(), kx.end());
                      U.insert(U.end(), p0 + 1, Rational(1));
                      std::vector<Rational> W(p1 + 1, Rational(0));
                      W.push_back(h);
                      W.insert(W.end(), p1 + 1, Rational(1));
                      T.knots = {U, W};
                      for (std::size_t k = 0; k < (U.size() - p0 - 1) * (W.size() - p1 - 1) * 3; ++k) T.points.push_back(Rational(pick(-9, 9), 4));
                      validate(T);
                      CompositionOptions co;
                      co.expand = true;
                      for (std::size_t k = 0; k < tiles.size(); ++k) {
                        const auto Q = tile_spline(tiles[k]);
                        const auto R = planted(compose(T, Q, co));
                        const int dT = p0 + p1;
                        // Both sides: T(Q) (Q's cells, degree (dT deg_x Q, dT)) and R (its own).
                        PiecewiseShape tq{{tiles[k].x, {Rational(0), Rational(1)}}, {dT * Q.degrees[0], dT}, {0, 0}};
                        const auto cuts = union_cuts(tq, shape_of(R), {{tiles[k].x.front(), tiles[k].x.back()}, {Rational(0), Rational(1)}});
                        acc.add(prove_by_samples(cuts, identity_bound(tq, shape_of(R)),
                                                 [&](const std::vector<Rational>& xl) -> std::string {
                                                   if (evaluate(R, xl) == evaluate(T, evaluate(Q, xl))) return "";
                                                   return "tile " + std::to_string(k) + " at (" + to_fraction_string(xl[0]) + ", " +
                                                          to_fraction_string(xl[1]) + ")";
                                                 },
                                                 "R = T(Q)"),
                                i);
                      }
                    }, 121, {true, false, false}));
  r.push_back(entry("trimming-endpoints",
                    "every isolated crossing of a trimming curve with an inner piece's edge (CGAL root isolation) is "
                    "certified (exact rational root on the knot line, or a sign change of s_c - u at the interval's "
                    "ends; roots of even multiplicity are taken from CGAL's isolation without a sign certificate), and "
                    "completeness is sampled: every sign change between 65 points per edge lies in a reported interval. "
                    "Sampled, not proved: a pair of crossings between two samples is not seen",
                    "none (certificates checked exactly; completeness at 65 samples per edge)",
                    [](const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
                      RandomSplineSpec so, si;
                      so.degrees = {pick(1, 3), pick(1, 3)};
                      so.counts = {static_cast<std::size_t>(so.degrees[0] + 1 + pick(1, 3)), static_cast<std::size_t>(so.degrees[1] + 1 + pick(1, 3))};
                      so.q = 3;
                      si.degrees = {pick(1, 3), pick(1, 3)};
                      si.counts = {static_cast<std::size_t>(si.degrees[0] + 1), static_cast<std::size_t>(si.degrees[1] + 1)};
                      si.q = 2;
                      si.rational = pick(0, 2) == 0;
                      const auto T = random_spline(so, rng);
                      auto S = random_spline(si, rng);
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
                    }, 119, {true, false, true}));
  r.push_back(entry("flint-agreement",
                    "GMP (Boost mpq) and FLINT (fmpq) give identical knots, points and weights for: knot insertion (A5.1) "
                    "and refinement (A5.4), elevation (A5.9 and blossom), Bezier extraction, split, reparametrization, "
                    "reversal, clamping; and identical values and first derivatives at 3 points per case (not all "
                    "operations: composition, untrimming and the hybrid patch are not compared)",
                    "none (coefficient equality)",
                    [](const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
                      const auto to_f = [](const Rational& x) { return FlintRational(x); };
                      const auto back = [](const BSpline<FlintRational>& F) {
                        return convert<Rational>(F, [](const FlintRational& x) { return x.to_rational(); });
                      };
                      const BSpline<FlintRational> F = convert<FlintRational>(S, to_f);
                      const int d = random_dir(S, rng);
                      const Rational x = random_inside(S.domain_lo(d), S.domain_hi(d), rng), y = to_f(x).to_rational();
                      const FlintRational xf(x);
                      const int t = 1 + static_cast<int>(rng() % 3);
                      const int once = multiplicity(S.knots[d], x) < static_cast<std::size_t>(S.degrees[d]) + 1 ? 1 : 0;
                      compare_nets(acc, insert_knot(S, d, x, once), planted(back(insert_knot(F, d, xf, once))), "insertion differs", i);
                      const auto X2 = legal_insertions(S, d, {x, x});
                      std::vector<FlintRational> X2f;
                      for (const auto& v : X2) X2f.emplace_back(v);
                      compare_nets(acc, refine_knots(S, d, X2), back(refine_knots(F, d, X2f)), "refinement differs", i);
                      compare_nets(acc, elevate_degree(S, d, t), back(elevate_degree(F, d, t)), "A5.9 differs", i);
                      compare_nets(acc, elevate_degree(S, d, t, ElevationMethod::blossom),
                                   back(elevate_degree(F, d, t, ElevationMethod::blossom)), "blossom elevation differs", i);
                      compare_nets(acc, reverse(S, d), back(reverse(F, d)), "reversal differs", i);
                      compare_nets(acc, clamp_all(S), back(clamp_all(F)), "clamping differs", i);
                      compare_nets(acc, reparametrize(S, d, Rational(-1, 3), Rational(7, 5)),
                                   back(reparametrize(F, d, FlintRational(Rational(-1, 3)), FlintRational(Rational(7, 5)))),
                                   "reparametrization differs", i);
                      const auto [L, R] = split_at(S, d, x);
                      const auto [Lf, Rf] = split_at(F, d, xf);
                      compare_nets(acc, L, back(Lf), "split differs (left)", i);
                      compare_nets(acc, R, back(Rf), "split differs (right)", i);
                      if (y != x) acc.fail("a rational changed on its way through FLINT", i);
                      const auto pe = extract_bezier(S);
                      const auto pf = extract_bezier(F);
                      if (pe.size() != pf.size()) acc.fail("extraction gives different piece counts", i);
                      for (std::size_t k = 0; k < std::min(pe.size(), pf.size()); ++k)
                        compare_nets(acc, pe[k].spline, back(pf[k].spline), "extraction differs", i);
                      for (int m = 0; m < 3; ++m) {
                        std::vector<Rational> at;
                        std::vector<FlintRational> atf;
                        std::vector<int> orders(S.dim(), 0);
                        orders[d] = 1;
                        for (int e = 0; e < S.dim(); ++e) {
                          at.push_back(random_inside(S.domain_lo(e), S.domain_hi(e), rng));
                          atf.emplace_back(at.back());
                        }
                        for (const bool deriv : {false, true}) {
                          const auto ve = deriv ? derivative(S, at, orders) : evaluate(S, at);
                          const auto vf = deriv ? derivative(F, atf, orders) : evaluate(F, atf);
                          for (std::size_t c = 0; c < ve.size(); ++c)
                            if (ve[c] != vf[c].to_rational()) acc.fail(deriv ? "derivatives differ" : "values differ", i);
                          acc.compared(ve.size());
                        }
                      }
                    }, 113));
  {
    ProofEntry e;
    e.name = "teapot-merge";
    e.identity = "each merged teapot surface (body, handle, spout, lid) equals its Bezier patches, shifted to their cells";
    e.run = [identity = e.identity](std::size_t) {
      Accumulator acc;
      acc.rep.name = "teapot-merge";
      acc.rep.identity = identity;
      const auto patches = read_bpt(data_path("teapot.bpt"));
      std::size_t case_no = 0;
      for (const auto& t : teapot_surfaces(patches)) {
        for (std::size_t J = 0; J < t.grid.size(); ++J)
          for (std::size_t I = 0; I < t.grid[J].size(); ++I) {
            std::vector<AffineMap1> phi(2);
            phi[0].shift = -Rational(static_cast<long>(I));
            phi[1].shift = -Rational(static_cast<long>(J));
            const std::vector<std::pair<Rational, Rational>> box{{Rational(static_cast<long>(I)), Rational(static_cast<long>(I + 1))},
                                                                {Rational(static_cast<long>(J)), Rational(static_cast<long>(J + 1))}};
            acc.add(prove_equal_on_box(planted(t.surface), patches[t.grid[J][I]], box, phi, ""), case_no);
          }
        ++acc.rep.cases;
        ++case_no;
      }
      acc.rep.degree_bound = "3 per direction (bicubic), largest used: " + std::to_string(acc.max_bound);
      return acc.rep;
    };
    r.push_back(std::move(e));
  }
  for (auto& e : proof_detail::hybrid_proofs()) r.push_back(std::move(e));
  return r;
}

}  // namespace

const std::vector<ProofEntry>& proof_registry() {
  static const std::vector<ProofEntry> registry = make_registry();
  return registry;
}

std::vector<ProofReport> run_proofs(const std::vector<std::string>& names, std::size_t cases) {
  std::vector<ProofReport> out;
  const auto& reg = proof_registry();
  if (names.empty()) {
    for (const auto& e : reg) out.push_back(e.run(cases));
    return out;
  }
  for (const auto& n : names) {
    auto it = std::find_if(reg.begin(), reg.end(), [&](const ProofEntry& e) { return e.name == n; });
    if (it == reg.end()) {
      std::string all;
      for (const auto& e : reg) all += (all.empty() ? "" : ", ") + e.name;
      throw UsageError("prove", "unknown proof \"" + n + "\"", "use one of: " + all);
    }
    out.push_back(it->run(cases));
  }
  return out;
}

}  // namespace splinex
