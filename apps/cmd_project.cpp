// splinex project: the orthogonal projection of a point onto a surface (papers/002 Eq. 3), with
// certificates (solve/projection.hpp); in double the same subdivision, uncertified.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "float/rounding.hpp"
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
  return j;
}

template <class T>
Json projection_json(const ProjectionResult<T>& r) {
  Json out;
  out["arithmetic"] = ArithTraits<T>::name();
  out["complete"] = r.complete;
  out["closest_certified"] = r.closest_certified;
  out["distance2"] = range_json(r.distance2_lo, r.distance2_hi);
  out["distance_approx"] = std::sqrt(to_double(ArithTraits<T>::to_rational(r.distance2_hi)));
  Json closest = Json::array();
  for (std::size_t i : r.closest) closest.push_back(critical_json(r.critical[i]));
  out["closest"] = closest;
  Json all = Json::array();
  for (const auto& c : r.critical) all.push_back(critical_json(c));
  out["critical_points"] = all;
  Json und = Json::array();
  for (const auto& c : r.undecided) und.push_back(critical_json(c));
  out["undecided"] = und;
  out["boxes"] = r.boxes;
  std::string verdict;
  if (!ArithTraits<T>::exact)
    verdict = "not certified: the subdivision ran in " + ArithTraits<T>::name();
  else if (r.closest_certified)
    verdict = std::string("certified: the closest point is in the first box of \"closest\"") +
              (r.complete ? ", and every critical point is listed" : "; some critical points stay undecided (farther away)");
  else
    verdict = "not certified: " + std::to_string(r.closest.size()) + " candidates (or undecided boxes) may be the closest; the distance is enclosed";
  out["verdict"] = verdict;
  return out;
}

}  // namespace

Commands add_project(CLI::App& app) {
  struct Options {
    std::string arith = "exact", file, point;
    int max_depth = 30;
    std::size_t max_boxes = 200000;
  };
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("project", "orthogonal projection of a point onto a surface: all critical points of the distance, the closest one certified");
  add_arith_option(c, o->arith, "exact (certified) or double (the same subdivision in double, uncertified)")
      ->check(CLI::IsMember({"exact", "double"}));
  c->add_option("--point", o->point, "the point \"x,y,z\"")->required();
  c->add_option("--max-depth", o->max_depth, "halvings per direction before a box is undecided")->check(CLI::Range(1, 200))->capture_default_str();
  c->add_option("--max-boxes", o->max_boxes, "solver boxes per system before the rest is undecided")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
      ->capture_default_str();
  c->add_option("surface", o->file, "spline surface document, - for stdin")->required();
  return {{c, [o](const Context& ctx) {
             const auto S = spline_from_json(read_json_file(o->file, ctx.read_limits), ctx.limits);
             const auto P = parse_number_list(o->point, "point");
             if (P.size() != 3) throw UsageError("point", "has " + std::to_string(P.size()) + " coordinates", "write --point \"x,y,z\"");
             SolveOptions so;
             so.max_depth = o->max_depth;
             so.max_boxes = o->max_boxes;
             Json out;
             if (o->arith == "double")
               out = projection_json(project_point(round_spline<double>(S), round_values<double>(P, "point"), so, ctx.limits));
             else
               out = projection_json(project_point(S, P, so, ctx.limits));
             std::cout << out.dump() << "\n";
             return 0;
           }}};
}

}  // namespace splinex::app
