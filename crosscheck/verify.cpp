#include "crosscheck/verify.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>

#include "bernstein/tensor.hpp"  // Bernstein, bern_product, bern_coordinate
#include "compose/compose.hpp"
#include "spline/bezier.hpp"
#include "float/mpfr.hpp"
#include "spline/evaluate.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"

namespace splinex {

namespace {

std::string list(const std::vector<int>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  return s + "]";
}

/// max_c |v_c| of one point.
Rational max_abs(const std::vector<Rational>& v) {
  Rational m(0);
  for (const auto& x : v) m = std::max(m, Rational(abs(x)));
  return m;
}

/// The Greville abscissa of control index i in direction d (inside the domain of a clamped spline).
Rational greville(const BSpline<Rational>& S, int d, std::size_t i) {
  const int p = S.degrees[d];
  const auto& U = S.knots[d];
  if (p == 0) return (U[i] + U[i + 1]) / 2;
  Rational s(0);
  for (int k = 1; k <= p; ++k) s += U[i + k];
  return s / p;
}

/// The multi-index (direction 0 fastest) of flat control index k.
std::vector<std::size_t> multi_index(const BSpline<Rational>& S, std::size_t k) {
  std::vector<std::size_t> idx(S.dim());
  for (int d = 0; d < S.dim(); ++d) {
    idx[d] = k % S.count(d);
    k /= S.count(d);
  }
  return idx;
}

void check_comparable(const BSpline<Rational>& C, const BSpline<Rational>& R, const std::string& where) {
  if (C.dim() != R.dim())
    throw ValidationError(where + ".degrees", "the candidate has " + std::to_string(C.dim()) + " parametric directions, the reference " +
                                                  std::to_string(R.dim()),
                          "hand in the result of the same operation on the same input");
  if (C.q != R.q)
    throw ValidationError(where + ".points", "the candidate's points have " + std::to_string(C.q) + " coordinates, the reference's " +
                                                 std::to_string(R.q),
                          "hand in the result of the same operation on the same input");
}

/// Structure of one pair; returns "equal", "equal after rounding" or "different", with notes.
std::string compare_structure(const BSpline<Rational>& C, const BSpline<Rational>& R, int precision, const std::string& where,
                              std::vector<std::string>& notes) {
  if (C.degrees != R.degrees) {
    notes.push_back(where + ": degrees " + list(C.degrees) + " (candidate) vs " + list(R.degrees) + " (reference)");
    return "different";
  }
  if (C.is_rational() != R.is_rational()) {
    notes.push_back(where + (C.is_rational() ? ": the candidate is rational, the reference polynomial"
                                             : ": the candidate is polynomial, the reference rational"));
    return "different";
  }
  std::string verdict = "equal";
  for (int d = 0; d < C.dim(); ++d) {
    const auto &A = C.knots[d], &B = R.knots[d];
    const std::string at = where + ": knots[" + std::to_string(d) + "]";
    if (A.size() != B.size()) {
      notes.push_back(at + " has " + std::to_string(A.size()) + " knots in the candidate, " + std::to_string(B.size()) +
                      " in the reference");
      return "different";
    }
    if (A == B) continue;
    for (std::size_t i = 0; i < A.size(); ++i)
      if (!(A[i] == B[i]) && !(A[i] == rounded_to_precision(B[i], precision))) {
        notes.push_back(at + "[" + std::to_string(i) + "] is " + to_fraction_string(A[i]) + ", the reference " +
                        to_fraction_string(B[i]) + " (not its rounding)");
        return "different";
      }
    verdict = "equal after rounding";
  }
  return verdict;
}

int worse(const std::string& s) { return s == "equal" ? 0 : s == "equal after rounding" ? 1 : 2; }

}  // namespace

Rational rounded_to_precision(const Rational& x, int precision) {
  if (precision == 53) return exact_from_double(to_double(x));
  Mpfr::Precision scope(precision);
  return ArithTraits<Mpfr>::to_rational(ArithTraits<Mpfr>::from_rational(x));
}

// ---- the function-level error --------------------------------------------------------------------

namespace {

/// Indices of the (at most) k largest values, largest first.
std::vector<std::size_t> largest(const std::vector<Rational>& v, std::size_t k) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  k = std::min(k, v.size());
  std::partial_sort(order.begin(), order.begin() + k, order.end(), [&](std::size_t i, std::size_t j) { return v[j] < v[i]; });
  order.resize(k);
  return order;
}

/// Keeps the largest witnessed |C(x) - R(x)| and where.
void offer_witness(FunctionError& fe, const std::vector<Rational>& x, const Rational& v) {
  if (fe.at.empty() || fe.lower < v) {
    fe.lower = v;
    fe.at = x;
  }
}

/// Inserts X[d] into direction d of every spline in `nets` (they share their knots), unless the
/// result would exceed `budget` control points or the size limit; false (with the reason in
/// fe.method) when it stops, or when there is nothing to insert.
bool refine_within_budget(const std::vector<BSpline<Rational>*>& nets, std::vector<std::vector<Rational>> X,
                          std::size_t budget, const Limits& limits, FunctionError& fe) {
  const BSpline<Rational>& first = *nets.front();
  std::size_t after = 1;
  bool any = false;
  for (int d = 0; d < first.dim(); ++d) {
    after *= first.count(d) + X[d].size();
    any = any || !X[d].empty();
  }
  if (!any) return false;
  if (after > budget) {
    fe.method += "; stopped at the refinement budget";
    return false;
  }
  try {
    for (int d = 0; d < first.dim(); ++d)
      if (!X[d].empty())
        for (BSpline<Rational>* S : nets) *S = refine_knots(*S, d, X[d], limits);
  } catch (const SizeLimitError&) {
    fe.method += "; stopped at the size limit";
    return false;
  }
  return true;
}

/// Rational candidate or reference: on every Bezier piece of the common refinement,
/// C - R = (C_h R_w - R_h C_w) / (C_w R_w) per coordinate; the numerator's largest Bernstein
/// coefficient over the denominator's smallest (positive: the weights are) bounds |C - R| there.
FunctionError rational_function_error(const BSpline<Rational>& C0, const BSpline<Rational>& R0, const VerifyOptions& options,
                                      const Limits& limits) {
  auto [C, R] = make_compatible(C0, R0, limits);  // DomainError for different domains
  FunctionError fe;
  fe.certified = true;
  fe.method = "rational: per Bezier piece, max |Bernstein coefficient| of (C_h R_w - R_h C_w) over min of C_w R_w, "
              "refined at span midpoints";
  const std::size_t budget = options.budget * (C.size() + 64);
  const int q = C.q;
  for (fe.rounds = 0;; ++fe.rounds) {
    const BezierForm<Rational> FC = bezier_form(C, limits), FR = bezier_form(R, limits);
    const std::size_t pieces = FC.size();
    std::vector<Rational> bound(pieces);
    std::vector<std::vector<std::pair<Rational, Rational>>> boxes(pieces);
    for (std::size_t k = 0; k < pieces; ++k) {
      const BezierPiece<Rational> pc = FC.piece(k), pr = FR.piece(k);
      boxes[k] = pc.box;
      const auto cw = bern_coordinate(pc.spline, q), rw = bern_coordinate(pr.spline, q);
      const auto W = bern_product(cw, rw);
      const Rational wmin = *std::min_element(W.c.begin(), W.c.end());
      Rational nmax(0);
      for (int c = 0; c < q; ++c) {
        const auto a = bern_product(bern_coordinate(pc.spline, c), rw);
        const auto b = bern_product(bern_coordinate(pr.spline, c), cw);
        for (std::size_t i = 0; i < a.c.size(); ++i) nmax = std::max(nmax, Rational(abs(Rational(a.c[i] - b.c[i]))));
      }
      bound[k] = nmax / wmin;
    }
    const Rational upper = *std::max_element(bound.begin(), bound.end());
    if (fe.rounds == 0 || upper < fe.upper) fe.upper = upper;
    // Witnesses: the centres of the 8 pieces with the largest bounds.
    for (const std::size_t k : largest(bound, 8)) {
      std::vector<Rational> x;
      for (const auto& [lo, hi] : boxes[k]) x.push_back((lo + hi) / 2);
      std::vector<Rational> diff = evaluate(C, x);
      const auto r = evaluate(R, x);
      for (std::size_t c = 0; c < diff.size(); ++c) diff[c] -= r[c];
      offer_witness(fe, x, max_abs(diff));
    }
    if (fe.upper <= options.factor * fe.lower) {
      fe.within_factor = true;
      return fe;
    }
    if (fe.rounds >= options.max_rounds) return fe;
    // Midpoints of the pieces whose bound is not yet within the factor, every direction.
    const Rational bar = options.factor * fe.lower;
    std::vector<std::vector<Rational>> X(C.dim());
    for (int d = 0; d < C.dim(); ++d) {
      for (std::size_t k = 0; k < pieces; ++k)
        if (bar < bound[k]) X[d].push_back((boxes[k][d].first + boxes[k][d].second) / 2);
      std::sort(X[d].begin(), X[d].end());
      X[d].erase(std::unique(X[d].begin(), X[d].end()), X[d].end());
    }
    if (!refine_within_budget({&C, &R}, std::move(X), budget, limits, fe)) return fe;
  }
}

}  // namespace


