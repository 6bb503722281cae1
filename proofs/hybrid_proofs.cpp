// The hybrid-patch proofs of `splinex prove` (papers/003, issue 5): Theorems 3.1, 3.2 (literal
// and corrected), 4.1, 4.2, and Salvi's original elevation.
#include <algorithm>
#include <random>

#include "fixtures/hybrid_examples.hpp"
#include "proofs/suite_detail.hpp"
#include "hybrid/hybrid.hpp"
#include "hybrid/form.hpp"
#include "spline/kernel.hpp"

namespace splinex::proof_detail {

namespace {
bool& hybrid_bug() {
  static bool on = false;
  return on;
}
}  // namespace

ScopedPlantedHybridBug::ScopedPlantedHybridBug() : previous_(hybrid_bug()) { hybrid_bug() = true; }
ScopedPlantedHybridBug::~ScopedPlantedHybridBug() { hybrid_bug() = previous_; }

namespace {


// The patch (or form) under test, with the planted bug when a test asked for it.
HybridPatch<Rational> planted_patch(HybridPatch<Rational> P) {
  if (hybrid_bug())
    for (int k = 0; k < P.layers(); ++k)
      for (int j = 0; j <= P.d; ++j)
        for (int c = 0; c < P.q; ++c) P.points[P.index(0, j, k) + c] += Rational((k + 1) * (j + 1), 7);
  return P;
}
void plant_form(HybridForm<Rational>& G) {
  if (!hybrid_bug()) return;
  for (auto& x : G.sides[0].interior) x += Rational(1, 7);
  for (auto& x : G.sides[0].P) x += Rational(1, 7);
}

std::string fr(const Rational& x) { return to_fraction_string(x); }

std::string pt(const std::vector<Rational>& v) {
  std::string s = "(";
  for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + fr(v[k]);
  return s + ")";
}

// Restores the shared corner points C^i_{a,b} = C^{i-1}_{d-b,a} after perturbing a patch.
void share_corners(HybridPatch<Rational>& P) {
  const int l = P.layers();
  for (std::size_t s = 0; s < P.sides(); ++s)
    for (int a = 0; a < l; ++a)
      for (int b = 0; b < l; ++b)
        for (int c = 0; c < P.q; ++c) P.points[P.index(s, a, b) + c] = P.points[P.index((s + P.sides() - 1) % P.sides(), P.d - b, a) + c];
}

// A random patch on rational points of the unit circle: n sides, degree d, per-side degrees p
// (all equal when `same`, with one shared random knot vector), random heights, corners shared.
// `domain` non-empty replaces the random vertices.
HybridPatch<Rational> random_hybrid(std::mt19937_64& rng, int n, int d, int pmax, bool same, bool bezier = false,
                                    std::vector<Point2<Rational>> V = {}) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  std::vector<int> ts;
  while (V.empty() && static_cast<int>(ts.size()) < n) {
    const int t = pick(-40, 40);
    if (std::find(ts.begin(), ts.end(), t) == ts.end()) ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  for (int t : ts) {
    const Rational u(t, 10);
    V.push_back({(1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)});
  }
  n = static_cast<int>(V.size());
  auto knots = [&](int p) {
    std::vector<Rational> U(p + 1, Rational(0));
    std::vector<Rational> inner;
    for (int k = 0; k < d - p; ++k) {
      Rational x(pick(1, 19), 20);
      while (std::count(inner.begin(), inner.end(), x) >= p) x = Rational(pick(1, 19), 20);
      inner.push_back(x);
    }
    std::sort(inner.begin(), inner.end());
    U.insert(U.end(), inner.begin(), inner.end());
    U.insert(U.end(), p + 1, Rational(1));
    return U;
  };
  std::vector<int> p;
  std::vector<std::vector<Rational>> U;
  const int p0 = bezier ? d : pick(1, std::min(d, pmax));
  const auto U0 = knots(p0);
  for (int k = 0; k < n; ++k) {
    p.push_back(same || bezier ? p0 : pick(1, std::min(d, pmax)));
    U.push_back(same || bezier ? U0 : knots(p.back()));
  }
  auto P = hybrid_dome(V, d, p, U);
  for (std::size_t a = 2; a < P.points.size(); a += 3) P.points[a] += Rational(pick(-20, 20), 40);
  share_corners(P);
  validate(P);
  return P;
}

// deg D of the common denominator of S (hybrid-thm-3.1's bound).
int denominator_degree(const HybridPatch<Rational>& P) {
  const int n = static_cast<int>(P.sides());
  int deg = (P.d + 1) * (n - 2) + 2 * n * (n - 2);
  for (int pm : P.p) deg += P.d + pm;
  return deg;
}

std::vector<Rational> distinct(const std::vector<Rational>& U) {
  std::vector<Rational> c;
  for (const auto& u : U)
    if (c.empty() || c.back() != u) c.push_back(u);
  return c;
}

// The distinct values of two sorted knot vectors together.
std::vector<Rational> merged(const std::vector<Rational>& U, const std::vector<Rational>& V) {
  std::vector<Rational> m = distinct(U), n = distinct(V);
  m.insert(m.end(), n.begin(), n.end());
  std::sort(m.begin(), m.end());
  m.erase(std::unique(m.begin(), m.end()), m.end());
  return m;
}

Point2<Rational> on_side(const HybridPatch<Rational>& P, std::size_t s, const Rational& t) {
  const auto& A = P.vertices[s];
  const auto& B = P.vertices[(s + 1) % P.sides()];
  return {A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])};
}

