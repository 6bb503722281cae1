// splinex::verify_trimmed_composition / verify_tensor_composition (issue 16): Algorithm 1's
// trimmed patches and Algorithm 2's tiles handed in as candidates, with errors known by
// construction.
#include <catch2/catch.hpp>

#include "compose/compose.hpp"
#include "crosscheck/verify.hpp"
#include "float/rounding.hpp"
#include "io/result_json.hpp"
#include "tests/helpers.hpp"

using namespace splinex;
using splinex::test::spline;

namespace {

// T: a biquadratic surface in R^3 with interior knots 1/2 and 1/3; S: a surface in T's domain
// whose coordinate 0 crosses u = 1/2 along a curve (a quadratic in S's first parameter).
const char* kOuter = R"({"type": "bspline", "degrees": [2, 2], "knots": [[0, 0, 0, 0.5, 1, 1, 1], [0, 0, 0, "1/3", 1, 1, 1]],
  "points": [[0,0,0],[1,0,1],[2,0,0],[3,0,1], [0,1,1],[1,1,3],[2,1,-1],[3,1,2],
             [0,2,0],[1,2,-2],[2,2,1],[3,2,0], [0,3,1],[1,3,0],[2,3,2],[3,3,1]]})";
const char* kInner = R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, 1, 1, 1], [0, 0, 1, 1]],
  "points": [[0.1, 0.1], [0.9, 0.2], [0.2, 0.15], [0.15, 0.9], [0.8, 0.7], [0.3, 0.95]]})";
// The same with a rational outer spline (weights 1 and 2).
const char* kOuterRational = R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, 0.5, 1, 1, 1], [0, 0, 1, 1]],
  "points": [[0,0,0],[1,0,1],[2,0,0],[3,0,1], [0,1,1],[1,1,3],[2,1,-1],[3,1,2]],
  "weights": [1, 2, 1, 2, 2, 1, 1, 1]})";
// An affine inner surface: straight trimming curves, so the exact tiling exists.
const char* kInnerAffine = R"({"type": "bspline", "degrees": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]],
  "points": [[0.2, 0.1], [0.8, 0.2], [0.25, 0.9], [0.85, 1.0]]})";

/// What a program writes, read back as a candidate: decimals as the doubles printed.
Json as_candidate(const Json& j) { return candidate_numbers_as_doubles(splinex::test::doc(j.dump())); }

/// max over [0, 1] of the Bernstein polynomial B_i^n: attained at i/n.
Rational bernstein_max(int n, int i) {
  Rational c(1);
  for (int k = 1; k <= i; ++k) c = c * Rational(n - i + k) / Rational(k);
  if (n == 0) return c;
  const Rational t = Rational(i) / Rational(n);
  for (int k = 0; k < i; ++k) c *= t;
  for (int k = 0; k < n - i; ++k) c *= (1 - t);
  return c;
}

/// Adds `delta` to coordinate 0 of control point m of the spline document j (exact text).
void plant(Json& j, std::size_t m, const Rational& delta) {
  j["points"][m][0] = to_fraction_string(json_number(j["points"][m][0], "test") + delta);
}

/// The planted error's size: delta times the maximum of the tensor Bernstein basis function m.
Rational planted_sup(const Json& patch, std::size_t m, const Rational& delta) {
  const auto P = spline_from_json(patch);
  Rational b = delta;
  for (int d = 0; d < P.dim(); ++d) {
    const std::size_t i = m % P.count(d);
    m /= P.count(d);
    b *= bernstein_max(P.degrees[d], static_cast<int>(i));
    REQUIRE(P.count(d) == static_cast<std::size_t>(P.degrees[d]) + 1);  // a Bezier patch
  }
  return b;
}

bool inside(const Json& box, const std::vector<Rational>& x) {
  for (std::size_t l = 0; l < x.size(); ++l)
    if (x[l] < json_number(box[l][0], "test") || json_number(box[l][1], "test") < x[l]) return false;
  return true;
}

}  // namespace

