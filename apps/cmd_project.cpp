// splinex project: the orthogonal projection of a point onto a surface (papers/002 Eq. 3), with
// certificates (solve/projection.hpp); splinex contact: the minimum distance of two surfaces
// (Eq. 4, solve/contact.hpp). In double the same subdivision runs, uncertified.
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "float/rounding.hpp"
#include "experiments/solve_study.hpp"
#include "experiments/svg_plot.hpp"
#include "io/solve_io.hpp"

namespace splinex::app {

namespace {

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
               const auto C = read_spline(o->curve, ctx.limits, ctx.read_limits, "curve");
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
               print_document(curve_projection_document(r));
               return 0;
             }
             if (!o->svg.empty() || !o->obj.empty()) throw UsageError("svg", "figures are drawn for --curve only", "leave --svg and --obj out");
             const auto P = parse_number_list(o->point, "point");
             if (P.size() != 3) throw UsageError("point", "has " + std::to_string(P.size()) + " coordinates", "write --point \"x,y,z\"");
             SolveOptions so;
             so.max_depth = o->max_depth;
             so.max_boxes = o->max_boxes;
             so.progress = [](const std::string& line) { std::cerr << "[project] " << line << "\n"; };
             if (o->arith == "double") {
               print_document(projection_document(project_point(round_spline<double>(S), round_values<double>(P, "point"), so, ctx.limits)));
               return 0;
             }
             {
               check_exact_bits(S, "surface", o->max_bits);
               for (const auto& x : P)
                 if (bit_size(x) > o->max_bits)
                   throw SizeLimitError("point", "has a number of " + std::to_string(bit_size(x)) + " bits, over the exact limit of " + std::to_string(o->max_bits),
                                        "give the number with fewer digits, raise --max-bits, or use --arith double");
               print_document(projection_document(project_point(S, P, so, ctx.limits)));
             }
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
             print_document(o->arith == "double"
                                ? contact_document(surface_distance(round_spline<double>(S1), round_spline<double>(S2), so, ctx.limits, o->penetration))
                                : contact_document(surface_distance(S1, S2, so, ctx.limits, o->penetration)));
             return 0;
           }}};
}

}  // namespace splinex::app
