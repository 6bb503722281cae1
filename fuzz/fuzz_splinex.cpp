// libFuzzer target over the document readers and every command's core (issue 13).
//
// Input: byte 0 chooses the reader (spline, trimmed domain, hybrid patch, verify candidate) and the
// operation, byte 1 is its small parameter (a direction, an amount, a
// fraction of the domain), the rest is a JSON document. Typed splinex::Error is the expected
// answer to bad input and is swallowed; anything else (another exception, a crash, a leak, an
// ASan/UBSan report, a timeout) is a finding. Exact results are also checked against an
// independent route where one is cheap (insertion by A5.1 vs A5.4, elevation by A5.9 vs the
// blossom, evaluation by A2.2 vs de Boor), so a wrong value is a finding too.
//
// Build and run: bash scripts/run.sh fuzz [EXECUTIONS] (README, reliability).
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "exact/flint_rational.hpp"
#include "io/hybrid_io.hpp"
#include "io/json_io.hpp"
#include "io/trimmed_domain_io.hpp"
#include "exact/memory.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "hybrid/hybrid.hpp"
#include "compose/trimmed_compose.hpp"
#include "crosscheck/verify.hpp"
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

void run_spline(std::uint8_t op, std::uint8_t arg, const sx::BSpline<sx::Rational>& S, const sx::Limits& L) {
  const int d = arg % S.dim();
  switch (op % 10) {
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
    case 8: {  // FLINT equals GMP exactly
      const auto F = sx::convert<sx::FlintRational>(S, [](const sx::Rational& r) { return sx::FlintRational(r); });
      const auto a = sx::refine_knots(F, d, {sx::FlintRational(inside(S, d, arg))}, L);
      const auto b = sx::refine_knots(S, d, {inside(S, d, arg)}, L);
      if (sx::convert<sx::Rational>(a, [](const sx::FlintRational& r) { return r.to_rational(); }).points != b.points)
        finding("FLINT and GMP differ");
      break;
    }
    case 9: {  // composition with itself when the dimensions fit (S o S for curves in R^1)
      sx::CompositionOptions o;
      o.expand = true;
      if (S.q == S.dim()) (void)sx::compose(S, S, o, L);
      break;
    }
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
    (void)rep.to_json();
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
