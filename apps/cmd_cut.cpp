// splinex cut: papers/004's cutting curves (d = 2). `cut example NAME` writes an example solid and
// its cutting data; `cut guide SOLID CUT` finds the implicit guiding curve by RDCP (exact QP, KKT
// checked exactly; or in double) and certifies the separation of b and b-bar by f* on the whole
// boundary.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "cut/curve_facet.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "cut/surface_facet.hpp"
#include "experiments/cut_figure.hpp"
#include "experiments/svg_plot.hpp"
#include "cut/io/commands.hpp"
#include "spline/knots.hpp"

namespace splinex::app {

namespace {

using namespace splinex::cut;  // the documents of cut/io/documents.hpp

struct GuideCliOptions {
  std::string solid, cut, arith = "exact", svg, vtk, delta = "1/20", strip = "1/16", li = "1", lt = "1", lr = "1/100";
  int inner = 3, inner_y = -1, inner_z = -1, max_inner = 7, samples = 16, loop_samples = 4;
  std::size_t max_size = 400000;
  CLI::Option *inner_opt = nullptr, *max_inner_opt = nullptr, *samples_opt = nullptr, *max_size_opt = nullptr;
};

void add_guide_options(CLI::App* g, GuideCliOptions& go) {
  g->add_option("solid", go.solid, "solid document {\"type\": \"solid2d\", ...}")->required();
  g->add_option("cut", go.cut, "cutting data document {\"type\": \"cut2d\", ...}")->required();
  go.inner_opt = g->add_option("--inner-knots", go.inner, "uniform inner knots per direction of the cubic guide (solid3d: default 1)")->check(CLI::Range(0, 1000))->capture_default_str();
  g->add_option("--inner-knots-y", go.inner_y, "inner knots in y, if not as many as in x (-1)")->check(CLI::Range(-1, 1000))->capture_default_str();
  go.max_inner_opt = g->add_option("--max-inner-knots", go.max_inner, "dyadic refinement (k -> 2k+1) while infeasible, up to this (solid3d: default 3)")->check(CLI::Range(0, 1000))->capture_default_str();
  go.samples_opt = g->add_option("--samples", go.samples, "sample points per facet (b* and b-bar*); solid3d: per facet direction, default 4")->check(CLI::Range(1, 100000))->capture_default_str();
  go.max_size_opt = g->add_option("--max-size", go.max_size,
                                  "the program's size limit, variables x (variables + rows), checked before any work (solid3d: default 60000, "
                                  "about 2 minutes exactly)")
                       ->check(CLI::Range(std::size_t(1), std::size_t(100000000)))
                       ->capture_default_str();
  g->add_option("--delta", go.delta, "the margin: f* >= delta on b*, <= -delta on b-bar*")->capture_default_str();
  g->add_option("--strip", go.strip, "no samples (and no certification) within this max-norm distance of the cut points, normalized units")->capture_default_str();
  g->add_option("--lambda-int", go.li, "weight of F_int")->capture_default_str();
  g->add_option("--lambda-tan", go.lt, "weight of F_tan")->capture_default_str();
  g->add_option("--lambda-reg", go.lr, "weight of F_reg (Eq. 3)")->capture_default_str();
}

GuideOptions to_guide_options(const GuideCliOptions& go) {
  GuideOptions o;
  o.inner_knots = go.inner;
  o.inner_knots_y = go.inner_y;
  o.max_inner_knots = go.max_inner;
  o.samples = go.samples;
  o.max_size = go.max_size;
  o.delta = parse_number(go.delta, "delta");
  o.strip = parse_number(go.strip, "strip");
  o.lambda_int = parse_number(go.li, "lambda-int");
  o.lambda_tan = parse_number(go.lt, "lambda-tan");
  o.lambda_reg = parse_number(go.lr, "lambda-reg");
  return o;
}

// A cutting curve document must be a polynomial curve in the plane.
void check_cutting_curve_shape(const BSpline<Rational>& C) {
  if (C.dim() != 1 || C.q != 2) throw ValidationError("curve", "is not a curve in R^2", "give a spline with one parameter and 2 coordinates");
  if (C.is_rational()) throw ValidationError("curve", "is rational", "give a polynomial curve");
  if (C.degrees[0] < 1) throw ValidationError("curve", "has degree 0", "give a continuous curve of degree >= 1");
  if (!is_clamped(C.knots[0], C.degrees[0], C.count(0))) throw ValidationError("curve.knots", "is not clamped", "clamp the knot vector");
}

struct CertifyCliOptions {
  std::string solid, cut, curve, out;
};

/// cut certify and cut split: the solid, the validated cutting data and the curve (typed errors).
struct CurveInput {
  Solid2<Rational> solid;
  CutData2<Rational> cut;
  BSpline<Rational> curve;
};
CurveInput read_curve_input(const SolidDocument& solid, const CertifyCliOptions& o, const Context& ctx) {
  auto S = solid.solid2(ctx.limits);
  auto C = validate_cut(S, read_cut2(o.cut, ctx.read_limits));
  auto curve = read_spline(o.curve, ctx.limits, ctx.read_limits, "curve");
  check_cutting_curve_shape(curve);
  return {std::move(S), std::move(C), std::move(curve)};
}

GuideOptions3 to_guide3_options(const GuideCliOptions& go) {
  GuideOptions3 o;
  const GuideOptions b = to_guide_options(go);
  // the 2D defaults of --inner-knots, --max-inner-knots and --samples give way to the 3D ones
  o.base.delta = b.delta, o.base.strip = b.strip, o.base.lambda_int = b.lambda_int, o.base.lambda_tan = b.lambda_tan, o.base.lambda_reg = b.lambda_reg;
  if (go.inner_opt && go.inner_opt->count()) o.base.inner_knots = go.inner;
  if (go.max_inner_opt && go.max_inner_opt->count()) o.base.max_inner_knots = go.max_inner;
  if (go.samples_opt && go.samples_opt->count()) o.base.samples = go.samples;
  if (go.max_size_opt && go.max_size_opt->count()) o.base.max_size = go.max_size;
  o.inner_knots = {-1, go.inner_y, go.inner_z};
  o.loop_samples = go.loop_samples;
  return o;
}

int run_guide3(const GuideCliOptions& go, const Solid3<Rational>& S, const Context& ctx) {
  const auto C = read_cut3(go.cut, ctx.read_limits);
  if (!go.svg.empty()) throw UsageError("svg", "is for solid2d documents", "give --vtk DIR for a solid3d");
  const GuideOptions3 o = to_guide3_options(go);
  validate_cut(S, C);  // every typed error before the first progress line
  validate_guide_options(o, S.facets.size());
  if (go.arith != "double") check_exact_sizes(S, C, o.base);
  auto run = [&](auto tag) {
    using T = decltype(tag);
    std::cerr << "[cut guide] " << ArithTraits<T>::name() << ": solving RDCP in three variables\n";
    const auto R = guide_surface<T>(S, C, o);
    std::optional<SeparationResult3> sep;
    if (R.status == QPStatus::optimal) {
      std::cerr << "[cut guide] " << ArithTraits<T>::name() << ": certifying the separation\n";
      sep = certify_separation(R.solid, R.loop, C.positive, R.f_exact, o.base.strip);
    }
    return GuideRun3<T>{R, sep};
  };
  std::optional<GuideRun3<Rational>> exact;
  std::optional<GuideRun3<double>> dbl;
  std::optional<std::pair<BSpline<Rational>, Frame3>> drawn;
  if (go.arith == "exact" || go.arith == "both") {
    exact = run(Rational());
    if (exact->result.status == QPStatus::optimal) drawn = std::make_pair(exact->result.f_exact, exact->result.frame);
    if (go.arith == "both") dbl = run(double());
  } else {
    dbl = run(double());
    if (dbl->result.status == QPStatus::optimal) drawn = std::make_pair(dbl->result.f_exact, dbl->result.frame);
  }
  std::string vtk;
  if (!go.vtk.empty()) {
    std::filesystem::create_directories(go.vtk);
    write_file_atomically((std::filesystem::path(go.vtk) / "solid.vtk").string(), solid3_vtk(S));
    if (drawn) write_file_atomically((std::filesystem::path(go.vtk) / "guide.vtk").string(), guide3_vtk(drawn->first, drawn->second.lo, drawn->second.scale, 32));
    vtk = drawn ? "solid.vtk and guide.vtk written" : "solid.vtk written; no guide (RDCP infeasible)";
  }
  print_document(guide3_runs_document(exact ? &*exact : nullptr, dbl ? &*dbl : nullptr, vtk));
  return 0;
}

// ---- d = 3: the cutting surface ----------------------------------------------------------------

struct Facet3CliOptions {
  std::string domain = "auto", weight_boundary = "1", weight_fair = "1", lambda = "1", tangent_delta = "1/20", strip = "1/16";
  int inner = 3, samples = 4, max_depth = 14;
  std::string arith = "exact", vtk, out;
  bool guided = false;
  std::string weight_guide = "10";
  int guide_grid = 16, guide_iterations = 30;
};

SurfaceFacetOptions to_surface_options(const Facet3CliOptions& f) {
  SurfaceFacetOptions o;
  o.domain = f.domain;
  o.inner_knots = f.inner;
  o.boundary_samples = f.samples;
  o.weight_boundary = parse_number(f.weight_boundary, "weight-boundary");
  o.weight_fair = parse_number(f.weight_fair, "weight-fair");
  o.lambda = parse_number(f.lambda, "lambda-normal");
  o.tangent_delta = parse_number(f.tangent_delta, "tangent-delta");
  o.strip = parse_number(f.strip, "strip");
  o.max_depth = f.max_depth;
  o.progress = true;
  validate_surface_options(o);
  return o;
}

// The two parts of a valid surface's split, as facet lists, into dir/split.json.
SurfaceSplit write_surface_split(const Solid3<Rational>& S, const CutData3& C, const std::string& dir) {
  const auto sp = split_by_surface(S, C.positive);
  write_file_atomically((std::filesystem::path(dir) / "split.json").string(), document_text(surface_split_parts_document(sp), 1));
  return sp;
}

int run_facet3(const Facet3CliOptions& fo, const GuideCliOptions& gco, const Solid3<Rational>& S, const std::string& cut_file, const Context& ctx) {
  const auto C = read_cut3(cut_file, ctx.read_limits);
  const auto o = to_surface_options(fo);
  validate_cut(S, C);  // typed errors before the first progress line
  const Frame3 frame = unit_frame(S);
  const auto Sn = to_frame(S, frame);
  const auto loop = validate_cut(Sn, C);
  check_patch_program(loop, o);  // Step 1's and the interpolation conditions' typed errors too
  if (fo.arith != "exact")  // the double program is assembled from these weights' doubles
    for (const auto& [name, w] : {std::pair<const char*, const Rational*>{"weight-boundary", &o.weight_boundary}, {"weight-fair", &o.weight_fair},
                                  {"lambda-normal", &o.lambda}, {"tangent-delta", &o.tangent_delta}})
      if (!std::isfinite(to_double(*w))) throw UsageError(name, "is beyond double's range", "give a smaller number, or --arith exact");
  GuidedOptions gopt;
  gopt.grid = fo.guide_grid, gopt.iterations = fo.guide_iterations;
  // --weight-guide W, or auto: the sweep 10, 10^2, ..., 10^6 until the refined patch is valid
  std::vector<double> weights;
  if (fo.weight_guide == "auto") {
    weights = {10, 1e2, 1e3, 1e4, 1e5, 1e6};
  } else {
    const double w = to_double(parse_number(fo.weight_guide, "weight-guide"));
    if (!std::isfinite(w)) throw UsageError("weight-guide", "is beyond double's range", "give a smaller number, or auto");
    weights = {w};
  }
  gopt.weight_guide = weights.front();
  const GuideOptions3 g3 = to_guide3_options(gco);
  std::optional<BSpline<double>> guide;
  std::string guide_status;
  if (fo.guided) {
    validate_guide_options(g3, S.facets.size());
    if (fo.arith != "double") check_exact_sizes(S, C, g3.base);
    validate_guided_options(gopt);
    std::cerr << "[cut facet] the guiding surface (RDCP, " << (fo.arith == "double" ? "double" : "exact") << ")\n";
    auto to_d = [](const BSpline<Rational>& f) { return convert<double>(f, [](const Rational& x) { return to_double(x); }); };
    if (fo.arith == "double") {
      const auto G = guide_surface<double>(S, C, g3);
      guide_status = "double, " + to_string(G.status);
      if (G.status == QPStatus::optimal) guide = to_d(G.f_exact);
    } else {
      const auto G = guide_surface<Rational>(S, C, g3);
      guide_status = "exact, " + to_string(G.status);
      if (G.status == QPStatus::optimal) guide = to_d(G.f_exact);
    }
    // RDCP infeasible is a result (printed below), not an error: the progress lines are out already
  }
  auto run = [&](auto tag) {
    using T = decltype(tag);
    std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": the patch program (Step 1 and 2)\n";
    const auto R = cutting_surface<T>(loop, o);
    std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": certifying the surface\n";
    auto V = certify_cutting_surface(Sn, loop, R.domain, R.patch, o);
    std::optional<std::vector<GuidedStep>> refined;
    if (guide) {
      CuttingSurface<Rational> init;
      init.domain = R.domain, init.patch = R.patch, init.coefficients = R.coefficients, init.program = R.program, init.equalities = R.equalities;
      std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": the guided refinement (Eq. 6, Gauss-Newton in double), certified\n";
      refined = refine_with_guide_sweep(Sn, loop, init, *guide, gopt, weights, o);
    }
    return SurfaceRun<T>{R, V, refined};
  };
  SurfaceRunSettings settings;
  settings.frame = frame, settings.guide = g3, settings.guide_status = guide_status;
  settings.weight_sweep = fo.weight_guide == "auto", settings.guided = fo.guided, settings.guide_found = guide.has_value();
  std::optional<SurfaceRun<Rational>> exact;
  std::optional<SurfaceRun<double>> dbl;
  if (fo.arith == "exact" || fo.arith == "both") exact = run(Rational());
  if (fo.arith != "exact") dbl = run(double());
  // what is drawn and written: the exact run's patch, else the double run's
  const auto drawn = exact ? std::make_pair(final_patch(*exact, frame), exact->surface.domain.vertices)
                           : std::make_pair(final_patch(*dbl, frame), dbl->surface.domain.vertices);
  const bool valid = exact ? final_validity(*exact).verdict.is_proved() : final_validity(*dbl).verdict.is_proved();
  if (!fo.vtk.empty()) {
    std::filesystem::create_directories(fo.vtk);
    write_file_atomically((std::filesystem::path(fo.vtk) / "solid.vtk").string(), solid3_vtk(S));
    write_file_atomically((std::filesystem::path(fo.vtk) / "surface.vtk").string(), surface3_vtk(drawn.first, drawn.second, 40));
    settings.vtk = true;
  }
  if (!fo.out.empty()) {
    std::filesystem::create_directories(fo.out);
    write_file_atomically((std::filesystem::path(fo.out) / "surface.json").string(), document_text(cutting_surface_document(drawn.first, drawn.second), 1));
    settings.out = true;
    if (valid) settings.split = write_surface_split(S, C, fo.out);
  }
  print_document(surface_facet_document(exact ? &*exact : nullptr, dbl ? &*dbl : nullptr, settings));
  return 0;
}

// A given cutting_surface document with its solid and cutting data (cut certify, cut split).
struct GivenSurface {
  Solid3<Rational> solid;
  CutData3 cut;
  CuttingSurfaceDoc surface;
};

GivenSurface read_given_surface(const SolidDocument& solid, const std::string& cut_file, const std::string& surface_file, const Context& ctx) {
  GivenSurface g;
  g.solid = solid.solid3(ctx.limits);
  g.cut = read_cut3(cut_file, ctx.read_limits);
  g.surface = read_cutting_surface(surface_file, ctx.limits, ctx.read_limits);
  return g;
}

// Section 2's conditions for the given surface, decided exactly in the normalized frame.
SurfaceValidity certify_given_surface(const GivenSurface& g, const Frame3& frame, const SurfaceFacetOptions& o) {
  const auto Sn = to_frame(g.solid, frame);
  const auto loop = validate_cut(Sn, g.cut);
  DomainPolygon D;
  D.method = "given";
  D.vertices = g.surface.domain;
  D.axes = projection_axes(loop);
  return certify_cutting_surface(Sn, loop, D, patch_to_frame(g.surface.patch, frame), o);
}

int run_certify3(const Facet3CliOptions& fo, const SolidDocument& solid, const std::string& cut_file, const std::string& surface_file, const Context& ctx) {
  const auto g = read_given_surface(solid, cut_file, surface_file, ctx);
  const auto o = to_surface_options(fo);
  const Frame3 frame = unit_frame(g.solid);
  print_document(surface_validity_document(certify_given_surface(g, frame, o), frame));
  return 0;
}

// cut split on a solid3d: the given surface certified (as cut certify), then the parts written.
int run_split3(const SolidDocument& solid, const std::string& cut_file, const std::string& surface_file, const std::string& out_dir, const Context& ctx) {
  const auto g = read_given_surface(solid, cut_file, surface_file, ctx);
  const auto V = certify_given_surface(g, unit_frame(g.solid), SurfaceFacetOptions{});
  if (!V.verdict.is_proved())
    throw DomainError("surface", std::string("is not certified valid (") + validity_word(V.verdict) + ": tangents " + certificate_word(V.tangents) +
                                     ", regular " + status_name(V.regular.status()) + ", injective " + status_name(V.injective.status()) +
                                     ", collision " + collision_word(V.collision) + ")",
                      "run cut certify to see why; split along a valid cutting surface");
  std::filesystem::create_directories(out_dir);
  write_file_atomically((std::filesystem::path(out_dir) / "surface.json").string(), document_text(cutting_surface_document(g.surface.patch, g.surface.domain), 1));
  const auto sp = write_surface_split(g.solid, g.cut, out_dir);
  print_document(surface_split_document((std::filesystem::path(out_dir) / "split.json").string(), sp, V.verdict));
  return 0;
}

/// `splinex cut example`: its options, and what it runs (the work is in cut/ and cut/io/).
Command cut_example_command(CLI::App* parent) {
  struct ExampleOptions {
    std::string name, out = ".";
  };
  auto eo = std::make_shared<ExampleOptions>();
  auto* ex = parent->add_subcommand("example", "write an example solid and its cutting data (NAME.solid.json, NAME.cut.json)");
  ex->add_option("name", eo->name, "2D: square, L, U, J, K, maze, snake; 3D: tower, cube, slotted, maiden, vase, twisted-vase")->required();
  ex->add_option("--out", eo->out, "folder to write into")->check(output_folder())->capture_default_str();
  return {ex, [eo](const Context&) {
    const auto docs = example_documents(eo->name);
    std::filesystem::create_directories(eo->out);
    const std::string sp = (std::filesystem::path(eo->out) / (eo->name + ".solid.json")).string();
    const std::string cp = (std::filesystem::path(eo->out) / (eo->name + ".cut.json")).string();
    write_file_atomically(sp, document_text(docs.solid, 1));
    write_file_atomically(cp, document_text(docs.cut, 1));
    print_document(example_written_document(sp, cp));
    return 0;
  }};
}

/// `splinex cut guide`: its options, and what it runs (the work is in cut/ and cut/io/).
Command cut_guide_command(CLI::App* parent) {
  auto go = std::make_shared<GuideCliOptions>();
  auto* g = parent->add_subcommand("guide", "the implicit guiding curve f* = 0 by RDCP (Eq. 2 with the constraints of DCP), and the certified separation");
  add_guide_options(g, *go);
  g->add_option("--inner-knots-z", go->inner_z, "solid3d: inner knots in z, if not as many as in x (-1)")->check(CLI::Range(-1, 1000))->capture_default_str();
  g->add_option("--loop-samples", go->loop_samples, "solid3d: points of L* per loop side")->check(CLI::Range(1, 1000))->capture_default_str();
  g->add_option("--vtk", go->vtk, "solid3d: write solid.vtk (the facets) and guide.vtk (f* on a 33^3 grid, contour it at 0 in ParaView) into this folder")->check(output_folder());
  add_arith_option(g, go->arith, "exact (the QP exactly, KKT checked), double (assembled in double), or both (and the double judged exactly)")
      ->check(CLI::IsMember({"exact", "double", "both"}));
  g->add_option("--svg", go->svg, "write the figure (boundary, samples, f* = 0, the certificate's witness) here")->check(output_file());
  return {g, [go](const Context& ctx) {
    const SolidDocument solid(go->solid, ctx.read_limits);
    if (solid.dimension() == 3) return run_guide3(*go, solid.solid3(ctx.limits), ctx);
    if (!go->vtk.empty()) throw UsageError("vtk", "is for solid3d documents", "leave --vtk out, or give --svg for a 2D figure");
    const auto S = solid.solid2(ctx.limits);
    const auto C = read_cut2(go->cut, ctx.read_limits);
    const GuideOptions o = to_guide_options(*go);
    validate_cut(S, C);  // every typed error before the first progress line
    validate_guide_options(o, S.facets.size());
    if (go->arith != "double") check_exact_sizes(S, C, o);
    auto run = [&](auto tag) {
      using T = decltype(tag);
      std::cerr << "[cut guide] " << ArithTraits<T>::name() << ": solving RDCP\n";
      const auto R = guide_curve<T>(S, C, o);
      std::optional<SeparationResult> sep;
      if (R.status == QPStatus::optimal) {
        std::cerr << "[cut guide] " << ArithTraits<T>::name() << ": certifying the separation\n";
        sep = certify_separation(R.solid, R.cut, R.f_exact, o.strip);
      }
      return GuideRun<T>{R, sep};
    };
    std::optional<GuideRun<Rational>> exact;
    std::optional<GuideRun<double>> dbl;
    std::string svg;
    if (go->arith == "exact" || go->arith == "both") {
      exact = run(Rational());
      const auto& [R, sep] = *exact;
      if (R.status == QPStatus::optimal)
        svg = cut_guide_svg(R.solid, R.cut, R.f_exact, R.sample_points, R.samples_positive, o.strip, sep ? &*sep : nullptr,
                            "Guiding curve (papers/004 RDCP), exact, " + std::to_string(R.inner_knots) + " inner knots");
      if (go->arith == "both") dbl = run(double());
    } else {
      dbl = run(double());
      const auto& [D, dsep] = *dbl;
      if (D.status == QPStatus::optimal)
        svg = cut_guide_svg(D.solid, D.cut, D.f_exact, D.sample_points, D.samples_positive, o.strip, dsep ? &*dsep : nullptr,
                            "Guiding curve (papers/004 RDCP), double, " + std::to_string(D.inner_knots) + " inner knots");
    }
    if (!go->svg.empty()) {
      if (svg.empty()) throw DomainError("svg", "there is no guide to draw (RDCP infeasible)", "leave --svg out or make RDCP feasible");
      write_file_atomically(go->svg, svg);
    }
    print_document(guide_runs_document(exact ? &*exact : nullptr, dbl ? &*dbl : nullptr));
    return 0;
  }};
}

/// `splinex cut facet`: its options, and what it runs (the work is in cut/ and cut/io/).
Command cut_facet_command(CLI::App* parent) {
  struct FacetCliOptions {
    GuideCliOptions guide;
    int control_points = 8;
    double step = 1.0 / 256;
    std::string out;
  };
  auto fo = std::make_shared<FacetCliOptions>();
  auto* fc = parent->add_subcommand("facet", "the cutting curve: the exact guide traced (march in double), fitted exactly (least squares, ends and "
                                           "tangents imposed), its validity certified; with --out also the two sub-solids");
  add_guide_options(fc, fo->guide);
  fc->add_option("--control-points", fo->control_points, "control points of the fitted cubic")->check(CLI::Range(4, 1000))->capture_default_str();
  fc->add_option("--step", fo->step, "marching step, normalized units")->check(CLI::Range(1e-6, 0.5))->capture_default_str();
  fc->add_option("--svg", fo->guide.svg, "write the figure (guide, samples, cutting curve) here")->check(output_file());
  fc->add_option("--out", fo->out, "write curve.json, part1.solid.json (b side) and part2.solid.json (b-bar side) into this folder; solid3d: "
                                   "surface.json and, when valid, split.json")->check(output_folder());
  auto f3 = std::make_shared<Facet3CliOptions>();
  fc->add_option("--domain", f3->domain, "solid3d: Omega by auto (projection, else Eq. 5's qp, else circle), projection, qp or circle")
      ->check(CLI::IsMember({"auto", "projection", "qp", "circle"}))
      ->capture_default_str();
  fc->add_option("--patch-inner-knots", f3->inner, "solid3d: uniform inner knots per direction of the bicubic patch")->check(CLI::Range(0, 15))->capture_default_str();
  fc->add_option("--boundary-samples", f3->samples, "solid3d: samples of Eq. 7 per loop side")->check(CLI::Range(1, 1000))->capture_default_str();
  fc->add_option("--weight-boundary", f3->weight_boundary, "solid3d: weight of Eq. 7 (the paper: 1)")->capture_default_str();
  fc->add_option("--weight-fair", f3->weight_fair, "solid3d: weight of the thin-plate energy (the paper: 1)")->capture_default_str();
  fc->add_option("--lambda-normal", f3->lambda, "solid3d: lambda of Eq. 7, the tangent-plane term")->capture_default_str();
  fc->add_option("--tangent-delta", f3->tangent_delta, "solid3d: t . dp/dm >= this at the boundary samples")->capture_default_str();
  fc->add_option("--max-depth", f3->max_depth, "solid3d: halvings of one piece in the certificates")->check(CLI::Range(0, 40))->capture_default_str();
  fc->add_option("--vtk", f3->vtk, "solid3d: write solid.vtk and surface.vtk (the trimmed patch) into this folder")->check(output_folder());
  fc->add_flag("--guided", f3->guided, "solid3d: find the guiding surface (RDCP, the guide options) and refine the patch by Eq. 6 (Gauss-Newton in double)");
  fc->add_option("--weight-guide", f3->weight_guide,
                 "solid3d --guided: the weight of Eq. 6 (the paper: 10), or auto: 10, 10^2, ..., 10^6 in turn until the refined patch is certified valid")
      ->capture_default_str();
  fc->add_option("--guide-grid", f3->guide_grid, "solid3d --guided: n x n samples of Eq. 6 over Omega's bounding box")->check(CLI::Range(2, 200))->capture_default_str();
  fc->add_option("--guide-iterations", f3->guide_iterations, "solid3d --guided: Gauss-Newton steps at most")->check(CLI::Range(0, 1000))->capture_default_str();
  fc->add_option("--inner-knots-z", fo->guide.inner_z, "solid3d --guided: the guide's inner knots in z (-1: as in x)")->check(CLI::Range(-1, 1000))->capture_default_str();
  fc->add_option("--loop-samples", fo->guide.loop_samples, "solid3d --guided: points of L* per loop side")->check(CLI::Range(1, 1000))->capture_default_str();
  add_arith_option(fc, f3->arith, "solid3d: exact (KKT exactly), double (Eigen), or both (and the double judged exactly)")
      ->check(CLI::IsMember({"exact", "double", "both"}));
  return {fc, [fo, f3](const Context& ctx) {
    const SolidDocument solid(fo->guide.solid, ctx.read_limits);
    if (solid.dimension() == 3) {
      Facet3CliOptions o = *f3;
      o.strip = fo->guide.strip;
      o.out = fo->out;
      return run_facet3(o, fo->guide, solid.solid3(ctx.limits), fo->guide.cut, ctx);
    }
    if (f3->arith != "exact" || !f3->vtk.empty()) throw UsageError(f3->vtk.empty() ? "arith" : "vtk", "is for solid3d documents", "leave it out for a solid2d");
    const auto S = solid.solid2(ctx.limits);
    const auto C = read_cut2(fo->guide.cut, ctx.read_limits);
    const GuideOptions o = to_guide_options(fo->guide);
    validate_cut(S, C);
    validate_guide_options(o, S.facets.size());
    check_exact_sizes(S, C, o);
    // No progress lines here: the march can still fail with a typed error, which must be the
    // only line on stderr (the default sizes take seconds).
    const auto R = guide_curve<Rational>(S, C, o);
    if (R.status != QPStatus::optimal)
      throw DomainError("guide", "RDCP is " + to_string(R.status) + " up to " + std::to_string(R.inner_knots) + " inner knots",
                        "raise --max-inner-knots, lower --delta, or widen --strip");
    const auto sep = certify_separation(R.solid, R.cut, R.f, o.strip);
    CurveFitOptions fo2;
    fo2.control_points = fo->control_points;
    fo2.step = fo->step;
    const auto cc = fit_cutting_curve(R.solid, R.cut, R.f, fo2);
    const auto v = certify_cutting_curve(R.solid, R.cut, cc.curve);
    const auto curve = from_frame(cc.curve, R.frame);
    CurveFacetRun run{GuideRun<Rational>{R, sep}, curve, cc.polygon.size(), cc.fit_max_deviation, v, !fo->out.empty(), std::nullopt};
    if (!fo->guide.svg.empty())
      write_file_atomically(fo->guide.svg, cut_guide_svg(R.solid, R.cut, R.f, R.sample_points, R.samples_positive, o.strip, &sep,
                                                         std::string("Cutting curve (papers/004): guide, samples, fitted curve (") + validity_word(v.verdict) + ")", &cc.curve));
    if (!fo->out.empty()) {
      std::filesystem::create_directories(fo->out);
      write_file_atomically((std::filesystem::path(fo->out) / "curve.json").string(), document_text(document(curve), 1));
      if (v.verdict.is_proved()) {
        run.parts = split_solid(S, validate_cut(S, C), curve);
        write_file_atomically((std::filesystem::path(fo->out) / "part1.solid.json").string(), document_text(solid_document(run.parts->first), 1));
        write_file_atomically((std::filesystem::path(fo->out) / "part2.solid.json").string(), document_text(solid_document(run.parts->second), 1));
      }
    }
    print_document(curve_facet_document(run));
    return 0;
  }};
}

/// `splinex cut certify`: its options, and what it runs (the work is in cut/ and cut/io/).
Command cut_certify_command(CLI::App* parent) {
  auto co = std::make_shared<CertifyCliOptions>();
  auto* ce = parent->add_subcommand("certify", "decide a given cutting curve's validity (Section 2's conditions) exactly, in the solid's coordinates");
  ce->add_option("solid", co->solid, "solid document")->required();
  ce->add_option("cut", co->cut, "cutting data document")->required();
  ce->add_option("curve", co->curve, "the cutting curve (a spline document: a polynomial curve in R^2, from the first cut point to the second); "
                                     "solid3d: a cutting_surface document")->required();
  auto c3 = std::make_shared<Facet3CliOptions>();
  ce->add_option("--strip", c3->strip, "solid3d: no collision check within this max-norm distance of the loop (normalized units)")->capture_default_str();
  ce->add_option("--max-depth", c3->max_depth, "solid3d: halvings of one piece")->check(CLI::Range(0, 40))->capture_default_str();
  return {ce, [co, c3](const Context& ctx) {
    const SolidDocument solid(co->solid, ctx.read_limits);  // read once: "-" (standard input) works
    if (solid.dimension() == 3) return run_certify3(*c3, solid, co->cut, co->curve, ctx);
    const auto [S, C, curve] = read_curve_input(solid, *co, ctx);
    print_document(curve_validity_document(certify_cutting_curve(S, C, curve)));
    return 0;
  }};
}

/// `splinex cut split`: its options, and what it runs (the work is in cut/ and cut/io/).
Command cut_split_command(CLI::App* parent) {
  auto cso = std::make_shared<CertifyCliOptions>();
  auto* sp = parent->add_subcommand("split", "split the solid along a cutting curve (solid3d: surface) certified valid: the two sub-solids' facets");
  sp->add_option("solid", cso->solid, "solid document")->required();
  sp->add_option("cut", cso->cut, "cutting data document")->required();
  sp->add_option("curve", cso->curve, "the cutting curve (spline document); solid3d: a cutting_surface document")->required();
  sp->add_option("--out", cso->out, "folder for part1.solid.json and part2.solid.json (solid3d: split.json and surface.json)")->check(output_folder())->required();
  return {sp, [cso](const Context& ctx) {
    const SolidDocument solid(cso->solid, ctx.read_limits);
    if (solid.dimension() == 3) return run_split3(solid, cso->cut, cso->curve, cso->out, ctx);
    const auto [S, C, curve] = read_curve_input(solid, *cso, ctx);
    const auto v = certify_cutting_curve(S, C, curve);
    if (!v.verdict.is_proved())
      throw DomainError("curve", std::string("is not certified valid (") + validity_word(v.verdict) + ": regular " + certificate_word(v.regular) +
                                     ", injective " + certificate_word(v.injective) + ", no collision " + certificate_word(v.inside) + ")",
                        "run cut certify to see why; split along a valid cutting curve");
    const auto [S1, S2] = split_solid(S, C, curve);
    std::filesystem::create_directories(cso->out);
    const std::string p1 = (std::filesystem::path(cso->out) / "part1.solid.json").string();
    const std::string p2 = (std::filesystem::path(cso->out) / "part2.solid.json").string();
    write_file_atomically(p1, document_text(solid_document(S1), 1));
    write_file_atomically(p2, document_text(solid_document(S2), 1));
    print_document(curve_split_document(p1, p2, S1, S2));
    return 0;
  }};
}

}  // namespace

Commands add_cut(CLI::App& app) {
  auto* cut = app.add_subcommand("cut", "cutting curves and surfaces for isogeometric segmentation (papers/004): example, guide, facet, certify, split (d = 2 and 3)");
  cut->require_subcommand(1);
  // In the order of --help.
  return {cut_example_command(cut), cut_guide_command(cut), cut_facet_command(cut), cut_certify_command(cut), cut_split_command(cut)};
}

}  // namespace splinex::app