FunctionError function_error(const BSpline<Rational>& C, const BSpline<Rational>& R, const VerifyOptions& options,
                             const Limits& limits) {
  check_comparable(C, R, "candidate");
  FunctionError fe;
  if (C.is_rational() || R.is_rational()) return rational_function_error(C, R, options, limits);
  BSpline<Rational> D = difference(C, R, limits);  // DomainError for different domains
  fe.certified = true;
  fe.method = "max |coefficient| of the exact difference on a common refinement (convex hull), refined at span midpoints";
  const std::size_t q = D.q;
  // Refinement budget: by default 64 times the first difference's coefficients (about three rounds
  // of global halving of a surface, six of a curve). Refinement is local where the error is local.
  const std::size_t budget = options.budget * (D.points.size() / q + 64);
  auto coef = [&](std::size_t k) {
    Rational m(0);
    for (std::size_t c = 0; c < q; ++c) m = std::max(m, Rational(abs(D.points[k * q + c])));
    return m;
  };
  for (fe.rounds = 0;; ++fe.rounds) {
    const std::size_t n = D.points.size() / q;
    std::vector<Rational> a(n);
    for (std::size_t k = 0; k < n; ++k) a[k] = coef(k);
    // The bound: the largest coefficient. It only decreases under refinement (each new
    // coefficient is a convex combination of old ones); keep the smallest seen.
    const Rational upper = *std::max_element(a.begin(), a.end());
    if (fe.rounds == 0 || upper < fe.upper) fe.upper = upper;
    if (fe.upper == 0) {
      fe.lower = 0;
      fe.at.clear();
      for (int d = 0; d < D.dim(); ++d) fe.at.push_back(D.domain_lo(d));
      fe.within_factor = true;
      return fe;
    }
    // Witnesses: the Greville points of the 8 largest coefficients.
    for (const std::size_t k : largest(a, 8)) {
      const auto mi = multi_index(D, k);
      std::vector<Rational> x(D.dim());
      for (int d = 0; d < D.dim(); ++d) x[d] = greville(D, d, mi[d]);
      offer_witness(fe, x, max_abs(evaluate(D, x)));
    }
    if (fe.upper <= options.factor * fe.lower) {
      fe.within_factor = true;
      return fe;
    }
    if (fe.rounds >= options.max_rounds) return fe;
    // Refine where the bound is not yet within the factor: midpoints of every non-empty span in
    // the support of a coefficient above factor * lower. The spans of every direction are chosen
    // from this D before any direction is refined (refining changes the indices).
    const Rational bar = options.factor * fe.lower;
    std::vector<std::vector<Rational>> X(D.dim());
    for (int d = 0; d < D.dim(); ++d) {
      const auto& U = D.knots[d];
      const int p = D.degrees[d];
      std::vector<char> split(U.size(), 0);
      for (std::size_t k = 0; k < n; ++k)
        if (bar < a[k]) {
          const std::size_t i = multi_index(D, k)[d];
          for (std::size_t s = i; s < i + static_cast<std::size_t>(p) + 1; ++s) split[s] = 1;
        }
      for (std::size_t s = static_cast<std::size_t>(p); s < D.count(d); ++s)
        if (split[s] && U[s] < U[s + 1]) X[d].push_back((U[s] + U[s + 1]) / 2);
    }
    if (!refine_within_budget({&D}, std::move(X), budget, limits, fe)) return fe;
  }
}

