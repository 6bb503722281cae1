// libFuzzer target over the document readers and every command's core (issue 13).
//
// Input: byte 0 chooses the reader (spline, trimmed domain, hybrid patch, verify candidate) and the
// operation, byte 1 is its small parameter (a direction, an amount, a
// fraction of the domain), the rest is a JSON document. Typed splinex::Error is the expected
// answer to bad input and is swallowed; anything else (another exception, a crash, a leak, an
// ASan/UBSan report, a timeout) is a finding. Exact results are also checked against an
// independent route where one is cheap (insertion by A5.1 vs A5.4, elevation by A5.9 vs the
// blossom, evaluation by A2.2 vs de Boor), so a wrong value is a finding too; the certified
// solver's answers (roots, point projection) are checked exactly against the spline itself.
//
// Build and run: bash scripts/run.sh fuzz [EXECUTIONS] (README, reliability).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

#include "compose/trimmed_compose.hpp"
#include "crosscheck/verify.hpp"
#include "exact/ffnet.hpp"
#include "exact/flint_rational.hpp"
#include "exact/memory.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "hybrid/hybrid.hpp"
#include "io/hybrid_io.hpp"
#include "io/json_io.hpp"
#include "io/trimmed_domain_io.hpp"
#include "solve/projection.hpp"
#include "solve/solver.hpp"
#include "spline/kernel.hpp"
#include "untrim/curved.hpp"
#include "untrim/loops.hpp"

namespace sx = splinex;

namespace {

// Small limits keep each execution short; the limits themselves are part of what is fuzzed.
sx::Limits fuzz_limits() {
  sx::Limits L;
  L.max_control_points = 4000;
  L.max_degree = 12;
  return L;
}

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "splinex fuzz finding: %s\n", what);
  std::abort();
}

// A parameter inside the domain of direction d: lo + (hi - lo) * f / 255.
sx::Rational inside(const sx::BSpline<sx::Rational>& S, int d, std::uint8_t f) {
  return S.domain_lo(d) + (S.domain_hi(d) - S.domain_lo(d)) * sx::Rational(f, 255);
}

// The certified solver (solve/, issue 47) with exact oracles that do not use its Bernstein forms
// (tests/solve/test_planted.cpp shows each certificate refuting a planted bug):
//   curves: the roots of x(t) - c on each Bezier piece (x a coordinate; rational: W x - c W), c =
//     x(t0) at a sample t0 of the piece, so t0 is a known root: it lies in a reported box; a box
//     certified to hold one simple root has x - c of opposite signs (or 0) at its ends; an exact
//     root certified simple has x' != 0 there; no exact root is reported twice;
//   surfaces (no C^-1 knot line): the projection of a point near a control point: every distance
//     enclosure holds the exact squared distance at each corner of its box (surface points by the
//     basis functions), and a certified closest distance is below no sampled surface point (a
//     grid, and the point at the control point's Greville parameters).
// The roots of g (Bernstein form standing for the box [lo, hi]), given a known root x0: x0 lies
// in a reported box, no exact root is reported twice, an exact root certified simple has a
// non-singular Jacobian J(x) (exactly), a box certified to hold one simple root of a univariate
// g has f of opposite signs (or 0) at its ends.
void check_roots(const std::vector<sx::Bernstein<sx::Rational>>& g, const std::vector<sx::Rational>& lo, const std::vector<sx::Rational>& hi,
                 const std::vector<sx::Rational>& x0, const sx::SolveOptions& so,
                 const std::function<sx::Rational(const std::vector<sx::Rational>&)>& det_jacobian,
                 const std::function<sx::Rational(const sx::Rational&)>& f1) {
  const auto r = sx::solve_system(g, lo, hi, so);
  const auto in = [](const std::vector<sx::Rational>& x, const sx::RootBox<sx::Rational>& b) {
    for (std::size_t l = 0; l < x.size(); ++l)
      if (x[l] < b.lo[l] || b.hi[l] < x[l]) return b.exact && b.point == x;
    return true;
  };
  bool known = false;
  for (const auto* list : {&r.roots, &r.undecided})
    for (const auto& b : *list) known = known || in(x0, b);
  if (!known) finding("solve: a known root lies outside every reported box");
  for (std::size_t i = 0; i < r.roots.size(); ++i) {
    const auto& b = r.roots[i];
    if (b.unique && b.exact && det_jacobian(b.point) == 0) finding("solve: a multiple root certified simple");
    if (f1 && b.unique && !b.exact && f1(b.lo[0]) * f1(b.hi[0]) > 0) finding("solve: a box certified to hold one simple root has no sign change");
    for (std::size_t j = 0; j < i; ++j)
      if (b.exact && r.roots[j].exact && b.point == r.roots[j].point) finding("solve: an exact root reported twice");
  }
}

