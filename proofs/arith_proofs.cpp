// The arithmetics agree: GMP and FLINT give identical results on every kernel operation, and the
// fraction-free kernel (exact/ffnet.hpp) gives GMP's results on every operation written for it.
#include <algorithm>
#include <random>

#include "exact/ffnet.hpp"
#include "exact/flint_rational.hpp"
#include "fixtures/random_spline.hpp"
#include "proofs/suite_detail.hpp"
#include "spline/kernel.hpp"

namespace splinex::proof_detail {

namespace {

void flint_agreement(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
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
}

/// The fraction-free kernel against GMP, operation for operation (its results converted back
/// exactly; planted() seams the insertion result, so a planted bug must be refuted here too).
void ff_agreement(const BSpline<Rational>& S, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const ff::FFNet F = ff::from_bspline(S);
  compare_nets(acc, S, ff::to_bspline(F), "the conversion changed the spline", i);
  const int d = random_dir(S, rng);
  const auto [x, room] = random_knot(S, d, rng);
  const int times = room > 0 ? 1 + static_cast<int>(rng() % room) : 0;
  compare_nets(acc, insert_knot(S, d, x, times), planted(ff::to_bspline(ff::insert_knot(F, d, x, times))), "insertion differs", i);
  const auto X = legal_insertions(S, d, {x, x, random_inside(S.domain_lo(d), S.domain_hi(d), rng)});
  compare_nets(acc, refine_knots(S, d, X), ff::to_bspline(ff::refine_knots(F, d, X)), "refinement differs", i);
  const int t = 1 + static_cast<int>(rng() % 3);
  compare_nets(acc, elevate_degree(S, d, t), ff::to_bspline(ff::elevate_degree(F, d, t)), "elevation differs", i);
  compare_nets(acc, clamp(S, d), ff::to_bspline(ff::clamp(F, d)), "clamping differs", i);
  const auto pe = extract_bezier(S);
  const auto pf = ff::extract_bezier(F);
  if (pe.size() != pf.size()) acc.fail("extraction gives different piece counts", i);
  for (std::size_t k = 0; k < std::min(pe.size(), pf.size()); ++k)
    compare_nets(acc, pe[k].spline, ff::to_bspline(pf[k]), "extraction differs", i);
  std::vector<Rational> at;
  for (int m = 0; m < 3; ++m)
    for (int e = 0; e < S.dim(); ++e) at.push_back(random_inside(S.domain_lo(e), S.domain_hi(e), rng));
  const auto ve = evaluate_points(S, at);
  if (ve != ff::to_points(ff::evaluate_points(F, at))) acc.fail("values differ", i);
  acc.compared(ve.size());
}

}  // namespace

std::vector<ProofEntry> arithmetic_proofs() {
  return {
      entry("flint-agreement",
            "GMP (Boost mpq) and FLINT (fmpq) give identical knots, points and weights for: knot insertion (A5.1) "
            "and refinement (A5.4), elevation (A5.9 and blossom), Bezier extraction, split, reparametrization, "
            "reversal, clamping; and identical values and first derivatives at 3 points per case (not all "
            "operations: composition, untrimming and the hybrid patch are not compared)",
            "none (coefficient equality)",
            flint_agreement),
      entry("ff-agreement",
            "the fraction-free kernel (integers over one denominator per point and per knot vector, the "
            "arithmetic `exact`) and GMP give identical knots, points and weights for: knot insertion (A5.1, up "
            "to multiplicity p+1) and refinement (A5.4), elevation (A5.9; by one at p >= 3 its integer blossom, against "
            "GMP's A5.9), clamping, Bezier extraction; and "
            "identical values at 3 points per case (the operations it has; the others run GMP under `exact`)",
            "none (coefficient equality)",
            ff_agreement),
  };
}

}  // namespace splinex::proof_detail