Json FunctionError::document() const {
  Json j;
  j["certified"] = certified;
  // Only a certified bound is written: an uncertified "upper" (not compared, or point values only)
  // is absent, with the reason, never 0. Values beyond double's range are the usual string.
  if (certified) {
    j["upper"] = approx_json(to_double(upper));
    j["upper_exact"] = to_fraction_string(upper);
  } else {
    j["upper_note"] = "no certified bound: " + method;
  }
  j["lower"] = approx_json(to_double(lower));
  j["lower_exact"] = to_fraction_string(lower);
  Json x = Json::array();
  for (const auto& v : at) x.push_back(to_fraction_string(v));
  j["at"] = x;
  j["within_factor"] = within_factor;
  j["rounds"] = rounds;
  j["method"] = method;
  return j;
}

// ---- whole reports ---------------------------------------------------------------------------------

namespace {

/// The candidate affinely reparametrized onto the reference's domain, when every end of its
/// domain is the reference's end or that end rounded to `precision` bits; none otherwise.
std::optional<BSpline<Rational>> onto_reference_domain(const BSpline<Rational>& C, const BSpline<Rational>& R, int precision) {
  if (C.dim() != R.dim()) return std::nullopt;
  const auto same_or_rounded = [&](const Rational& c, const Rational& r) { return c == r || c == rounded_to_precision(r, precision); };
  BSpline<Rational> M = C;
  bool moved = false;
  for (int d = 0; d < C.dim(); ++d) {
    const Rational clo = C.domain_lo(d), chi = C.domain_hi(d), rlo = R.domain_lo(d), rhi = R.domain_hi(d);
    if (!same_or_rounded(clo, rlo) || !same_or_rounded(chi, rhi) || !(clo < chi) || !(rlo < rhi)) return std::nullopt;
    if (clo != rlo || chi != rhi) {
      M = reparametrize(M, d, rlo, rhi);
      moved = true;
    }
  }
  if (!moved) return std::nullopt;
  return M;
}

}  // namespace

