// The kernel's proofs: knot insertion and refinement, degree elevation, extraction, split,
// reparametrization, reversal, clamping, derivatives and de Boor evaluation, each an identity
// checked on the structured random cases (fixtures/random_spline.hpp).
#include <algorithm>
#include <random>

#include "fixtures/random_spline.hpp"
#include "proofs/suite_detail.hpp"
#include "spline/hodograph.hpp"
#include "spline/kernel.hpp"

namespace splinex::proof_detail {

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

namespace {

void knot_insertion_boehm(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  auto [x, times] = random_knot(S, d, rng);
  acc.add(prove_same_function(S, planted(insert_knot(S, d, x, times)), ""), i);
}

void knot_refinement_a54(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  std::vector<Rational> X;
  const std::size_t nx = 1 + rng() % 8;
  for (std::size_t j = 0; j < nx; ++j) X.push_back(random_inside(S.domain_lo(d), S.domain_hi(d), rng));
  X.push_back(X.front());  // a repeated knot
  X = legal_insertions(S, d, X);
  acc.add(prove_same_function(S, planted(refine_knots(S, d, X)), ""), i);
}

void insertion_agreement(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  std::vector<Rational> X;
  for (std::size_t j = 0; j < 1 + rng() % 6; ++j) X.push_back(random_inside(S.domain_lo(d), S.domain_hi(d), rng));
  BSpline<Rational> B = S;
  X = legal_insertions(S, d, X);
  for (const auto& x : X) B = insert_knot(B, d, x, 1);
  compare_nets(acc, B, planted(refine_knots(S, d, X)), "the control nets differ", i);
}

void degree_elevation_a59(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  const int t = 1 + static_cast<int>(rng() % 3);
  acc.add(prove_same_function(S, planted(elevate_degree(S, d, t, ElevationMethod::bezier_pieces)), ""), i);
}

void degree_elevation_blossom(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  const int t = 1 + static_cast<int>(rng() % 3);
  acc.add(prove_same_function(S, planted(elevate_degree(S, d, t, ElevationMethod::blossom)), ""), i);
}

void elevation_agreement(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  const int t = 1 + static_cast<int>(rng() % 3);
  compare_nets(acc, elevate_degree(S, d, t, ElevationMethod::bezier_pieces),
               planted(elevate_degree(S, d, t, ElevationMethod::blossom)), "the control nets differ", i);
}

void bezier_extraction(const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
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
}

void split(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
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
}

void reparametrize(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  const Rational lo(static_cast<long>(rng() % 2001) - 1000, 7), hi = lo + Rational(1 + rng() % 50, 3);
  const BSpline<Rational> R = planted(reparametrize(S, d, lo, hi));
  std::vector<AffineMap1> phi(S.dim());
  phi[d].scale = (hi - lo) / (S.domain_hi(d) - S.domain_lo(d));
  phi[d].shift = lo - phi[d].scale * S.domain_lo(d);
  acc.add(prove_equal_on_box(S, R, domain_box(S), phi, ""), i);
}

void reverse(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const int d = random_dir(S, rng);
  std::vector<AffineMap1> phi(S.dim());
  phi[d].scale = -1;
  phi[d].shift = S.domain_lo(d) + S.domain_hi(d);
  acc.add(prove_equal_on_box(S, planted(reverse(S, d)), domain_box(S), phi, ""), i);
  // And reversing twice gives S back, coefficient for coefficient.
  compare_nets(acc, reverse(reverse(S, d), d), S, "reverse(reverse(S)) != S", i);
}

void clamp(const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
  acc.add(prove_same_function(S, planted(clamp_all(S)), ""), i);
}

void derivative_hodograph(const BSpline<Rational>& S0, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
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
}

void evaluation_deboor(const BSpline<Rational>& S, std::mt19937_64&, Accumulator& acc, std::size_t i) {
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
}

}  // namespace

std::vector<ProofEntry> kernel_proofs() {
  const std::string same = "max(p, p') per direction (p' p for rational: cross-multiplied numerators)";
  return {
      entry("knot-insertion-boehm",
            "S with a knot inserted r times (A5.1) = S on the whole domain",
            same,
            knot_insertion_boehm),
      entry("knot-refinement-a54",
            "S refined by a knot list in one pass (A5.4) = S",
            same,
            knot_refinement_a54),
      entry("insertion-agreement",
            "A5.1 applied knot by knot and A5.4 give identical knots and control points",
            "none (coefficient equality)",
            insertion_agreement),
      entry("degree-elevation-a59",
            "S elevated by t in a direction (A5.9, via Bezier pieces) = S",
            "p + t per direction",
            degree_elevation_a59),
      entry("degree-elevation-blossom",
            "S elevated by t (blossom / Cohen-Lyche-Schumaker) = S",
            "p + t per direction",
            degree_elevation_blossom),
      entry("elevation-agreement",
            "A5.9 and the blossom elevation give identical knots and control points",
            "none (coefficient equality)",
            elevation_agreement),
      entry("bezier-extraction",
            "every Bezier piece = S on its box, and the boxes tile the domain",
            same,
            bezier_extraction),
      entry("split",
            "the two halves of S at x equal S on [lo, x] and [x, hi]",
            same,
            split),
      entry("reparametrize",
            "R(phi(x)) = S(x), phi affine from the domain onto [lo, hi]",
            same,
            reparametrize),
      entry("reverse",
            "R(a + b - x) = S(x) on the open cells of the domain [a, b] (where S jumps, R takes the "
            "other one-sided value), and reverse(reverse(S)) = S exactly",
            same,
            reverse),
      entry("clamp",
            "S with clamped end knots in every direction = S on the domain",
            same,
            clamp),
      entry("derivative-hodograph",
            "dS/dx_d by A2.3 basis derivatives = the hodograph B-spline (A3.3) of polynomial S",
            "p - 1 per direction d, p elsewhere",
            derivative_hodograph),
      entry("evaluation-deboor",
            "de Boor's algorithm (A3.1, direction by direction) = the basis-function sum (A2.2), exactly",
            "p per direction (2p for rational: cross-multiplied)",
            evaluation_deboor),
  };
}

}  // namespace splinex::proof_detail
