// splinex project: the orthogonal projection of a point onto a surface (papers/002 Eq. 3), with
// certificates (solve/projection.hpp); splinex contact: the minimum distance of two surfaces
// (Eq. 4, solve/contact.hpp). In double the same subdivision runs, uncertified.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "float/rounding.hpp"
#include "experiments/solve_study.hpp"
#include "experiments/svg_plot.hpp"
#include "solve/contact.hpp"
#include "solve/curve_projection.hpp"
#include "solve/projection.hpp"

namespace splinex::app {

namespace {

template <class T>
Json box_json(const std::vector<T>& lo, const std::vector<T>& hi) {
  return Json{{"lo", point_to_json(lo)}, {"hi", point_to_json(hi)}};
}

template <class T>
Json range_json(const T& lo, const T& hi) {
  return Json{{"lo", ArithTraits<T>::to_json(lo)}, {"hi", ArithTraits<T>::to_json(hi)}};
}

template <class T>
Json critical_json(const CriticalPoint<T>& c) {
  Json j{{"where", c.where}, {"stratum", c.stratum}, {"point", point_to_json(c.point)}, {"distance2", range_json(c.d2_lo, c.d2_hi)}};
  if (c.exact) {
    j["parameters"] = point_to_json(c.lo);
    j["certificate"] = ArithTraits<T>::exact ? (c.where == "corner" ? "a corner of the stratum" : "exact root: the equations are 0 there")
                                             : "exact in double only (not certified)";
  } else {
    j["parameters"] = box_json(c.lo, c.hi);
    j["certificate"] = !ArithTraits<T>::exact ? "none (double)"
                       : c.merged        ? "boxes from both sides of a knot line overlap: one critical point or two very close ones"
                       : c.unique        ? "Krawczyk: exactly one simple root in the box"
                                         : "none: undecided";
  }
  if (c.exact && !c.unique && c.where != "corner") j["certificate"] = "exact root, multiplicity not decided (its box stays undecided)";
  if (!c.along.empty()) {
    // A segment of critical points: the distance is constant along it (an equation vanished).
    j["parameters"] = box_json(c.lo, c.hi);
    j["certificate"] = std::string("the distance is constant along the segment (an equation vanishes identically); ") +
                       (c.collapsed ? "the segment is one point in space (exact)" : "its points are distinct points at the same distance, or undecided");
  }
  return j;
}

/// What projection and contact results share: the arithmetic, the certified flag, the enclosure
/// of the smallest squared distance and its square root in double (when finite).
template <class T, class Result>
Json distance_summary(const Result& r) {
  Json out;
  out["arithmetic"] = ArithTraits<T>::name();
  out["closest_certified"] = r.closest_certified;
  out["distance2"] = range_json(r.distance2_lo, r.distance2_hi);
  if (const double d = std::sqrt(to_double(ArithTraits<T>::to_rational(r.distance2_hi))); std::isfinite(d)) out["distance_approx"] = d;
  return out;
}

template <class T>
Json projection_json(const ProjectionResult<T>& r) {
  Json out = distance_summary<T>(r);
  out["complete"] = r.complete;
  Json closest = Json::array();
  for (std::size_t i : r.closest) closest.push_back(critical_json(r.critical[i]));
  out["closest"] = closest;
  Json all = Json::array();
  for (const auto& c : r.critical) all.push_back(critical_json(c));
  out["critical_points"] = all;
  Json und = Json::array(), und_closest = Json::array();
  for (const auto& c : r.undecided) und.push_back(critical_json(c));
  for (std::size_t i : r.undecided_closest) und_closest.push_back(critical_json(r.undecided[i]));
  out["undecided"] = und;
  out["undecided_closest"] = und_closest;
  out["boxes"] = r.boxes;
  std::string verdict;
  if (!ArithTraits<T>::exact)
    verdict = "not certified: the subdivision ran in " + ArithTraits<T>::name();
  else if (r.closest_certified)
    verdict = std::string("certified: the closest point is in the first box of \"closest\"") +
              (r.complete ? ", and every critical point is listed" : "; some critical points stay undecided (farther away)");
  else
    verdict = "not certified: " + r.reason + " (" + std::to_string(r.closest.size()) + " candidates in \"closest\", " +
              std::to_string(r.undecided_closest.size()) + " boxes in \"undecided_closest\"); the distance is enclosed";
  out["verdict"] = verdict;
  return out;
}

template <class T>
Json contact_point_json(const ContactPoint<T>& p) {
  Json j{{"where", p.where}, {"strata", p.strata}, {"distance2", range_json(p.d2_lo, p.d2_hi)}};
  if (!p.p1.empty()) {
    j["point1"] = point_to_json(p.p1);
    j["point2"] = point_to_json(p.p2);
  }
  if (p.exact)
    j["parameters"] = point_to_json(p.lo);
  else
    j["parameters"] = box_json(p.lo, p.hi);
  if (!p.along.empty()) j["parameters"] = box_json(p.lo, p.hi);
  j["certificate"] = !ArithTraits<T>::exact ? "none (double)"
                     : p.where == "intersection" ? (p.exact ? "exact common point" : "Krawczyk: one common point of S1 - S2 = 0 (one parameter fixed) in the box")
                     : p.where == "corner-corner" ? "corners of the strata"
                     : p.merged ? "boxes of neighbouring strata overlap: one pair or two very close ones"
                     : p.exact && p.unique ? "exact root, certified simple"
                     : p.exact ? "exact root, multiplicity not decided"
                     : p.unique ? "Krawczyk: exactly one simple root in the box"
                                : "none: undecided";
  if (!p.along.empty())
    j["certificate"] = std::string("the distance is constant along the segment of parameters (an equation vanishes identically); ") +
                       (p.collapsed ? "the segment is one pair of points in space (exact)" : "its pairs are distinct pairs at the same distance, or undecided");
  return j;
}

template <class T>
Json contact_json(const ContactResult<T>& r) {
  Json out = distance_summary<T>(r);
  // "undecided": no common point was found, but the minimum's enclosure reaches 0.
  out["intersecting"] = r.intersecting ? Json(true) : r.intersection_undecided ? Json("undecided") : Json(false);
  Json closest = Json::array(), pts = Json::array(), und = Json::array(), und_closest = Json::array();
  for (std::size_t i : r.closest) closest.push_back(contact_point_json(r.points[i]));
  for (const auto& p : r.points) pts.push_back(contact_point_json(p));
  for (const auto& p : r.undecided) und.push_back(contact_point_json(p));
  for (std::size_t i : r.undecided_closest) und_closest.push_back(contact_point_json(r.undecided[i]));
  out["closest"] = closest;
  out["stationary_pairs"] = pts;
  out["undecided"] = und;
  out["undecided_closest"] = und_closest;
  out["strata_pairs"] = Json{{"all", r.strata_pairs}, {"solved", r.pairs_solved}, {"skipped", r.pairs_skipped}};
  out["boxes"] = r.boxes;
  if (r.intersecting && (!r.extremes.empty() || r.extremes_complete)) {
    Json pen, ex = Json::array();
    for (const auto& p : r.extremes) {
      Json j = contact_point_json(p);
      j["side1"] = p.side1;
      j["side2"] = p.side2;
      ex.push_back(j);
    }
    pen["stationary_pairs"] = ex;
    pen["complete"] = r.extremes_complete;
    pen["first_into_second"] = r.deepest_1_in_2 < 0 ? Json(nullptr) : contact_point_json(r.extremes[r.deepest_1_in_2]);
    pen["second_into_first"] = r.deepest_2_in_1 < 0 ? Json(nullptr) : contact_point_json(r.extremes[r.deepest_2_in_1]);
    out["penetration"] = pen;
  }
  std::string verdict;
  if (!ArithTraits<T>::exact)
    verdict = std::string("not certified: the subdivision ran in ") + ArithTraits<T>::name() +
              (r.intersecting ? "; a common point was found (in double)" : r.intersection_undecided ? "; whether the surfaces meet is undecided" : "");
  else if (r.intersecting)
    verdict = "certified: the surfaces intersect (a common point is certified), the minimum distance is 0";
  else if (r.closest_certified)
    verdict = "certified: the closest pair of points is in \"closest\" (one entry per pair of parameters giving them), the minimum distance is "
              "enclosed in \"distance2\"";
  else
    verdict = "not certified: " + r.reason + " (" + std::to_string(r.closest.size()) + " pairs in \"closest\", " +
              std::to_string(r.undecided_closest.size()) + " boxes in \"undecided_closest\"); the minimum distance is enclosed" +
              (r.intersection_undecided ? ", and whether the surfaces meet is undecided" : "");
  out["verdict"] = verdict;
  return out;
}

Json curve_projection_json(const CurveProjectionResult& r) {
  Json out;
  out["segments"] = r.segments;
  out["loops"] = r.loops;
  out["certified_counts"] = r.certified_counts;
  out["consistent"] = r.consistent;
  out["max_cosine"] = r.max_cosine;
  out["traced_points"] = r.traced_points;
  out["boxes"] = r.boxes;
  Json sp = Json::array();
  for (const auto& p : r.special) {
    Json j{{"kind", p.kind}, {"where", p.where}, {"branches", p.branches}};
    j["parameters"] = p.exact ? point_to_json(p.lo) : box_json(p.lo, p.hi);
    j["certificate"] = p.exact && p.unique ? "exact root, certified simple" : p.exact ? "exact root, multiplicity not decided" : p.unique ? "Krawczyk: one simple root in the box" : "none";
    sp.push_back(j);
  }
  out["special_points"] = sp;
  Json und = Json::array();
  for (const auto& p : r.undecided) und.push_back(Json{{"where", p.where}, {"parameters", box_json(p.lo, p.hi)}});
  out["undecided"] = und;
  Json sl = Json::array();
  for (const auto& s : r.slices) sl.push_back(Json{{"t", to_fraction_string(s.t)}, {"branches", s.roots}, {"certified", s.certified}});
  out["slices"] = sl;
  std::string verdict;
  if (r.certified_counts && r.consistent)
    verdict = "certified: the end and turning points and the number of branches between them; the joins traced in double agree with them (" +
              std::to_string(r.segments) + " segments, " + std::to_string(r.loops) + " loops)";
  else if (r.certified_counts)
    verdict = "not certified: the special points and counts are certified, but the traced joins do not agree with them";
  else
    verdict = "not certified: some special points or slices stay undecided";
  out["verdict"] = verdict;
  return out;
}

// Exact runs: every number of the inputs within max_bits (SizeLimitError naming the field before
// any work). A coordinate of 10^100000 made an exact projection take half a minute.
void check_exact_bits(const BSpline<Rational>& S, const std::string& field, std::size_t max_bits) {
  auto check = [&](const std::vector<Rational>& v, const std::string& part) {
    for (const auto& x : v)
      if (bit_size(x) > max_bits)
        throw SizeLimitError(field + "." + part, "has a number of " + std::to_string(bit_size(x)) + " bits, over the exact limit of " + std::to_string(max_bits),
                             "give the number with fewer digits, raise --max-bits, or use --arith double");
  };
  check(S.points, "points");
  check(S.weights, "weights");
  for (const auto& U : S.knots) check(U, "knots");
}

}  // namespace

Commands add_project(CLI::App& app) {
  struct Options {
    std::string arith = "exact", file, point, curve, svg, obj;
    int max_depth = 30, steps = 48;
    std::size_t max_boxes = 20000, max_bits = 4096;
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("project",
                               "orthogonal projection onto a surface: of a point (all critical points of the distance, the closest one certified) "
                               "or of a curve (Eq. 3: the solution curves, special points certified, branches traced)");
  add_arith_option(c, o->arith, "exact (certified) or double (the same subdivision in double, uncertified; --point only)")
      ->check(CLI::IsMember({"exact", "double"}));
  auto* point = c->add_option("--point", o->point, "the point \"x,y,z\"");
  auto* curve = c->add_option("--curve", o->curve, "a curve document (polynomial or rational, points x,y,z)");
  point->excludes(curve);
  c->add_option("--max-bits", o->max_bits, "exact runs: the largest input number (numerator or denominator, bits), checked before the work")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
      ->capture_default_str();
  c->add_option("--steps", o->steps, "--curve: tracing steps in t between critical values")->check(CLI::Range(2, 100000))->capture_default_str();
  c->add_option("--svg", o->svg, "--curve: write the parameter-domain and top-view figure here")->check(output_file());
  c->add_option("--obj", o->obj, "--curve: write the curve, the surface's boundary and the projection as OBJ polylines here")->check(output_file());
  c->add_option("--max-depth", o->max_depth, "halvings per direction before a box is undecided")->check(CLI::Range(1, 200))->capture_default_str();
  c->add_option("--max-boxes", o->max_boxes, "solver boxes per system before the rest is undecided (ten times this in all)")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
      ->capture_default_str();
  c->add_option("surface", o->file, "spline surface document (- for stdin), or teapot:body|handle|spout|lid")->required();
  return {{c, [o](const Context& ctx) {
             const auto S = read_surface_argument(o->file, "surface", ctx);
             if (o->point.empty() == o->curve.empty()) throw UsageError("project", "needs --point or --curve", "give one of them");
             if (!o->curve.empty()) {
               if (o->arith != "exact") throw UsageError("arith", "--curve runs in exact arithmetic only", "leave --arith out");
               const auto C = spline_from_json(read_json_file(o->curve, ctx.read_limits), ctx.limits, "curve");
               check_exact_bits(S, "surface", o->max_bits);
               check_exact_bits(C, "curve", o->max_bits);
               CurveProjectionOptions co;
               co.solve.max_depth = o->max_depth;
               co.solve.max_boxes = o->max_boxes;
               co.steps = o->steps;
               co.solve.progress = [](const std::string& line) { std::cerr << "[project --curve] " << line << "\n"; };
               const auto r = project_curve(C, S, co, ctx.limits);
               if (!o->svg.empty()) write_file_atomically(o->svg, curve_projection_svg(C, S, r, "Projection of a curve onto a surface (papers/002 Eq. 3)"));
               if (!o->obj.empty()) write_file_atomically(o->obj, curve_projection_obj(C, S, r));
               std::cout << curve_projection_json(r).dump() << "\n";
               return 0;
             }
             if (!o->svg.empty() || !o->obj.empty()) throw UsageError("svg", "figures are drawn for --curve only", "leave --svg and --obj out");
             const auto P = parse_number_list(o->point, "point");
             if (P.size() != 3) throw UsageError("point", "has " + std::to_string(P.size()) + " coordinates", "write --point \"x,y,z\"");
             SolveOptions so;
             so.max_depth = o->max_depth;
             so.max_boxes = o->max_boxes;
             so.progress = [](const std::string& line) { std::cerr << "[project] " << line << "\n"; };
             Json out;
             if (o->arith == "double")
               out = projection_json(project_point(round_spline<double>(S), round_values<double>(P, "point"), so, ctx.limits));
             else {
               check_exact_bits(S, "surface", o->max_bits);
               for (const auto& x : P)
                 if (bit_size(x) > o->max_bits)
                   throw SizeLimitError("point", "has a number of " + std::to_string(bit_size(x)) + " bits, over the exact limit of " + std::to_string(o->max_bits),
                                        "give the number with fewer digits, raise --max-bits, or use --arith double");
               out = projection_json(project_point(S, P, so, ctx.limits));
             }
             std::cout << out.dump() << "\n";
             return 0;
           }}};
}

Commands add_contact(CLI::App& app) {
  struct Options {
    std::string arith = "exact", first, second;
    int max_depth = 30;
    std::size_t max_boxes = 20000, max_bits = 4096;
    bool penetration = false;
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("contact", "minimum distance of two surfaces (Eq. 4 and its boundary and knot-line cases), certified, or a certified common point");
  add_arith_option(c, o->arith, "exact (certified) or double (the same subdivision in double, uncertified)")
      ->check(CLI::IsMember({"exact", "double"}));
  c->add_option("--max-depth", o->max_depth, "halvings per direction before a box is undecided")->check(CLI::Range(1, 200))->capture_default_str();
  c->add_option("--max-boxes", o->max_boxes, "solver boxes per pair of strata before the rest is undecided (ten times this in all)")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
      ->capture_default_str();
  c->add_option("--max-bits", o->max_bits, "exact runs: the largest input number (numerator or denominator, bits), checked before the work")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
      ->capture_default_str();
  c->add_flag("--penetration", o->penetration,
              "intersecting surfaces: also the stationary pairs away from the intersection and the deepest penetration each way (slow: the "
              "subdivision follows the intersection curve)");
  c->add_option("first", o->first, "first surface document, or teapot:body|handle|spout|lid")->required();
  c->add_option("second", o->second, "second surface document, or teapot:body|handle|spout|lid")->required();
  return {{c, [o](const Context& ctx) {
             const auto S1 = read_surface_argument(o->first, "first", ctx), S2 = read_surface_argument(o->second, "second", ctx);
             if (o->arith != "double") check_exact_bits(S1, "first", o->max_bits), check_exact_bits(S2, "second", o->max_bits);
             SolveOptions so;
             so.max_depth = o->max_depth;
             so.max_boxes = o->max_boxes;
             so.progress = [](const std::string& line) { std::cerr << "[contact] " << line << "\n"; };
             const Json out = o->arith == "double"
                                  ? contact_json(surface_distance(round_spline<double>(S1), round_spline<double>(S2), so, ctx.limits, o->penetration))
                                  : contact_json(surface_distance(S1, S2, so, ctx.limits, o->penetration));
             std::cout << out.dump() << "\n";
             return 0;
           }}};
}

}  // namespace splinex::app