VerifyReport verify_splines(const std::string& operation, const std::vector<BSpline<Rational>>& reference,
                            const std::vector<BSpline<Rational>>& candidate, const VerifyOptions& options, const Limits& limits) {
  VerifyReport rep;
  rep.operation = operation;
  rep.precision = options.precision;
  rep.results = candidate.size();
  if (candidate.size() != reference.size()) {
    rep.structure = "different";
    rep.structure_notes.push_back("the candidate has " + std::to_string(candidate.size()) + " splines, the reference " +
                                  std::to_string(reference.size()));
    rep.function.method = "not compared: the results do not pair up";
    return rep;
  }
  for (const auto& R : reference)
    for (const auto& x : R.points) rep.reference_scale = std::max(rep.reference_scale, Rational(abs(x)));
  bool shapes = true;
  int verdict = 0;
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    const std::string where = candidate.size() == 1 ? "result" : "result[" + std::to_string(i) + "]";
    check_comparable(candidate[i], reference[i], where);
    const std::string s = compare_structure(candidate[i], reference[i], options.precision, where, rep.structure_notes);
    verdict = std::max(verdict, worse(s));
    if (candidate[i].degrees != reference[i].degrees || candidate[i].points.size() != reference[i].points.size() ||
        candidate[i].is_rational() != reference[i].is_rational())
      shapes = false;
  }
  rep.structure = verdict == 0 ? "equal" : verdict == 1 ? "equal after rounding" : "different";
  if (shapes) {
    rep.coefficients_compared = true;
    for (std::size_t i = 0; i < candidate.size(); ++i) {
      const auto &C = candidate[i], &R = reference[i];
      for (std::size_t k = 0; k < C.points.size(); ++k) rep.control_points.add(R.points[k], C.points[k]);
      for (std::size_t k = 0; k < C.weights.size(); ++k) rep.weights.add(R.weights[k], C.weights[k]);
      for (int d = 0; d < C.dim(); ++d)
        if (C.knots[d].size() == R.knots[d].size())
          for (std::size_t k = 0; k < C.knots[d].size(); ++k) rep.knots.add(R.knots[d][k], C.knots[d][k]);
    }
  }
  // The function-level error: the worst pair; certified and within the factor only if every pair is.
  bool certified = true, within = true;
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    FunctionError fe;
    const std::string where = candidate.size() == 1 ? "result" : "result[" + std::to_string(i) + "]";
    try {
      fe = function_error(candidate[i], reference[i], options, limits);
    } catch (const DomainError&) {
      // Domain ends rounded to the candidate's precision are accepted as interior knots are: the
      // candidate is compared after the affine map of its domain onto the reference's.
      if (auto mapped = onto_reference_domain(candidate[i], reference[i], options.precision)) {
        rep.domain_mapped = true;
        rep.structure_notes.push_back(where + ": the domain ends are the reference's rounded to " + std::to_string(options.precision) +
                                      " bits; the functions are compared after the affine map of the candidate's domain onto "
                                      "the reference's");
        fe = function_error(*mapped, reference[i], options, limits);
        certified = certified && fe.certified;
        within = within && fe.within_factor;
        if (i == 0 || rep.function.upper < fe.upper) {
          rep.function = std::move(fe);
          rep.function.method += " (candidate mapped onto the reference's domain)";
          if (candidate.size() > 1)
            rep.function.method += " (worst of " + std::to_string(candidate.size()) + " results, result " + std::to_string(i) + ")";
        }
        continue;
      }
      rep.structure = "different";
      rep.structure_notes.push_back(std::string(candidate.size() == 1 ? "result" : "result[" + std::to_string(i) + "]") +
                                    ": the domains differ, so the functions are not compared");
      rep.function = FunctionError{};
      rep.function.method = "not compared: different domains";
      return rep;
    }
    certified = certified && fe.certified;
    within = within && fe.within_factor;
    if (i == 0 || rep.function.upper < fe.upper) {
      rep.function = std::move(fe);
      if (candidate.size() > 1) rep.function.method += " (worst of " + std::to_string(candidate.size()) + " results, result " + std::to_string(i) + ")";
    }
  }
  rep.function.certified = certified;
  rep.function.within_factor = within;
  return rep;
}