TEST_CASE("verify compose trimmed: the exact patches are equal with error 0, the double ones lose few bits") {
  for (const char* outer : {kOuter, kOuterRational}) {
    const auto T = spline(outer), S = spline(kInner);
    const auto C = compose_trimmed(T, S);
    REQUIRE(C.patches.size() >= 2);  // the inner piece crosses u = 1/2 (and v = 1/3 in T)
    const auto exact = verify_trimmed_composition(T, S, as_candidate(trimmed_composition_to_json(C, 1e-6)));
    CHECK(exact.structure == "equal");
    CHECK(exact.function.certified);
    CHECK(exact.function.upper == 0);
    CHECK(exact.points_checked == 17 * 17);
    CHECK(exact.values.max_abs == 0);
    CHECK(exact.points_unclaimed == 0);
    CHECK(exact.points_misassigned == 0);

    const auto Cd = compose_trimmed(round_spline<double>(T), round_spline<double>(S));
    const auto dbl = verify_trimmed_composition(T, S, as_candidate(trimmed_composition_to_json(Cd, 1e-6)));
    CHECK(dbl.structure != "different");
    CHECK(dbl.function.certified);
    CHECK(dbl.function.upper > 0);  // 0.1 is not a double
    CHECK(dbl.worst_bits_lost() < 8);
    CHECK(dbl.values.count > 0);
  }
}

TEST_CASE("verify compose trimmed: an error planted in one patch is bounded within 2x, in that patch") {
  const auto T = spline(kOuter), S = spline(kInner);
  Json cand = trimmed_composition_to_json(compose_trimmed(T, S), 1e-6);
  const std::size_t k = cand["pieces"].size() / 2;
  const std::size_t m = 7;
  const Rational delta = Rational(1) / Rational(1099511627776LL);
  plant(cand["pieces"][k]["patch"], m, delta);
  const Rational sup = planted_sup(cand["pieces"][k]["patch"], m, delta);
  VerifyOptions vo;
  const auto rep = verify_trimmed_composition(T, S, as_candidate(cand), vo);
  CHECK(rep.structure == "equal");
  CHECK(rep.function.certified);
  CHECK(rep.function.within_factor);
  CHECK(sup <= rep.function.upper);
  CHECK(rep.function.upper <= 2 * sup);
  CHECK(rep.function.lower <= sup);
  CHECK(inside(cand["pieces"][k]["inner_box"], rep.function.at));
  CHECK(rep.parts[k]["function"]["upper"].get<double>() > 0);
  for (std::size_t i = 0; i < rep.parts.size(); ++i)
    if (i != k) CHECK(rep.parts[i]["function"]["upper"].get<double>() == 0);
}

TEST_CASE("verify compose trimmed: a missing patch or another region is a structure finding, not certified") {
  const auto T = spline(kOuter), S = spline(kInner);
  const Json full = trimmed_composition_to_json(compose_trimmed(T, S), 1e-6);
  Json missing = full;
  missing["pieces"].erase(missing["pieces"].begin() + 1);
  const auto rep = verify_trimmed_composition(T, S, as_candidate(missing));
  CHECK(rep.structure == "different");
  CHECK_FALSE(rep.function.certified);
  CHECK(rep.points_unclaimed > 0);  // the missing patch's region is claimed by no part

  Json moved = full;  // a region bound moved: a patch claims points of its neighbour
  bool changed = false;
  for (auto& pc : moved["pieces"])
    for (auto& c : pc["region"])
      if (!changed && c.contains("below")) {
        c["below"] = to_fraction_string(json_number(c["below"], "test") + Rational(1, 16));
        changed = true;
      }
  REQUIRE(changed);
  const auto rep2 = verify_trimmed_composition(T, S, as_candidate(moved));
  CHECK(rep2.structure == "different");
  CHECK(rep2.points_misassigned > 0);
  CHECK(rep2.values.max_abs > 0);  // T_j^e off its cell is not T
}

