#include "io/solve_io.hpp"

#include <cmath>

#include "float/mpfr.hpp"

namespace splinex {

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

}  // namespace

template <class T>
Json projection_document(const ProjectionResult<T>& r) {
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

namespace {

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

}  // namespace

template <class T>
Json contact_document(const ContactResult<T>& r) {
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

Json curve_projection_document(const CurveProjectionResult& r) {
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

template Json projection_document(const ProjectionResult<Rational>&);
template Json projection_document(const ProjectionResult<double>&);
template Json contact_document(const ContactResult<Rational>&);
template Json contact_document(const ContactResult<double>&);

}  // namespace splinex