/// The candidate's splines: one spline document, {"splines": [...]} or {"pieces": [{"spline": ...}]}.
std::vector<BSpline<Rational>> verify_candidate_splines(const Json& doc, const Limits& limits) {
  std::vector<BSpline<Rational>> out;
  if (doc.is_object() && doc.contains("splines")) {
    if (!doc["splines"].is_array()) throw ValidationError("candidate.splines", "is not an array", "give a list of spline documents");
    for (std::size_t i = 0; i < doc["splines"].size(); ++i)
      out.push_back(spline_from_json(doc["splines"][i], limits, "candidate.splines[" + std::to_string(i) + "]"));
  } else if (doc.is_object() && doc.contains("pieces")) {
    if (!doc["pieces"].is_array()) throw ValidationError("candidate.pieces", "is not an array", "give a list of pieces");
    for (std::size_t i = 0; i < doc["pieces"].size(); ++i) {
      const std::string where = "candidate.pieces[" + std::to_string(i) + "]";
      const Json& pc = doc["pieces"][i];
      if (!pc.is_object() || !pc.contains("spline"))
        throw ValidationError(where, "has no \"spline\"", "give each piece as {\"box\": ..., \"spline\": {...}}");
      out.push_back(spline_from_json(pc["spline"], limits, where + ".spline"));
    }
  } else {
    out.push_back(spline_from_json(doc, limits, "candidate"));
  }
  return out;
}