void run_solve(std::uint8_t arg, const sx::BSpline<sx::Rational>& S, const sx::Limits& L) {
  using R = sx::Rational;
  sx::SolveOptions so;
  so.max_depth = 12;
  so.max_boxes = std::size_t(8) << (arg % 4);  // small budgets too: the queue left must stay undecided
  if (S.dim() == 1 && S.degrees[0] >= 1 && S.degrees[0] <= 8 && sx::bezier_pieces_size(S, L) <= 64 * 9) {
    const int co = (arg / 9) % S.q;
    const auto pieces = sx::extract_bezier(S, L);
    for (std::size_t k = 0; k < pieces.size() && k < 8; ++k) {
      const auto& B = pieces[k].spline;
      const R lo = pieces[k].box[0].first, hi = pieces[k].box[0].second;
      const R t0 = lo + (hi - lo) * R(arg % 9, 8);
      const auto f = [&](const R& t) -> R { return sx::evaluate(B, {t})[co]; };
      const R c = f(t0);
      sx::Bernstein<R> g{{B.degrees[0]}, {}};  // (x - c) W in Bernstein form: the weights are positive
      bool zero = true;
      for (std::size_t i = 0; i < B.size(); ++i) {
        g.c.push_back((B.points[i * B.q + co] - c) * (B.is_rational() ? B.weights[i] : R(1)));
        zero = zero && g.c.back() == 0;
      }
      if (zero) continue;  // x constant on the piece: no isolated roots
      check_roots({g}, {lo}, {hi}, {t0}, so, [&](const std::vector<R>& t) -> R { return sx::derivative(B, t, {1})[co]; },
                  [&](const R& t) -> R { return f(t) - c; });
    }
    return;
  }
  if (S.dim() != 2 || S.q < 3 || S.degrees[0] < 1 || S.degrees[1] < 1 || S.degrees[0] > 3 || S.degrees[1] > 3 || S.size() > 25) return;
  for (int d = 0; d < 2; ++d)  // at a jump (C^-1) the point evaluated is one side's only
    for (const auto& x : S.knots[d])
      if (S.domain_lo(d) < x && x < S.domain_hi(d) && std::count(S.knots[d].begin(), S.knots[d].end(), x) > S.degrees[d]) return;
  // Inverse evaluation on a Bezier piece: two coordinates (x, y), (x, z) or (y, z) of S(u, v) equal to
  // those of S(u0, v0) at a sample (u0, v0) of the piece (on its split lines too), in Bernstein form
  // ((x - c) W for a rational surface).
  {
    const auto pieces = sx::extract_bezier(S, L);
    const auto& piece = pieces[arg % pieces.size()];
    const auto& B = piece.spline;
    std::vector<R> lo(2), hi(2), x0(2);
    for (int d = 0; d < 2; ++d) {
      lo[d] = piece.box[d].first;
      hi[d] = piece.box[d].second;
      x0[d] = lo[d] + (hi[d] - lo[d]) * R((arg >> (3 * d)) % 9, 8);
    }
    const auto c = sx::evaluate(B, x0);
    const int coords[3][2] = {{0, 1}, {0, 2}, {1, 2}}, *co = coords[(arg / 81) % 3];
    std::vector<sx::Bernstein<R>> g(2, sx::Bernstein<R>{{B.degrees[0], B.degrees[1]}, {}});
    bool zero[2] = {true, true};
    for (int e = 0; e < 2; ++e)
      for (std::size_t i = 0; i < B.size(); ++i) {
        g[e].c.push_back((B.points[i * B.q + co[e]] - c[co[e]]) * (B.is_rational() ? B.weights[i] : R(1)));
        zero[e] = zero[e] && g[e].c.back() == 0;
      }
    if (!zero[0] && !zero[1]) {
      try {
        check_roots(g, lo, hi, x0, so,
                    [&](const std::vector<R>& x) -> R {
                      const auto du = sx::derivative(B, x, {1, 0}), dv = sx::derivative(B, x, {0, 1});
                      return du[co[0]] * dv[co[1]] - du[co[1]] * dv[co[0]];
                    },
                    {});
      } catch (const sx::ValidationError&) {
        // a degenerate system (an equation identically zero after all): not this oracle's business
      }
    }
  }
  const std::size_t k = arg % S.size();
  const std::vector<R> P{S.points[k * S.q], S.points[k * S.q + 1], S.points[k * S.q + 2] + R(arg % 16, 16)};
  const auto p = sx::project_point<R>(S, P, so, L);
  const auto d2 = [&](const std::vector<R>& uv) -> R {
    const auto x = sx::evaluate(S, uv);
    R s(0);
    for (int c = 0; c < 3; ++c) s += (x[c] - P[c]) * (x[c] - P[c]);
    return s;
  };
  for (const auto* list : {&p.critical, &p.undecided})
    for (const auto& c : *list)
      for (int m = 0; m < 4; ++m) {
        const R v = d2({m & 1 ? c.hi[0] : c.lo[0], m & 2 ? c.hi[1] : c.lo[1]});
        if (v < c.d2_lo || c.d2_hi < v) finding("project: a distance enclosure misses a point of its box");
      }
  if (p.closest_certified) {
    std::vector<std::vector<R>> samples;
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j)
        samples.push_back({S.domain_lo(0) + (S.domain_hi(0) - S.domain_lo(0)) * R(i, 4), S.domain_lo(1) + (S.domain_hi(1) - S.domain_lo(1)) * R(j, 4)});
    std::vector<R> greville(2);  // of control point k: near P
    const std::size_t idx[2] = {k % S.count(0), k / S.count(0)};
    for (int d = 0; d < 2; ++d) {
      for (int m = 1; m <= S.degrees[d]; ++m) greville[d] += S.knots[d][idx[d] + m];
      greville[d] = std::clamp(R(greville[d] / S.degrees[d]), S.domain_lo(d), S.domain_hi(d));
    }
    samples.push_back(greville);
    const R claimed = p.critical[p.closest[0]].d2_lo;  // the point certified closest
    for (const auto& uv : samples)
      if (d2(uv) < p.distance2_lo || d2(uv) < claimed) finding("project: a surface point closer than the certified minimum");
  }
}