// Domain sample: the vertex centroid G and G + (a/m)(V_k - G) + (b/m)(V_{k+1} - G), a + b <= m.
std::vector<Point2<Rational>> fan_sample(const HybridPatch<Rational>& P, int m) {
  Rational gx = 0, gy = 0;
  for (const auto& v : P.vertices) {
    gx += v[0];
    gy += v[1];
  }
  gx /= static_cast<long>(P.sides());
  gy /= static_cast<long>(P.sides());
  std::vector<Point2<Rational>> X{{gx, gy}};
  for (std::size_t k = 0; k < P.sides(); ++k) {
    const auto& A = P.vertices[k];
    const auto& B = P.vertices[(k + 1) % P.sides()];
    for (int a = 0; a <= m; ++a)
      for (int b = (a == 0 ? 1 : 0); a + b <= m; ++b)
        if (b < m || a > 0) X.push_back({gx + Rational(a, m) * (A[0] - gx) + Rational(b, m) * (B[0] - gx),
                                          gy + Rational(a, m) * (A[1] - gy) + Rational(b, m) * (B[1] - gy)});
  }
  return X;
}

// Theorems 4.1 and 4.2: every side of G (elevated or refined) has the interior and ribbon of the
// same side of F as functions of (s, h), proved per cell of G's knots; then the forms are compared
// with the patch on a fan sample. `what` names the operation in messages.
void prove_form_unchanged(const HybridPatch<Rational>& P, const HybridForm<Rational>& F, const HybridForm<Rational>& G,
                          const std::string& what, Accumulator& acc, std::size_t i) {
  for (std::size_t s = 0; s < P.sides(); ++s) {
    const auto& A = F.sides[s];
    const auto& B = G.sides[s];
    // Cells and bounds from both sides: the original form's (the input) and the new one's.
    acc.add(prove_by_samples({merged(A.U, B.U), merged(A.V, B.V)}, {std::max(A.du, B.du), std::max(A.dh, B.dh)},
                             [&](const std::vector<Rational>& y) -> std::string {
                               return hybrid_form_interior(B, P.q, y[0], y[1]) == hybrid_form_interior(A, P.q, y[0], y[1])
                                          ? ""
                                          : "side " + std::to_string(s) + " interior at " + pt(y);
                             },
                             what + " interior = interior"),
            i);
    for (int hh = 0; hh <= 1; ++hh)
      acc.add(prove_by_samples({merged(A.Ub, B.Ub)}, {std::max(A.p, B.p)},
                               [&](const std::vector<Rational>& y) -> std::string {
                                 return hybrid_form_ribbon(B, P.q, y[0], Rational(hh)) == hybrid_form_ribbon(A, P.q, y[0], Rational(hh))
                                            ? ""
                                            : "side " + std::to_string(s) + " ribbon at s = " + fr(y[0]);
                               },
                               what + " ribbon = ribbon"),
              i);
  }
  for (const auto& x : fan_sample(P, 6)) {
    ++acc.rep.points;
    if (hybrid_form_evaluate(G, x) != hybrid_evaluate(P, x)) acc.fail(what + " patch differs at " + fr(x[0]) + ", " + fr(x[1]), i);
  }
}