TEST_CASE("verify compose tensor: exact tiles equal with no area moved, a planted error bounded in its tile") {
  const auto T = spline(kOuter), S = spline(kInnerAffine);
  const auto A = compose_tensor(T, S);
  REQUIRE(A.tiles.size() >= 4);
  Json cand = tensor_composition_to_json(A);
  const auto rep = verify_tensor_composition(T, S, as_candidate(cand));
  CHECK(rep.structure == "equal");
  CHECK(rep.function.certified);
  CHECK(rep.function.upper == 0);
  CHECK(rep.area_compared);
  CHECK(rep.area_moved == 0);
  CHECK(rep.points_misassigned == 0);
  CHECK(rep.values.max_abs == 0);

  const std::size_t k = cand["tiles"].size() - 1, m = 2;
  const Rational delta = Rational(1) / Rational(1099511627776LL);
  plant(cand["tiles"][k]["patch"], m, delta);
  const auto planted = verify_tensor_composition(T, S, as_candidate(cand));
  const auto P = spline_from_json(cand["tiles"][k]["patch"]);
  // The tile patch is a B-spline in x (knots at the slab boundaries): bound the basis function's
  // maximum from below by the planted value at its Greville-point neighbourhood and above by 1.
  CHECK(planted.function.certified);
  CHECK(planted.function.upper <= delta);
  CHECK(planted.function.lower > 0);
  CHECK(planted.function.upper <= 2 * planted.function.lower);
  CHECK(planted.parts[k]["function"]["upper"].get<double>() > 0);
  CHECK(planted.structure == "equal");
  (void)P;

  Json dropped = tensor_composition_to_json(A);
  dropped["tiles"].erase(dropped["tiles"].begin());
  const auto d = verify_tensor_composition(T, S, as_candidate(dropped));
  CHECK(d.structure == "different");
  CHECK(d.area_moved > 0);
}

TEST_CASE("verify compose tensor: double tiles from trimming polylines, judged against their own Coons patches") {
  const auto T = spline(kOuter), S = spline(kInner);
  CHECK_THROWS_AS(compose_tensor(T, S), DomainError);  // curved trimming curves: no exact tiling
  TensorOptions to;
  to.boundary = TrimBoundary::polyline;
  to.eps = 1e-2;  // coarse: fewer polyline vertices, cheaper exact compositions of the tiles
  const auto A = compose_tensor(round_spline<double>(T), round_spline<double>(S), to);
  const auto rep = verify_tensor_composition(T, S, as_candidate(tensor_composition_to_json(A)));
  CHECK_FALSE(rep.area_compared);
  REQUIRE_FALSE(rep.structure_notes.empty());
  CHECK(rep.structure_notes[0].find("no exact tiling") != std::string::npos);
  CHECK(rep.function.certified);
  CHECK(rep.worst_bits_lost() > 0);
  CHECK(rep.function.upper < 1e-12);  // each tile's patch is T_j^e(S_i(Q)) to rounding
  CHECK(rep.points_checked == 25 * A.tiles.size());
  // Sampled: what the tolerance does; a point's value is off by at most about eps times |T'| |S'|.
  CHECK(rep.values.count > 0);
  CHECK(rep.values.abs() < 1e-2);
}

TEST_CASE("verify compose: unusable candidates are typed errors naming the field") {
  const auto T = spline(kOuter), S = spline(kInner);
  CHECK_THROWS_AS(verify_trimmed_composition(T, S, splinex::test::doc(R"({"tiles": []})")), ValidationError);
  Json cand = trimmed_composition_to_json(compose_trimmed(T, S), 1e-6);
  cand["pieces"][0]["patch"]["points"][0] = Json::array({"1", "2"});
  try {
    verify_trimmed_composition(T, S, as_candidate(cand));
    FAIL("accepted a patch of the wrong point size");
  } catch (const ValidationError& e) {
    CHECK(std::string(e.what()).find("candidate.pieces[0].patch") != std::string::npos);
  }
  CHECK_THROWS_AS(verify_tensor_composition(T, spline(R"({"type": "bspline", "degrees": [2], "knots": [[0, 0, 0, 1, 1, 1]],
      "points": [[0.1, 0.1], [0.5, 0.9], [0.9, 0.2]]})"), splinex::test::doc(R"({"tiles": []})")),
                  ValidationError);
}
