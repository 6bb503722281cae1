// The cutting package's results as documents (cut/io/documents.hpp), moved here from the command
// line (apps/cmd_cut.cpp) unchanged.
#include "cut/io/documents.hpp"

#include <cmath>
#include <type_traits>

#include "io/cut_io.hpp"

namespace splinex::cut {

// An exact value and its double (or, beyond double's range, log2 of its magnitude).
Json q_json(const Rational& x) {
  Json j{{"exact", to_fraction_string(x)}};
  const double d = to_double(x);
  if (std::isfinite(d)) j["approx"] = d;
  else j["log2_abs"] = log2_abs(x);
  return j;
}

namespace {

// The separation certificate of a guide, d = 2 and 3: verdict, pieces, witness, undecided pieces.
template <class Result>
Json separation_document(const Result& s) {
  constexpr bool planar = std::is_same_v<Result, SeparationResult>;
  auto fractions = [](const auto& v) {
    Json a = Json::array();
    for (const auto& x : v) a.push_back(to_fraction_string(x));
    return a;
  };
  Json j{{"verdict", certificate_word(s.verdict)}, {"pieces_certified", s.pieces}, {"pieces_in_strip", s.excluded}};
  if (s.witness) {
    const auto& w = *s.witness;
    j["witness"] = Json{{"facet", w.facet},
                        {"point_normalized", fractions(w.point)},
                        {"value", q_json(w.value)},
                        {"side", w.positive_side ? "b (f* must be > 0)" : "b-bar (f* must be < 0)"}};
    if constexpr (planar) j["witness"]["parameter"] = to_fraction_string(w.param);
    else j["witness"]["parameters"] = fractions(w.param);
  }
  Json u = Json::array();
  for (const auto& o : s.undecided) {
    if constexpr (planar)
      u.push_back(Json{{"facet", o.facet}, {"parameters", Json::array({to_fraction_string(o.lo), to_fraction_string(o.hi)})}});
    else
      u.push_back(Json{{"facet", o.facet},
                       {"parameters", Json::array({Json::array({to_fraction_string(o.lo[0]), to_fraction_string(o.hi[0])}),
                                                   Json::array({to_fraction_string(o.lo[1]), to_fraction_string(o.hi[1])})})}});
  }
  j["undecided"] = u;
  j["meaning"] = s.verdict.reason();
  return j;
}

}  // namespace

Json separation_json(const SeparationResult& s) { return separation_document(s); }

// The double guide's coefficients against the exact minimizer, measured exactly.
Json judged_against_exact(const std::vector<Rational>& exact, const std::vector<Rational>& rounded) {
  const auto e = coefficient_error(exact, rounded);
  Json cmp{{"max_abs_error", q_json(e.max_abs_error)}, {"bits_lost", e.bits_lost}};
  cmp["max_rel_error"] = e.max_abs > 0 && e.max_abs_error > 0 ? to_double(Rational(e.max_abs_error / e.max_abs)) : 0.0;
  cmp["meaning"] = "the double guide's coefficients against the exact minimizer (Lemma 1: unique), measured exactly";
  return cmp;
}


Json validity_json(const ValidityResult& v) {
  Json j{{"verdict", validity_word(v.verdict)},
         {"boundary_interpolation", v.interpolates},
         {"tangent_conditions", v.tangents},
         {"regular", certificate_word(v.regular)},
         {"injective", certificate_word(v.injective)},
         {"no_collision", certificate_word(v.inside)},
         {"pairs_examined", v.pairs}};
  if (v.singular_s) j["singular_at"] = to_fraction_string(*v.singular_s);
  if (v.witness) {
    j["witness"] = Json{{"parameter", to_fraction_string(*v.witness_s)},
                        {"point", Json::array({to_fraction_string((*v.witness)[0]), to_fraction_string((*v.witness)[1])})},
                        {"meaning", v.witness_meaning}};
  }
  j["meaning"] = "each condition decided exactly (certified or violated, with a witness) or undecided at the subdivision budget";
  return j;
}

namespace {

// A guide, d = 2 or 3 (R: GuideResult<T> or GuideResult3<T>): the program, its KKT check, the
// verdict, the guide and, when given, the separation certificate.
template <class T, class Result, class Separation>
Json guide_document(const Result& R, const std::optional<Separation>& sep) {
  constexpr bool planar = std::is_same_v<Result, GuideResult<T>>;
  constexpr int d = planar ? 2 : 3;
  Json j;
  j["arithmetic"] = ArithTraits<T>::name();
  j["status"] = to_string(R.status);
  if constexpr (planar) j["inner_knots"] = Json::array({R.inner_knots, R.inner_knots_y});
  else j["inner_knots"] = R.inner_knots;
  j["inner_knots_tried"] = R.tried;
  j["variables"] = R.program.n;
  j["rows"] = R.program.rows.size();
  j["samples"] = Json{{"b", R.samples_positive}, {"b_bar", R.samples_negative}};
  Json lo = Json::array();
  for (int k = 0; k < d; ++k) lo.push_back(to_fraction_string(R.frame.lo[static_cast<std::size_t>(k)]));
  j["frame"] = Json{{"lo", lo},
                    {"scale", to_fraction_string(R.frame.scale)},
                    {"meaning", "f* lives on [0,1]^" + std::to_string(d) + " in normalized coordinates (x - lo) / scale"}};
  j["kkt"] = Json{{"holds", R.kkt.holds}, {"failed", R.kkt.failed}, {"active_rows", R.kkt.active}, {"method", R.solution.method}};
  j["positive_definite"] = R.positive_definite;
  if (R.status == QPStatus::optimal) {
    j["verdict"] = guide_verdict(ArithTraits<T>::exact, R.program, R.kkt, R.positive_definite);
    j["objective"] = q_json(R.solution.objective);
    if constexpr (planar) {
      j["value_at_ends"] = Json::array({q_json(R.value_at_ends[0]), q_json(R.value_at_ends[1])});
      j["gradient_error_squared_at_ends"] = Json::array({q_json(R.gradient_error2[0]), q_json(R.gradient_error2[1])});
    } else {
      j["max_abs_value_on_loop_samples"] = q_json(R.max_abs_value_on_loop);
      j["max_gradient_error_squared_on_loop_samples"] = q_json(R.max_gradient_error2);
    }
    j["guide"] = spline_to_json(R.f);
  } else {
    std::string upto;
    if constexpr (planar) upto = " up to " + std::to_string(R.inner_knots) + " inner knots";
    j["verdict"] = R.status == QPStatus::infeasible
                       ? "infeasible" + upto + " (Farkas certificate " + (R.kkt.holds ? "checked exactly" : "not confirmed: " + R.kkt.failed) + ")" +
                             (R.refinement_stopped_by_limit ? "; refinement stopped at the size limit" : "") +
                             ": raise --max-inner-knots, lower --delta, or widen --strip"
                       : "unbounded";
  }
  if constexpr (!planar) {
    j["samples"]["loop"] = R.loop_points.size();
    j["loop_sides"] = R.loop.size();
  }
  if (sep) j["separation"] = separation_document(*sep);
  j["seconds"] = R.seconds;
  return j;
}

}  // namespace

template <class T>
Json guide_json(const GuideResult<T>& R, const std::optional<SeparationResult>& sep) {
  return guide_document<T>(R, sep);
}


Json separation3_json(const SeparationResult3& s) { return separation_document(s); }

template <class T>
Json guide3_json(const GuideResult3<T>& R, const std::optional<SeparationResult3>& sep) {
  return guide_document<T>(R, sep);
}


// The patch between normalized and solid coordinates (exact).
BSpline<Rational> patch_from_frame(BSpline<Rational> p, const Frame3& f) {
  for (std::size_t i = 0; i < p.points.size(); ++i) p.points[i] = f.lo[i % 3] + f.scale * p.points[i];
  return p;
}
BSpline<Rational> patch_to_frame(BSpline<Rational> p, const Frame3& f) {
  for (std::size_t i = 0; i < p.points.size(); ++i) p.points[i] = (p.points[i] - f.lo[i % 3]) / f.scale;
  return p;
}

Json point3_json(const std::array<Rational, 3>& x) {
  return Json::array({to_fraction_string(x[0]), to_fraction_string(x[1]), to_fraction_string(x[2])});
}

Json surface_validity_json(const SurfaceValidity& v, const Frame3& f) {
  Json j{{"verdict", validity_word(v.verdict)},
         {"vertices_interpolated_exactly", v.vertices_exact},
         {"vertex_error_normalized", q_json(v.vertex_error)},
         {"boundary_deviation_bound_normalized", q_json(v.boundary_deviation)},
         {"boundary_meaning", "p interpolates the loop at Omega's vertices; between them |p(e(s)) - L(s)|_inf <= this bound (Bernstein coefficients, exact)"},
         {"tangents", certificate_word(v.tangents)},
         {"tangents_meaning", "t . (dp/dm) > 0 along every edge of Omega, m its inward normal: the prescribed tangents point into the patch"},
         {"regular", status_name(v.regular.status())},
         {"injective", status_name(v.injective.status())},
         {"regularity_method", v.regularity_method},
         {"collision", collision_word(v.collision)},
         {"collision_pieces", Json{{"certified", v.collision_pieces}, {"in_strip", v.collision_excluded}, {"undecided", v.collision_undecided}}},
         {"membership_test", v.membership},
         {"seconds", v.seconds}};
  if (v.witness) {
    const auto& w = *v.witness;
    std::array<Rational, 3> x;
    for (int c = 0; c < 3; ++c) x[c] = f.lo[c] + f.scale * w.point[c];
    j["witness"] = Json{{"condition", w.condition},
                        {"parameters", Json::array({to_fraction_string(w.param[0]), to_fraction_string(w.param[1])})},
                        {"point", point3_json(x)},
                        {"detail", w.detail}};
    if (w.condition == "tangent") j["witness"]["value"] = q_json(w.value);
  }
  j["meaning"] = v.verdict.is_proved() ? "Section 2's conditions hold: interpolation at the vertices exact, tangents, regularity, injectivity and no collision "
                                        "outside the strip certified exactly"
                 : v.verdict.is_refuted() ? "a condition fails at the witness, an exact point"
                                          : "no condition fails at a point found, but some could not be certified (see above)";
  return j;
}

template <class T>
Json surface_json(const CuttingSurface<T>& R, const Frame3& f) {
  Json dom = Json::array();
  for (const auto& w : R.domain.vertices) dom.push_back(Json::array({to_fraction_string(w[0]), to_fraction_string(w[1])}));
  Json j{{"arithmetic", ArithTraits<T>::name()},
         {"domain", Json{{"method", R.domain.method}, {"vertices", dom}, {"projection_axes", Json::array({R.domain.axes[0], R.domain.axes[1]})}}},
         {"variables", R.variables},
         {"equalities", R.equalities},
         {"inequalities", R.inequalities},
         {"active_inequalities", R.active_inequalities},
         {"solver", R.solver},
         {"kkt", Json{{"holds", R.kkt_holds}, {"failed", R.kkt_failed}}},
         {"seconds", R.seconds},
         {"surface", cutting_surface_to_json(patch_from_frame(R.patch, f), R.domain.vertices)}};
  if (!R.domain.why_not_projection.empty()) j["domain"]["why_not_projection"] = R.domain.why_not_projection;
  if (!R.domain.why_not_qp.empty()) j["domain"]["why_not_qp"] = R.domain.why_not_qp;
  j["kkt"]["meaning"] = ArithTraits<T>::exact
                            ? (R.kkt_holds ? "proved: the minimizer of the patch program (KKT conditions checked exactly)" : "not proved: " + R.kkt_failed)
                            : "a double solution: judge it against --arith exact";
  return j;
}

Json guided_json(const GuidedResult& g, double weight, const GuideOptions3& o, const std::string& guide_status) {
  return Json{{"guide", guide_status},
              {"weight", weight},
              {"guide_inner_knots", Json::array({o.inner_knots[0] < 0 ? o.base.inner_knots : o.inner_knots[0], o.inner_knots[1], o.inner_knots[2]})},
              {"iterations", g.iterations},
              {"samples", g.samples},
              {"objective", Json{{"before", g.objective_before}, {"after", g.objective_after}}},
              {"max_abs_f_on_samples", Json{{"before", g.max_abs_f_before}, {"after", g.max_abs_f_after}}},
              {"seconds", g.seconds},
              {"meaning", "Eq. 6 (at this weight; the paper's is 10) added and minimized by Gauss-Newton in double from the initial patch, then projected "
                          "exactly onto the vertex equalities; the validity above is decided exactly on that patch"}};
}


template Json guide_json(const GuideResult<Rational>&, const std::optional<SeparationResult>&);
template Json guide_json(const GuideResult<double>&, const std::optional<SeparationResult>&);
template Json guide3_json(const GuideResult3<Rational>&, const std::optional<SeparationResult3>&);
template Json guide3_json(const GuideResult3<double>&, const std::optional<SeparationResult3>&);
template Json surface_json(const CuttingSurface<Rational>&, const Frame3&);
template Json surface_json(const CuttingSurface<double>&, const Frame3&);

}  // namespace splinex::cut