HybridPatch<Rational> example_or_random(std::size_t i, std::mt19937_64& rng, bool same_p) {
  if (i == 0) return hybrid_example_2_1();
  if (i == 1) return same_p ? hybrid_example_3_1_octagon() : hybrid_example_3_1_hexagon();
  if (i == 2) return same_p ? hybrid_example_3_1_hexagon() : hybrid_example_3_1_octagon();
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  return random_hybrid(rng, pick(3, 6), pick(3, 6), 4, same_p);
}

// Theorem 3.2 at corner V_i: the derivative of S along the iso-line s_i = 0 (side i-1, on which
// S = P_{i-1} (Theorem 3.1) and h_i = 1 - s_{i-1}) is -P'_{i-1}(1) (kernel derivative).
std::vector<Rational> corner_cross_derivative(const HybridPatch<Rational>& P, std::size_t i) {
  const std::size_t prev = (i + P.sides() - 1) % P.sides();
  auto D = derivative(hybrid_boundary_spline(P, prev), {Rational(1)}, {1});
  for (auto& c : D) c = -c;
  return D;
}

void hybrid_thm_3_1(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const auto P = example_or_random(i, rng, false);
  const int degD = denominator_degree(P);
  const auto Pt = planted_patch(P);  // the patch whose evaluation is under test
  for (std::size_t s = 0; s < P.sides(); ++s)
    acc.add(prove_by_samples({distinct(P.knots[s])}, {degD + P.p[s]},
                             [&](const std::vector<Rational>& t) -> std::string {
                               const auto x = on_side(P, s, t[0]);
                               const auto L = hybrid_local(P, x);
                               if (L.s[s] != t[0] || L.h[s] != 0)
                                 return "side " + std::to_string(s) + ": (s, h) = (" + fr(L.s[s]) + ", " + fr(L.h[s]) +
                                        ") at t = " + fr(t[0]);
                               if (hybrid_evaluate(Pt, x) == hybrid_boundary(P, s, t[0])) return "";
                               return "side " + std::to_string(s) + " at t = " + fr(t[0]);
                             },
                             "S(x(t)) = P_i(t)"),
            i);
}

void hybrid_thm_3_2(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  // Every case is checked up to its own first mismatch, whatever the cases before it found: a
  // case's points depend on the case alone, so ranges of cases run apart add up (the sweep).
  const auto P = i == 0 ? hybrid_example_3_1_hexagon() : example_or_random(i == 1 ? 0 : i, rng, false);
  const std::string name = i == 0 ? "Example 3.1 hexagon" : i == 1 ? "Example 2.1" : i == 2 ? "octagon" : "random patch";
  for (std::size_t s = 0; s < P.sides(); ++s) {
    const auto c = corner_cross_derivative(P, s), T0 = hybrid_cross_tangent(P, s, Rational(0));
    ++acc.rep.points;
    if (c != T0) {
      acc.fail(name + ", corner V_" + std::to_string(s) + ": along s_" + std::to_string(s) + " = 0 (side " +
                   std::to_string((s + P.sides() - 1) % P.sides()) + ") dS/dh_" + std::to_string(s) + " = " + pt(c) +
                   " but T_" + std::to_string(s) + "(0) = " + pt(T0),
               i);
      return;
    }
    const auto cuts = distinct(P.knots[s]);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      for (int m = 1; m <= 3; ++m) {
        const Rational t = cuts[k] + (cuts[k + 1] - cuts[k]) * Rational(m, 4);
        ++acc.rep.points;
        if (hybrid_cross_derivative(P, s, on_side(P, s, t)).value != hybrid_cross_tangent(P, s, t)) {
          acc.fail(name + ", side " + std::to_string(s) + " at t = " + fr(t), i);
          return;
        }
      }
  }
}