VerifyReport verify(const Operation& op, const BSpline<Rational>& input, const std::vector<BSpline<Rational>>& candidate,
                    const VerifyOptions& options, const Limits& limits) {
  return verify_splines(op.name(), run_operation(op, input, limits), candidate, options, limits);
}

VerifyReport verify_point_values(const std::string& operation, const std::vector<std::vector<Rational>>& at,
                                 const std::vector<std::vector<Rational>>& candidate_values,
                                 const std::function<std::vector<Rational>(const std::vector<Rational>&)>& exact_at,
                                 const VerifyOptions& options) {
  if (at.size() != candidate_values.size())
    throw ValidationError("candidate.values", "has " + std::to_string(candidate_values.size()) + " points for " +
                                                  std::to_string(at.size()) + " parameters",
                          "give one value per parameter");
  VerifyReport rep;
  rep.operation = operation;
  rep.precision = options.precision;
  rep.results = at.size();
  rep.function.method = "values at the given parameters (no function-level bound for point values)";
  for (std::size_t i = 0; i < at.size(); ++i) {
    const std::string field = "candidate.values[" + std::to_string(i) + "]";
    const auto exact = exact_at(at[i]);
    if (candidate_values[i].size() != exact.size())
      throw ValidationError(field, "has " + std::to_string(candidate_values[i].size()) + " coordinates, the exact value " +
                                       std::to_string(exact.size()),
                            "give a value with as many coordinates as the control points");
    rep.reference_scale = std::max(rep.reference_scale, max_abs(exact));
    std::vector<Rational> diff(exact.size());
    for (std::size_t c = 0; c < exact.size(); ++c) {
      rep.values.add(exact[c], candidate_values[i][c]);
      diff[c] = candidate_values[i][c] - exact[c];
    }
    const Rational m = max_abs(diff);
    if (i == 0 || rep.function.lower < m) {
      rep.function.lower = m;
      rep.function.upper = m;
      rep.function.at = at[i];
    }
  }
  return rep;
}

VerifyReport verify_values(const BSpline<Rational>& S, const std::vector<std::vector<Rational>>& at,
                           const std::vector<std::vector<Rational>>& candidate_values, const VerifyOptions& options) {
  return verify_point_values("eval", at, candidate_values, [&](const std::vector<Rational>& x) { return evaluate(S, x); },
                             options);
}

std::optional<ErrorStat> VerifyReport::function_stat() const {
  if (!(reference_scale > 0) || !function.certified) return std::nullopt;
  ErrorStat e;  // the same definitions as the coefficient errors'
  e.max_abs = function.upper;
  e.max_ref = reference_scale;
  return e;
}

std::pair<std::string, double> VerifyReport::worst_part() const {
  std::pair<std::string, double> worst{"", 0.0};
  const auto take = [&](const char* name, double bits) {
    if (bits > worst.second) worst = {name, bits};
  };
  if (coefficients_compared) take("control_points", control_points.bits_lost(precision));
  if (values.count) take("values", values.bits_lost(precision));
  if (const auto f = function_stat()) take("function", f->bits_lost(precision));
  return worst;
}

double VerifyReport::worst_bits_lost() const { return worst_part().second; }