void run_spline(std::uint8_t op, std::uint8_t arg, const sx::BSpline<sx::Rational>& S, const sx::Limits& L) {
  const int d = arg % S.dim();
  switch (op % 11) {
    case 0: {  // evaluation: A2.2 against de Boor, exactly
      std::vector<sx::Rational> x;
      for (int k = 0; k < S.dim(); ++k) x.push_back(inside(S, k, static_cast<std::uint8_t>(arg * (k + 7))));
      if (sx::evaluate(S, x) != sx::evaluate_de_boor(S, x)) finding("A2.2 and de Boor differ");
      std::vector<int> ord(S.dim(), 0);
      ord[d] = arg % 3;
      (void)sx::derivative(S, x, ord);
      break;
    }
    case 1: {  // insertion: A5.1 knot by knot against A5.4
      const std::vector<sx::Rational> X{inside(S, d, arg), inside(S, d, static_cast<std::uint8_t>(arg * 3)), inside(S, d, arg)};
      if (sx::insert_knots_boehm(S, d, X, L).points != sx::refine_knots(S, d, X, L).points) finding("A5.1 and A5.4 differ");
      break;
    }
    case 2: {  // elevation: A5.9 against the blossom
      const int t = 1 + arg % 3;
      const auto a = sx::elevate_degree(S, d, t, sx::ElevationMethod::bezier_pieces, L);
      const auto b = sx::elevate_degree(S, d, t, sx::ElevationMethod::blossom, L);
      if (a.points != b.points || a.knots != b.knots) finding("A5.9 and the blossom differ");
      break;
    }
    case 3: (void)sx::extract_bezier(S, L); break;
    case 4: (void)sx::split_at(S, d, inside(S, d, arg), L); break;
    case 5: (void)sx::reverse(sx::reparametrize(S, d, sx::Rational(-1), sx::Rational(arg + 1)), d); break;
    case 6: {  // rounding into double and the float kernel
      const auto F = sx::round_spline<double>(S);
      std::vector<double> x;
      for (int k = 0; k < S.dim(); ++k) x.push_back(sx::to_double(inside(S, k, arg)));
      (void)sx::evaluate(F, x);
      (void)sx::refine_knots(F, d, {sx::to_double(inside(S, d, arg))}, L);
      (void)sx::elevate_degree(F, d, 1, sx::ElevationMethod::blossom, L);
      break;
    }
    case 7: {  // MPFR at a small precision
      sx::Mpfr::Precision scope(24 + arg % 64);
      const auto F = sx::round_spline<sx::Mpfr>(S);
      (void)sx::extract_bezier(F, L);
      break;
    }
    case 8: {  // FLINT and the fraction-free kernel equal GMP exactly
      const auto F = sx::convert<sx::FlintRational>(S, [](const sx::Rational& r) { return sx::FlintRational(r); });
      const auto a = sx::refine_knots(F, d, {sx::FlintRational(inside(S, d, arg))}, L);
      const auto b = sx::refine_knots(S, d, {inside(S, d, arg)}, L);
      if (sx::convert<sx::Rational>(a, [](const sx::FlintRational& r) { return r.to_rational(); }).points != b.points)
        finding("FLINT and GMP differ");
      const auto X = sx::ff::from_bspline(S);
      if (!sx::same_net(sx::ff::to_bspline(sx::ff::refine_knots(X, d, {inside(S, d, arg)}, L)), b))
        finding("the fraction-free insertion and GMP differ");
      const int t = 1 + arg % 2;
      if (!sx::same_net(sx::ff::to_bspline(sx::ff::elevate_degree(X, d, t, L)),
                        sx::elevate_degree(S, d, t, sx::ElevationMethod::bezier_pieces, L)))
        finding("the fraction-free elevation and GMP differ");
      std::vector<sx::Rational> x;
      for (int k = 0; k < S.dim(); ++k) x.push_back(inside(S, k, static_cast<std::uint8_t>(arg * (k + 3))));
      if (sx::ff::to_points(sx::ff::evaluate_points(X, x)) != sx::evaluate(S, x)) finding("the fraction-free value and GMP differ");
      break;
    }
    case 9: {  // composition with itself when the dimensions fit (S o S for curves in R^1)
      sx::CompositionOptions o;
      o.expand = true;
      if (S.q == S.dim()) (void)sx::compose(S, S, o, L);
      break;
    }
    case 10: run_solve(arg, S, L); break;
  }
}