void hybrid_thm_3_2_corrected(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  const auto P = i == 0 ? hybrid_example_2_1()
                 : i == 1 ? hybrid_example_3_1_hexagon()
                          : random_hybrid(rng, pick(3, 5), pick(3, 4), 3, false);
  const int degD = denominator_degree(P), n = static_cast<int>(P.sides());
  const auto Pt = planted_patch(P);  // the patch whose derivative is under test
  for (std::size_t s = 0; s < P.sides(); ++s) {
    acc.add(prove_by_samples({distinct(P.knots[s])}, {2 * degD + 2 * (n - 2) + P.p[s]},
                             [&](const std::vector<Rational>& t) -> std::string {
                               const auto C = hybrid_cross_derivative(Pt, s, on_side(P, s, t[0]));
                               if (C.value == hybrid_cross_tangent(P, s, t[0])) return "";
                               return "side " + std::to_string(s) + " at t = " + fr(t[0]) + ": dS/dh = " + pt(C.value) +
                                      ", T_i = " + pt(hybrid_cross_tangent(P, s, t[0]));
                             },
                             "dS/dh_i = T_i on the open side"),
            i);
    const std::size_t prev = (s + P.sides() - 1) % P.sides();
    acc.add(prove_by_samples({{Rational(0), Rational(1)}}, {n - 1},
                             [&](const std::vector<Rational>& t) -> std::string {
                               const auto L = hybrid_local(P, on_side(P, prev, t[0]));
                               return L.h[s] == 1 - t[0] ? "" : "h_" + std::to_string(s) + " != 1 - t on side " + std::to_string(prev);
                             },
                             "h_i = 1 - s_{i-1} on side i-1"),
            i);
    const auto& Up = P.knots[prev];
    const Rational sigma = Rational(P.p[prev]) / (1 - Up[P.d]);
    const Rational tau = Rational(P.p[s]) / P.knots[s][P.p[s] + 1];
    auto T0 = hybrid_cross_tangent(P, s, Rational(0));
    for (auto& c : T0) c = c * sigma / tau;
    ++acc.rep.points;
    if (corner_cross_derivative(P, s) != T0) acc.fail("corner V_" + std::to_string(s) + ": -P'_{i-1}(1) != (sigma/tau) T_i(0)", i);
  }
}

void hybrid_thm_4_1(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const auto P = example_or_random(i, rng, true);
  const auto F = hybrid_form(P);
  auto G = F;
  const int steps = i == 0 ? 3 : 1;
  for (int st = 0; st < steps; ++st) {
    const auto H = hybrid_elevate(G);
    for (std::size_t s = 0; s < P.sides(); ++s) {
      const auto& A = G.sides[s];
      const auto& B = H.sides[s];
      auto c = make_spline<Rational>({A.p}, {A.Ub}, P.q, A.P);
      const auto eP = elevate_degree(c, 0, 1);
      c.points = A.Tbar;
      const auto eT = elevate_degree(c, 0, 1);
      acc.rep.points += 2;
      if (eP.knots[0] != B.Ub || eP.points != B.P || eT.points != B.Tbar)
        acc.fail("side " + std::to_string(s) + ": Eq. 4.6 differs from the kernel's elevation", i);
    }
    G = H;
  }
  if (i == 0) {  // Example 4.1: S^{6,2} -> S^{21,5}
    const auto& S0 = G.sides[0];
    ++acc.rep.points;
    if (S0.du != 21 || S0.dh != 21 || S0.p != 5 || S0.count_b() != 22)
      acc.fail("Example 4.1 counts: interior degree " + std::to_string(S0.du) + ", p " + std::to_string(S0.p) + ", " +
                   std::to_string(S0.count_b()) + " ribbon coefficients (want 21, 5, 22)",
               i);
  }
  plant_form(G);
  prove_form_unchanged(P, F, G, "elevated", acc, i);
}