Json VerifyReport::verdict() const {
  // The claim judged: the candidate is the exact result - as a function on the domain, or, for
  // point values (eval, hybrid-eval), at the given points.
  const bool point_values = parts.empty() && points_checked == 0 && !coefficients_compared && values.count > 0;
  const bool composition = !parts.empty() || points_checked > 0 || area_compared;
  const std::string claim = point_values ? "the candidate's values equal the exact values at the " + std::to_string(results) + " points"
                                         : "the candidate equals the exact result as a function on the domain";
  Json v{{"claim", claim}};
  const auto refuted = [&](const std::string& witness) {
    v["status"] = "refuted";
    v["witness"] = witness;
    return v;
  };
  const auto undecided = [&](const std::string& reason) {
    v["status"] = "undecided";
    v["reason"] = reason;
    return v;
  };
  // Refuted: a value that differs, measured exactly (point values, or a composition's samples of
  // T(S(r)) in Cartesian coordinates).
  if (values.count > 0 && values.max_abs > 0)
    return refuted("a value differs from the exact one by " + to_fraction_string(values.max_abs) + " (measured exactly)");
  if (point_values) {
    if (points_failed > 0) return undecided(std::to_string(points_failed) + " values could not be compared");
    v["status"] = "proved";
    v["reason"] = "every value compared exactly and equal";
    return v;
  }
  // Refuted by the function-level witness: only for the kernel operations, where it is the
  // difference of the functions at a point of the domain. (A composition's patches may be compared
  // in homogeneous coordinates, whose difference is no witness; a candidate mapped onto the
  // reference's domain is witnessed in the reference's parameters.)
  if (!composition && !domain_mapped && function.lower > 0) {
    std::string at;
    for (const auto& x : function.at) at += (at.empty() ? "" : ", ") + to_fraction_string(x);
    return refuted("|candidate - exact| = " + to_fraction_string(function.lower) + " at (" + at + "), evaluated exactly");
  }
  // Proved only where every part of the claim was checked: a certified bound of 0, nothing mapped,
  // and for compositions the same regions or tiles, no area moved and every sample point claimed
  // by the right part.
  if (!function.certified) return undecided("no certified bound: " + function.method);
  if (function.upper != 0) return undecided("the certified bound is not 0 and no difference was witnessed");
  if (domain_mapped) return undecided("equal after the affine map of the candidate's domain onto the reference's, whose ends differ");
  if (composition) {
    if (structure != "equal") return undecided("the patches agree, but the structure is " + structure + " (see structure_notes)");
    if (area_compared && area_moved != 0) return undecided("tiles cover other areas than the exact tiling (area_moved)");
    if (points_unclaimed + points_misassigned + points_failed > 0)
      return undecided(std::to_string(points_unclaimed) + " sample points unclaimed, " + std::to_string(points_misassigned) + " misassigned, " +
                       std::to_string(points_failed) + " with weight 0");
  }
  v["status"] = "proved";
  v["reason"] = composition ? "the certified bound of every part's difference is 0, with the same regions and every sample point claimed rightly"
                            : "the certified bound of the difference is 0";
  return v;
}

Json VerifyReport::document() const {
  Json j;
  j["operation"] = operation;
  j["precision"] = precision;
  j["structure"] = structure;
  j["structure_notes"] = structure_notes;
  j["results"] = results;
  if (coefficients_compared) {
    j["control_points"] = control_points.to_json(precision);
    if (weights.count) j["weights"] = weights.to_json(precision);
    if (knots.count) j["knots"] = knots.to_json(precision);
  }
  if (values.count) j["values"] = values.to_json(precision);
  if (points_checked)
    j["sampled"] = Json{{"points", points_checked},
                        {"unclaimed", points_unclaimed},
                        {"misassigned", points_misassigned},
                        {"zero_weight", points_failed},
                        {"note", "values: checked at " + std::to_string(points_checked) + " points (a sample, not a bound)"}};
  if (area_compared) j["area_moved"] = Json{{"value", to_double(area_moved)}, {"exact", to_fraction_string(area_moved)}};
  if (!parts.empty()) j["parts"] = parts;
  Json f = function.document();
  // Relative to the largest reference coefficient (values: the largest exact value), and as bits
  // lost at the candidate's precision, as the coefficient errors are.
  if (const auto e = function_stat()) {
    f["relative"] = approx_json(e->rel());
    f["bits_lost"] = e->bits_lost(precision);
  }
  j["function"] = f;
  // The summary: the worst bits lost and where, and the verdict.
  const auto [part, bits] = worst_part();
  j["worst_bits_lost"] = bits;
  j["worst_part"] = part.empty() ? Json(nullptr) : Json(part);
  j["verdict"] = verdict();
  return j;
}