// verify (issue 16) with the document as the candidate. Oracles: a certified bound is never below
// its witness; the candidate judged against its own knot insertion or degree elevation is the same
// function, so its function-level error is exactly 0 (whatever its structure); Algorithm 1's and
// 2's readers take any document as a candidate of a fixed T(S) and answer with a report or a typed
// error.
void run_verify(std::uint8_t arg, const sx::Json& doc, const sx::Limits& L) {
  sx::VerifyOptions vo;
  vo.max_rounds = 4;
  auto check = [](const sx::VerifyReport& rep) {
    if (rep.function.certified && rep.function.upper < rep.function.lower) finding("verify: certified bound below its witness");
    (void)rep.document();
  };
  switch (arg % 4) {
    case 0:
    case 1: {
      const auto C = sx::spline_from_json(arg & 4 ? sx::candidate_numbers_as_doubles(doc) : doc, L);
      sx::Operation op = sx::Operation::parse_kind(arg % 4 == 0 ? "insert-knots" : "elevate");
      op.dir = (arg / 8) % C.dim();
      if (arg % 4 == 0) op.knots = {inside(C, op.dir, static_cast<std::uint8_t>(arg * 5))};
      const auto rep = sx::verify(op, C, {C}, vo, L);
      check(rep);
      if (rep.function.upper != 0) finding("verify: a spline differs from its own refinement or elevation");
      break;
    }
    default: {
      // T: a biquadratic surface with interior knots; S: a curved surface crossing them.
      static const auto T = sx::spline_from_json(
          sx::Json::parse(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, "1/2", 1, 1, 1], [0, 0, 1, 1]],
                               "points": [[0,0,0],[1,0,1],[2,0,0],[3,0,1],[0,1,1],[1,1,3],[2,1,-1],[3,1,2]]})"));
      static const auto S = sx::spline_from_json(
          sx::Json::parse(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, 1, 1, 1], [0, 0, 1, 1]],
                               "points": [["1/10", "1/10"], ["9/10", "1/5"], ["1/5", "3/20"], ["3/20", "9/10"], ["4/5", "7/10"], ["3/10", "19/20"]]})"));
      check(arg % 4 == 2 ? sx::verify_trimmed_composition(T, S, doc, vo, L) : sx::verify_tensor_composition(T, S, doc, vo, L));
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sx::install_throwing_allocators();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::uint8_t op = data[0], arg = data[1];
  const std::string text(reinterpret_cast<const char*>(data) + 2, size - 2);
  const sx::Limits L = fuzz_limits();
  sx::ReadLimits R = sx::ReadLimits::from(L);
  R.max_tree_bytes = std::size_t(64) << 20;
  try {
    std::istringstream in(text);
    const sx::Json doc = sx::read_json(in, "fuzz", R);
    switch (op % 4) {
      case 0: run_spline(op / 4, arg, sx::spline_from_json(doc, L), L); break;
      case 1: {
        const auto D = sx::trimmed_domain_from_json(doc);
        if (op & 8) {
          (void)sx::untrim_domain<double>(D);
        } else {
          const auto tiles = sx::untrim_domain<sx::Rational>(D);
          if (!sx::certify_cover(D, tiles).ok) finding("exact untrimming tiles fail the cover certificate");
        }
        break;
      }
      case 2: {
        const auto P = sx::hybrid_from_json(doc, L);
        const std::array<sx::Rational, 2> x{sx::Rational(arg % 17, 17), sx::Rational(arg / 17, 17)};
        (void)sx::hybrid_evaluate(P, x);
        break;
      }
      case 3: run_verify(arg, doc, L); break;
    }
  } catch (const sx::Error&) {
    // the typed answer to bad input
  }
  return 0;
}