void hybrid_thm_4_2(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  auto pick = [&](int lo, int hi) { return static_cast<int>(std::uniform_int_distribution<int>(lo, hi)(rng)); };
  const auto P = example_or_random(i, rng, true);
  const auto F = hybrid_form(P);
  auto G = F;
  for (int k = 0; k < 5; ++k) {
    Rational xs(k + 1, 6), xh(k + 1, 6), xb(2 * k + 1, 10);
    if (i >= 3) {
      xs = Rational(pick(1, 9), 10);
      xh = Rational(pick(1, 9), 10);
      xb = Rational(pick(1, 9), 10);
      while (std::count(G.sides[0].Ub.begin(), G.sides[0].Ub.end(), xb) >= G.sides[0].p ||
             std::any_of(G.sides.begin(), G.sides.end(), [&](const auto& S) {
               return std::count(S.Ub.begin(), S.Ub.end(), xb) >= S.p;
             }))
        xb = Rational(pick(1, 19), 20);
    }
    const auto H = hybrid_insert(G, xs, xh, xb);
    for (std::size_t s = 0; s < P.sides(); ++s) {
      const auto& A = G.sides[s];
      const auto in = make_spline<Rational>({A.du, A.dh}, {A.U, A.V}, P.q, A.interior);
      const auto kin = insert_knot(insert_knot(in, 0, xs), 1, xh);
      auto c = make_spline<Rational>({A.p}, {A.Ub}, P.q, A.P);
      const auto kP = insert_knot(c, 0, xb);
      c.points = A.Tbar;
      const auto kT = insert_knot(c, 0, xb);
      acc.rep.points += 3;
      const auto& B = H.sides[s];
      if (kin.points != B.interior || kin.knots[0] != B.U || kin.knots[1] != B.V || kP.points != B.P || kT.points != B.Tbar ||
          kP.knots[0] != B.Ub)
        acc.fail("side " + std::to_string(s) + ": Eq. 4.10-4.12 differ from the kernel's insertion", i);
    }
    G = H;
  }
  plant_form(G);
  prove_form_unchanged(P, F, G, "refined", acc, i);
}

void hybrid_salvi_elevation(const BSpline<Rational>&, std::mt19937_64& rng, Accumulator& acc, std::size_t i) {
  const HybridPatch<Rational> dom[3] = {hybrid_example_2_1(), hybrid_example_3_1_hexagon(), hybrid_example_3_1_octagon()};
  const auto P = random_hybrid(rng, 0, i % 2 == 0 ? 5 : 3, 0, true, true, dom[i % 3].vertices);
  const auto Q = hybrid_elevate_salvi(P);
  for (const auto& x : fan_sample(P, 6)) {
    ++acc.rep.points;
    const auto a = hybrid_evaluate(P, x), b = hybrid_evaluate(Q, x);
    if (a != b) {
      std::vector<Rational> dlt;
      for (std::size_t c = 0; c < a.size(); ++c) dlt.push_back(b[c] - a[c]);
      acc.fail("n = " + std::to_string(P.sides()) + ", d = " + std::to_string(P.d) + ": at the vertex centroid " + pt({x[0], x[1]}) +
                   " the elevated patch moves by " + pt(dlt),
               i);
      return;
    }
  }
}

}  // namespace