// ---- reading a candidate as a float program meant it ------------------------------------------------

Json candidate_numbers_as_doubles(const Json& doc) {
  if (doc.is_object()) {
    Json out = Json::object();
    for (auto it = doc.begin(); it != doc.end(); ++it)
      out[it.key()] = (it.key() == "type" || it.key() == "degrees") ? it.value() : candidate_numbers_as_doubles(it.value());
    return out;
  }
  if (doc.is_array()) {
    Json out = Json::array();
    for (const auto& v : doc) out.push_back(candidate_numbers_as_doubles(v));
    return out;
  }
  std::string text;
  if (doc.is_number_integer() || doc.is_number_unsigned()) text = doc.dump();
  else if (doc.is_string()) text = doc.get<std::string>();
  else return doc;
  if (text.find('/') != std::string::npos) return doc;  // a fraction is what it says
  Rational exact;
  try {
    exact = parse_number(text, "candidate");
  } catch (const ParseError&) {
    return doc;  // not a number: the reader will say what is wrong with it
  }
  const double d = to_double(exact);
  if (!std::isfinite(d))
    throw RangeError("candidate", "the number " + text.substr(0, 40) + " is beyond the range of double",
                     "read the candidate with --read-as exact if it is not a double");
  return Json(to_fraction_string(exact_from_double(d)));
}

namespace {

std::vector<std::vector<Rational>> number_rows(const Json& doc, const std::string& field) {
  if (!doc.contains(field) || !doc[field].is_array())
    throw ValidationError("candidate." + field, "is missing or not an array", "give \"at\" and \"values\" as lists of points");
  std::vector<std::vector<Rational>> out;
  for (std::size_t i = 0; i < doc[field].size(); ++i) {
    const Json& row = doc[field][i];
    const std::string where = "candidate." + field + "[" + std::to_string(i) + "]";
    if (!row.is_array()) throw ValidationError(where, "is not a list of numbers", "write [x0, x1, ...]");
    std::vector<Rational> r;
    for (std::size_t c = 0; c < row.size(); ++c) r.push_back(json_number(row[c], where + "[" + std::to_string(c) + "]"));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

Json read_candidate(const std::string& path, bool as_doubles, const ReadLimits& read_limits) {
  Json cand = read_json_file(path, read_limits);
  return as_doubles ? candidate_numbers_as_doubles(cand) : cand;
}

CandidateValues candidate_values(const Json& doc) {
  CandidateValues c;
  c.values = number_rows(doc, "values");  // first, as the command read them before (its error names values when both are missing)
  c.at = number_rows(doc, "at");
  return c;
}

CandidateValues hybrid_candidate_values(const Json& cand) {
  if (!(cand.is_object() && cand.contains("points") && !cand.contains("values"))) return candidate_values(cand);
  Json at = Json::array(), values = Json::array();
  for (const auto& row : cand["points"]) {
    if (!row.is_object() || !row.contains("at") || !row.contains("point"))
      throw ValidationError("candidate.points", "an entry has no \"at\" or \"point\"", "give {\"at\": [u, v], \"point\": [...]}");
    at.push_back(row["at"]);
    values.push_back(row["point"]);
  }
  return candidate_values(Json{{"at", at}, {"values", values}});
}

}  // namespace splinex