std::vector<ProofEntry> hybrid_proofs() {
  return {
      entry("hybrid-thm-3.1",
            "Theorem 3.1 of papers/003 (boundary interpolation): on side i of the hybrid patch, at x(t) = V_i + t "
            "(V_{i+1} - V_i), s_i = t, h_i = 0 and S(x(t)) = P_i(t), for t in [0, 1]. Cases: Examples 2.1 and 3.1 "
            "(hexagon, octagon), then random patches on rational points of the unit circle (n = 3..6, d = 3..6, "
            "p_i = 1..min(d, 4), random knots and heights, corners shared)",
            "per knot span of P_i, D(t) (S(x(t)) - P_i(t)) is a polynomial of degree <= deg D + p_i with the common "
            "denominator D = Lambda^(d+1) prod_m E_m^(d+p_m) prod_m (H_(m-1)^2 + H_m^2), deg D = (d+1)(n-2) + "
            "sum_m (d + p_m) + 2n(n-2) (Lambda = sum of Wachspress weights, E_m the denominator of s_m, H_m = "
            "Lambda h_m); D != 0 at the interior sample points",
            hybrid_thm_3_1, own_inputs),
      entry("hybrid-thm-3.2",
            "Theorem 3.2 of papers/003 as stated: at every point of side i (h_i = 0), the derivative of S in h_i at "
            "fixed s_i equals T_i(s_i). Checked at the corners (where the iso-line s_i = 0 is side i-1, so the "
            "derivative is -P'_{i-1}(1) by Theorem 3.1) and at 3 interior points per knot span, exact (dual "
            "numbers). Cases: Example 3.1 hexagon, Example 2.1, the octagon, random patches",
            "none (exact values compared point by point; the first mismatch refutes)",
            hybrid_thm_3_2, own_inputs_expected_refuted),
      entry("hybrid-thm-3.2-corrected",
            "Theorem 3.2 corrected: (a) at every point x(t), 0 < t < 1, of side i, dS/dh_i at fixed s_i (along the "
            "iso-line of s_i, a line through the meeting point of sides i-1 and i+1) equals T_i(t), for any ribbon "
            "factor; (b) at the corner V_i it equals -P'_{i-1}(1) = (sigma_{i-1} / tau_i) T_i(0), sigma_{i-1} = "
            "p_{i-1} / (1 - U^{i-1}_d) the end-span factor of side i-1, tau_i = p_i / U^i_{p_i+1} the ribbon factor: "
            "so T_i(0) is met at V_i iff sigma_{i-1} = tau_i (or C^{i-1}_{d-1,0} = C^{i-1}_{d,0}); (c) on side i-1, "
            "h_i = 1 - s_{i-1}. Cases: Examples 2.1, 3.1 (hexagon), random patches (n = 3..5, d = 3..4)",
            "(a) per knot span of P_i: dS/dh = X Lambda^2 / (M^2 Y) with X, Y the numerators of S_v s_u - S_u s_v and "
            "of the Jacobian s_u h_v - s_v h_u, so X Lambda^2 - T_i M^2 Y has degree <= 2 deg D + 2(n-2) + p_i in t "
            "(deg D as in hybrid-thm-3.1; distant sides contribute 0 to value and derivative on side i whichever "
            "knot span they are in, their weights vanishing to order d - l + 1 >= 2); (c) Lambda (h_i - 1 + t) has "
            "degree <= n - 1",
            hybrid_thm_3_2_corrected, own_inputs),
      entry("hybrid-thm-4.1",
            "Theorem 4.1 of papers/003 (improved degree elevation S^{d,p} -> S^{d+h,p+1}): per side, (a) Eq. 4.6 "
            "(Cohen-Lyche-Schumaker, literally) gives exactly the kernel's elevated B-spline coefficients (A5.9) for "
            "P_i and T_i; (b) the ribbon over Ubar equals the original (P and T, per knot span); (c) the interior "
            "after h applications of Eq. 4.5 equals the original Bernstein interior on [0, 1]^2; (d) the elevated "
            "form equals the patch at the vertex centroid and a fan sample (49 points per triangle). (b)-(c) with "
            "Remark 4.1 (L_i^*, B_0, C_0 kept) make the patches equal. Cases: Example 4.1 (Example 2.1 elevated "
            "three times to S^{21,5}; counts checked), the octagon, the hexagon (per-side p_i), random S^{d,p}",
            "(b) p + 1 per knot span; (c) (d + h, d + h) on [0, 1]^2",
            hybrid_thm_4_1, own_inputs),
      entry("hybrid-thm-4.2",
            "Theorem 4.2 of papers/003 (knot insertion): five knots inserted one at a time into U, V (interior) and "
            "U^b (ribbons) by Eq. 4.8-4.12; per side (a) the coefficients equal the kernel's (A5.1) exactly; (b) the "
            "refined interior equals the Bernstein interior on every cell of the refined knots; (c) the refined "
            "ribbon equals the original; (d) the refined form equals the patch at a fan sample. Cases: Example 4.2 "
            "(Example 2.1 with U, V += 1/6, 1/3, 1/2, 2/3, 5/6 and U^b += 1/10, 3/10, 1/2, 7/10, 9/10), the octagon, "
            "the hexagon, random patches and random knots (repeats allowed)",
            "(b) (d, d) per cell; (c) p per knot span",
            hybrid_thm_4_2, own_inputs),
      entry("hybrid-salvi-elevation",
            "Salvi's original degree elevation (the Bezier-sided patch's net elevated by Eq. 4.5, a new patch of degree "
            "d + 1 with the new weights, L_i^* and C_0) gives the same surface, compared exactly at the vertex centroid "
            "and a fan sample (49 points per triangle), on Bezier-sided patches over the domains of Examples 2.1 and 3.1 "
            "(n = 5, 6, 8 in turn, d = 5 or 3, dome plus random heights). Expected refuted: papers/003 says it moves the surface; the improved elevation (hybrid-thm-4.1) "
            "is the one that keeps it",
            "none (exact values compared point by point)",
            hybrid_salvi_elevation, own_inputs_expected_refuted),
  };
}

}  // namespace splinex::proof_detail
