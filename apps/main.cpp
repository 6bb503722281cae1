// splinex: the command line, one thin layer over the libraries. Documents are read exactly,
// converted to the requested arithmetic by correct rounding, and written per arithmetic
// (fractions, round-trip doubles, all MPFR digits). Every splinex::Error exits with status 2.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <type_traits>
#include <iostream>
#include <new>
#include <optional>

#include "crosscheck/crosscheck.hpp"
#include "crosscheck/operations_impl.hpp"
#include "exact/json_io.hpp"
#include "exact/memory.hpp"
#include "exact/root_isolation.hpp"
#include "float/rounding.hpp"
#include "float/trimming_polyline.hpp"
#include "spline/untrim_integrate.hpp"
#include "untrim/algorithm2.hpp"
#include "exact/hybrid_examples.hpp"
#include "exact/hybrid_io.hpp"
#include "spline/hybrid.hpp"
#include "untrim/curved.hpp"
#include "untrim/loops.hpp"
#include "experiments/report.hpp"
#include "proofs/suite.hpp"
#include "spline/kernel.hpp"

namespace sx = splinex;

namespace {

struct Common {
  std::string arith = "exact";
  std::string file;
};

struct OpOptions {
  int dir = 0;
  std::string knots;
  std::string insert_method = "a54";
  int by = 1;
  std::string elevate_method = "auto";
  std::string at;
  std::string interval;
};

void add_op_options(CLI::App* c, OpOptions& o, const std::string& kind) {
  if (kind != "extract-bezier") c->add_option("--dir", o.dir, "parametric direction (0-based)")->capture_default_str();
  if (kind == "insert-knots") {
    c->add_option("--knots", o.knots, "comma-separated knots, e.g. \"0.25,1/3\"")->required();
    c->add_option("--method", o.insert_method, "a54 (refinement in one pass) or boehm (A5.1 knot by knot)")
        ->check(CLI::IsMember({"a54", "boehm"}))
        ->capture_default_str();
  } else if (kind == "elevate") {
    c->add_option("--by", o.by, "elevate the degree by this amount")->required();
    c->add_option("--method", o.elevate_method,
                  "auto (a59 in exact arithmetic, blossom in floating point: fewer bits lost), a59 (NURBS Book, "
                  "via Bezier pieces) or blossom")
        ->check(CLI::IsMember({"auto", "a59", "blossom"}))
        ->capture_default_str();
  } else if (kind == "split") {
    c->add_option("--at", o.at, "split parameter")->required();
  } else if (kind == "reparametrize") {
    c->add_option("--interval", o.interval, "new domain \"lo,hi\" of the direction")->required();
  }
}

sx::Operation make_op(const std::string& kind, const OpOptions& o) {
  sx::Operation op = sx::Operation::parse_kind(kind);
  op.dir = o.dir;
  switch (op.kind) {
    case sx::Operation::Kind::insert_knots:
      op.knots = sx::parse_number_list(o.knots, "knots");
      op.boehm = o.insert_method == "boehm";
      break;
    case sx::Operation::Kind::elevate:
      op.by = o.by;
      op.method = o.elevate_method == "blossom" ? sx::ElevationMethod::blossom : sx::ElevationMethod::bezier_pieces;
      op.method_auto = o.elevate_method == "auto";
      break;
    case sx::Operation::Kind::split: op.at = sx::parse_number(o.at, "at"); break;
    case sx::Operation::Kind::reparametrize: {
      const auto v = sx::parse_number_list(o.interval, "interval");
      if (v.size() != 2) throw sx::UsageError("interval", "needs two numbers", "write --interval \"lo,hi\"");
      op.lo = v[0];
      op.hi = v[1];
      break;
    }
    default: break;
  }
  return op;
}

sx::Json run_op_document(const sx::Operation& op, const sx::BSpline<sx::Rational>& S, const sx::ArithSpec& spec,
                         const sx::Limits& limits) {
  return sx::with_arith(spec, [&](auto tag) {
    using T = typename decltype(tag)::type;
    const sx::BSpline<T> in = sx::round_spline<T>(S);
    if (op.kind == sx::Operation::Kind::extract_bezier) {
      sx::Json pieces = sx::Json::array();
      for (const auto& pc : sx::extract_bezier(in, limits)) {
        sx::Json box = sx::Json::array();
        for (const auto& [lo, hi] : pc.box) box.push_back({sx::ArithTraits<T>::to_json(lo), sx::ArithTraits<T>::to_json(hi)});
        pieces.push_back({{"box", box}, {"spline", sx::spline_to_json(pc.spline)}});
      }
      return sx::Json{{"pieces", pieces}};
    }
    const auto R = sx::run_operation(op, in, limits);
    if (R.size() == 1) return sx::spline_to_json(R[0]);
    sx::Json parts = sx::Json::array();
    for (const auto& r : R) parts.push_back(sx::spline_to_json(r));
    return sx::Json{{"splines", parts}};
  });
}

// Parsed numbers that must be whole and in [0, hi] (derivative orders, exponents).
std::vector<int> whole_numbers(const std::vector<sx::Rational>& numbers, const std::string& field, int hi,
                               const std::string& what, const std::string& fix) {
  std::vector<int> out;
  for (const auto& r : numbers) {
    if (boost::multiprecision::denominator(r) != 1 || r < 0 || r > hi) throw sx::UsageError(field, what, fix);
    out.push_back(static_cast<int>(boost::multiprecision::numerator(r).template convert_to<long>()));
  }
  return out;
}

// A tile's chains as JSON: {"x": [...], "y_bottom": [...], "y_top": [...]}.
template <class F>
sx::Json tile_to_json(const sx::Tile<F>& t) {
  sx::Json xs = sx::Json::array(), yb = sx::Json::array(), yt = sx::Json::array();
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    xs.push_back(sx::ArithTraits<F>::to_json(t.x[i]));
    yb.push_back(sx::ArithTraits<F>::to_json(t.yb[i]));
    yt.push_back(sx::ArithTraits<F>::to_json(t.yt[i]));
  }
  sx::Json j{{"x", xs}, {"y_bottom", yb}, {"y_top", yt}};
  if (t.curved()) {
    auto pieces = [](const std::vector<std::vector<F>>& c) {
      sx::Json a = sx::Json::array();
      for (const auto& piece : c) {
        sx::Json p = sx::Json::array();
        for (const auto& v : piece) p.push_back(sx::ArithTraits<F>::to_json(v));
        a.push_back(p);
      }
      return a;
    };
    j["bottom_pieces"] = pieces(t.bottom);
    j["top_pieces"] = pieces(t.top);
  }
  return j;
}

// Dispatch for the operations instantiated for exact (GMP), double and MPFR but not FLINT.
template <class F>
sx::Json without_flint(const sx::ArithSpec& spec, const std::string& what, F&& run) {
  switch (spec.kind) {
    case sx::ArithSpec::Kind::exact: return run(sx::ArithTag<sx::Rational>{});
    case sx::ArithSpec::Kind::dbl: return run(sx::ArithTag<double>{});
    case sx::ArithSpec::Kind::mpfr: {
      sx::Mpfr::Precision scope(spec.bits);
      return run(sx::ArithTag<sx::Mpfr>{});
    }
    case sx::ArithSpec::Kind::flint: break;
  }
  throw sx::UsageError("arith", what + " runs in exact, double or mpfr:BITS (not flint)", "use --arith exact, double or mpfr:BITS");
}

// A message on one line: input quoted in it may hold line breaks.
std::string one_line(std::string s) {
  std::string out;
  for (char c : s) {
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else out += c;
  }
  while (!out.empty() && (out.back() == ' ')) out.pop_back();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  // Memory exhaustion in GMP, MPFR or FLINT throws std::bad_alloc instead of aborting.
  sx::install_throwing_allocators();
  CLI::App app{"splinex: exact and floating B-spline algorithms, cross-checked exactly"};
  app.require_subcommand(1);
  sx::Limits limits;
  std::string max_memory = "auto";
  app.add_option("--max-memory", max_memory,
                 "memory budget (address space) of the whole run, e.g. 512M or 8G (at least 128M); auto: 3/4 of "
                 "physical memory (" + sx::format_bytes(sx::default_memory_budget()) + " here)")
      ->capture_default_str();
  app.add_option("--max-control-points", limits.max_control_points, "size limit per result spline (1 .. 10^9)")
      ->check(CLI::Range(1.0, 1e9))
      ->capture_default_str();
  app.add_option("--max-degree", limits.max_degree, "degree limit per direction (0 .. 10^8)")
      ->check(CLI::Range(0.0, 1e8))
      ->capture_default_str();

  Common ev;
  std::string at, orders, eval_method = "basis";
  auto* c_eval = app.add_subcommand("eval", "evaluate a spline (or a partial derivative) at a parameter");
  c_eval->add_option("--arith", ev.arith, "exact (GMP), flint (exact, FLINT), double or mpfr:BITS")->capture_default_str();
  c_eval->add_option("--at", at, "parameter \"x0,x1,...\"")->required();
  c_eval->add_option("--derivative", orders, "derivative orders per direction, e.g. \"1,0\"");
  c_eval->add_option("--method", eval_method, "basis (A2.2 basis functions) or deboor (de Boor's algorithm)")
      ->check(CLI::IsMember({"basis", "deboor"}))
      ->capture_default_str();
  c_eval->add_option("file", ev.file, "spline document, - for stdin")->required();

  std::map<std::string, std::pair<Common, OpOptions>> ops;
  std::map<std::string, CLI::App*> op_cmds;
  for (const char* k : {"insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse"}) {
    auto& [cm, oo] = ops[k];
    auto* c = app.add_subcommand(k, std::string("spline document -> ") + k + " result");
    c->add_option("--arith", cm.arith, "exact (GMP), flint (exact, FLINT), double or mpfr:BITS")->capture_default_str();
    add_op_options(c, oo, k);
    c->add_option("file", cm.file, "spline document, - for stdin")->required();
    op_cmds[k] = c;
  }

  Common cp;
  std::string cp_outer, cp_inner, cp_method = "symbolic";
  bool cp_expand = false;
  double cp_eps = 1e-9;
  auto* c_compose = app.add_subcommand("compose", "functional composition T(S) of B-splines (S inside T's pieces)");
  c_compose->add_option("--arith", cp.arith, "exact (GMP), flint (exact, FLINT), double or mpfr:BITS")->capture_default_str();
  c_compose->add_option("--outer", cp_outer, "outer spline document T")->required();
  c_compose->add_option("--inner", cp_inner, "inner spline document S (points in T's parameter space)")->required();
  c_compose->add_option("--method", cp_method,
                        "symbolic (Elber's Bernstein products), interpolation, trimmed (Algorithm 1) or tensor "
                        "(Algorithm 2: untrimmed tensor-product tiles)")
      ->check(CLI::IsMember({"symbolic", "interpolation", "trimmed", "tensor"}))
      ->capture_default_str();
  c_compose->add_flag("--expand", cp_expand, "use T's end pieces as polynomials on all of R^n where S leaves T's domain");
  auto* cp_eps_opt = c_compose->add_option("--eps", cp_eps,
                        "trimming polylines' tolerance: trimmed with --arith double; tensor (any arith): untrim curved "
                        "trimming curves by polylines (without --eps, tensor is exact and needs straight ones)")
      ->check(CLI::Range(1e-12, 1e-1))
      ->capture_default_str();

  std::string cc_op, cc_float = "double", cc_file;
  int cc_grid = 0;
  OpOptions cc_opts;
  auto* c_cross = app.add_subcommand("crosscheck", "run an operation exactly and in float; report the exact errors");
  c_cross->add_option("operation", cc_op, "insert-knots, elevate, extract-bezier, split, reparametrize, reverse, identity")->required();
  c_cross->add_option("--float", cc_float, "double, mpfr:BITS, or flint (exact: must agree exactly)")->capture_default_str();
  c_cross->add_option("--grid", cc_grid, "evaluation points per direction (0: 65/17/7 by dimension; at most 10000)")
      ->check(CLI::Range(0, 10000));
  c_cross->add_option("--dir", cc_opts.dir, "parametric direction");
  c_cross->add_option("--knots", cc_opts.knots, "insert-knots: knots");
  c_cross->add_option("--by", cc_opts.by, "elevate: amount");
  c_cross->add_option("--method", cc_opts.insert_method, "insert-knots: a54|boehm; elevate: a59|blossom");
  c_cross->add_option("--at", cc_opts.at, "split: parameter");
  c_cross->add_option("--interval", cc_opts.interval, "reparametrize: \"lo,hi\"");
  c_cross->add_option("file", cc_file, "spline document, - for stdin")->required();

  std::vector<std::string> proof_names;
  bool proof_json = false;
  long proof_cases = 12;
  auto* c_prove = app.add_subcommand("prove", "run the exact proofs (proof by identity)");
  c_prove->add_option("names", proof_names, "proof names (default: all)");
  c_prove->add_flag("--json", proof_json, "JSON output");
  c_prove->add_option("--cases", proof_cases, "random exact cases per proof")->capture_default_str();
  bool proof_list = false;
  c_prove->add_flag("--list", proof_list, "list the proof names");

  sx::ReportOptions report;
  auto* c_report = app.add_subcommand("report", "the main job: crosscheck suite, figures, report.md");
  c_report->add_option("--out", report.out_dir, "output folder")->capture_default_str();
  c_report->add_flag("--full", report.full, "the long sweep (larger cases, more precisions)");

  std::string ut_arith = "exact", ut_surface, ut_density, ut_monomial, ut_file;
  auto* c_untrim = app.add_subcommand(
      "untrim", "tile a trimmed domain (loops of straight and polynomial graph edges) with Coons patches; exact areas and integrals, cross-checked");
  c_untrim->add_option("--arith", ut_arith, "exact, double or mpfr:BITS")->capture_default_str();
  c_untrim->add_option("--surface", ut_surface, "compose every tile into this surface (its knot lines split the tiles)");
  c_untrim->add_option("--density", ut_density, "integrate this polynomial density (one Bezier piece, q = 1) over the region");
  c_untrim->add_option("--monomial", ut_monomial, "integrate x^a y^b over the region, given as \"a,b\"");
  c_untrim->add_option("FILE", ut_file, "trimmed domain document")->required();

  auto* c_hybrid = app.add_subcommand("hybrid", "the hybrid multi-sided patch with B-spline boundaries (papers/003)");
  c_hybrid->require_subcommand(1);
  std::string hy_arith = "exact", hy_file, hy_example;
  std::vector<std::string> hy_at;
  auto* c_hy_eval = c_hybrid->add_subcommand("eval", "evaluate the patch (and its local parameters) at domain points");
  c_hy_eval->add_option("--arith", hy_arith, "exact, double or mpfr:BITS")->capture_default_str();
  c_hy_eval->add_option("--at", hy_at, "a domain point \"u,v\" (repeatable)")->required();
  c_hy_eval->add_option("FILE", hy_file, "hybrid patch document")->required();
  auto* c_hy_example = c_hybrid->add_subcommand("example", "print a paper example as a hybrid patch document (control points constructed)");
  c_hy_example->add_option("NAME", hy_example, "2.1, 3.1-hexagon or 3.1-octagon")->required();

  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      // CLI11's own errors (missing, unknown or repeated option, value not in the set, failed
      // conversion) in the one-line format of every other user error.
      std::cerr << "splinex: error: options: " << one_line(e.what())
                << " (fix: see splinex --help, or splinex COMMAND --help)\n";
      return 2;
    }
    sx::set_memory_budget(max_memory == "auto" ? sx::default_memory_budget() : sx::parse_memory_size(max_memory, "max-memory"));
    const sx::ReadLimits read_limits = sx::ReadLimits::from(limits);

    if (c_eval->parsed()) {
      const auto S = sx::spline_from_json(sx::read_json_file(ev.file, read_limits), limits);
      const auto x = sx::parse_number_list(at, "at");
      std::vector<int> ord;
      if (!orders.empty())
        ord = whole_numbers(sx::parse_number_list(orders, "derivative"), "derivative", 1000, "orders must be whole numbers in [0, 1000]",
                            "write e.g. --derivative \"1,0\"");
      const auto spec = sx::ArithSpec::parse(ev.arith);
      const sx::Json out = sx::with_arith(spec, [&](auto tag) {
        using T = typename decltype(tag)::type;
        const auto Sf = sx::round_spline<T>(S);
        const std::vector<T> xf = sx::round_values<T>(x, "at");
        if (!ord.empty() && eval_method == "deboor")
          throw sx::UsageError("method", "de Boor evaluation gives values only", "use --method basis with --derivative");
        const auto p = !ord.empty() ? sx::derivative(Sf, xf, ord) : eval_method == "deboor" ? sx::evaluate_de_boor(Sf, xf) : sx::evaluate(Sf, xf);
        return sx::Json{{"point", sx::point_to_json(p)}};
      });
      std::cout << out.dump() << "\n";
      return 0;
    }
    for (auto& [k, c] : op_cmds) {
      if (!c->parsed()) continue;
      const auto& [cm, oo] = ops[k];
      const auto S = sx::spline_from_json(sx::read_json_file(cm.file, read_limits), limits);
      const auto spec = sx::ArithSpec::parse(cm.arith);
      std::cout << run_op_document(make_op(k, oo), S, spec, limits).dump() << "\n";
      return 0;
    }
    if (c_hy_example->parsed()) {
      sx::HybridPatch<sx::Rational> P;
      if (hy_example == "2.1") P = sx::hybrid_example_2_1();
      else if (hy_example == "3.1-hexagon") P = sx::hybrid_example_3_1_hexagon();
      else if (hy_example == "3.1-octagon") P = sx::hybrid_example_3_1_octagon();
      else throw sx::UsageError("NAME", "is not an example: " + hy_example, "use 2.1, 3.1-hexagon or 3.1-octagon");
      std::cout << sx::hybrid_to_json(P).dump() << "\n";
      return 0;
    }
    if (c_hy_eval->parsed()) {
      const auto P = sx::hybrid_from_json(sx::read_json_file(hy_file, read_limits), limits);
      std::vector<std::array<sx::Rational, 2>> xs;
      for (const auto& a : hy_at) {
        const auto v = sx::parse_number_list(a, "at");
        if (v.size() != 2) throw sx::UsageError("at", "needs two numbers, got \"" + a + "\"", "write --at \"u,v\"");
        xs.push_back({v[0], v[1]});
      }
      const auto spec = sx::ArithSpec::parse(hy_arith);
      const sx::Json out = without_flint(spec, "hybrid eval", [&](auto tag) {
        using F = typename decltype(tag)::type;
        using Tr = sx::ArithTraits<F>;
        const auto cv = [](const sx::Rational& r) { return Tr::from_rational(r); };
        const auto Q = sx::convert_hybrid<F>(P, cv);
        sx::Json pts = sx::Json::array();
        for (const auto& x : xs) {
          const std::array<F, 2> xf{cv(x[0]), cv(x[1])};
          const auto L = sx::hybrid_local(Q, xf);
          sx::Json row{{"at", {sx::ArithTraits<sx::Rational>::to_json(x[0]), sx::ArithTraits<sx::Rational>::to_json(x[1])}},
                       {"point", sx::point_to_json(sx::hybrid_evaluate(Q, xf))},
                       {"wachspress", sx::point_to_json(L.lambda)},
                       {"s", sx::point_to_json(L.s)},
                       {"h", sx::point_to_json(L.h)}};
          bool corner = false;
          for (const auto& v : Q.vertices) corner = corner || (v[0] == xf[0] && v[1] == xf[1]);
          if (corner) {
            row["derivatives"] = "none at a corner (alpha_i, beta_(i-1) are 0/0 there; see README)";
          } else {
            const auto D = sx::hybrid_derivatives(Q, xf);
            row["du"] = sx::point_to_json(D.du);
            row["dv"] = sx::point_to_json(D.dv);
          }
          pts.push_back(row);
        }
        return sx::Json{{"points", pts}, {"arith", Tr::name()}};
      });
      std::cout << out.dump() << "\n";
      return 0;
    }
    if (c_untrim->parsed()) {
      const auto D = sx::trimmed_domain_from_json(sx::read_json_file(ut_file, read_limits));
      std::optional<sx::BSpline<sx::Rational>> S, f;
      std::array<std::vector<sx::Rational>, 2> knot_lines;
      if (!ut_surface.empty()) {
        S = sx::spline_from_json(sx::read_json_file(ut_surface, read_limits), limits, "surface");
        if (S->dim() != 2)
          throw sx::ValidationError("surface", "has " + std::to_string(S->dim()) + " parameters", "give a surface");
        for (int d = 0; d < 2; ++d) {
          if (D.lo[d] < S->domain_lo(d) || S->domain_hi(d) < D.hi[d])
            throw sx::DomainError("surface", "its domain in direction " + std::to_string(d) + " does not contain the trimmed domain's box",
                                  "give a box inside the surface's parameter domain");
          for (const auto& k : S->knots[d])
            if (S->domain_lo(d) < k && k < S->domain_hi(d) &&
                (knot_lines[d].empty() || !(knot_lines[d].back() == k)))
              knot_lines[d].push_back(k);
        }
      }
      if (!ut_density.empty() && !ut_monomial.empty())
        throw sx::UsageError("density", "--density and --monomial both given", "give one density");
      if (!ut_density.empty()) f = sx::spline_from_json(sx::read_json_file(ut_density, read_limits), limits, "density");
      if (!ut_monomial.empty()) {
        const std::string hint = "write --monomial \"a,b\" for x^a y^b";
        const auto ab = sx::parse_number_list(ut_monomial, "monomial");
        if (ab.size() != 2) throw sx::UsageError("monomial", "needs two exponents", hint);
        const auto e = whole_numbers(ab, "monomial", limits.max_degree,
                                     "exponents must be integers in [0, " + std::to_string(limits.max_degree) + "]", hint);
        f = sx::monomial_density(e[0], e[1], D);
      }
      if (f && f->q != 1) throw sx::ValidationError("density", "has " + std::to_string(f->q) + " coordinates", "give a scalar density (q = 1)");
      const auto spec = sx::ArithSpec::parse(ut_arith);
      auto run = [&](auto tag) {
        using F = typename decltype(tag)::type;
        using Tr = sx::ArithTraits<F>;
        const auto tiles = sx::untrim_domain<F>(D, knot_lines);
        sx::Json out_tiles = sx::Json::array();
        F area(0), integral(0);
        std::optional<sx::BSpline<F>> Sf, ff;
        if (S) Sf = sx::round_spline<F>(*S, "surface");
        if (f) ff = sx::round_spline<F>(*f, "density");
        sx::CompositionOptions co;
        co.expand = true;
        for (const auto& t : tiles) {
          const auto Q = sx::tile_spline(t);
          const F a = sx::tile_area(t);
          area = area + a;
          sx::Json tj{{"tile", tile_to_json(t)}, {"area", Tr::to_json(a)}, {"coons_patch", sx::spline_to_json(Q)}};
          if (Sf) tj["patch"] = sx::spline_to_json(sx::compose(*Sf, Q, co, limits));
          if (ff) {
            const F v = sx::integrate_over_tile(*ff, t, limits)[0];
            integral = integral + v;
            tj["integral"] = Tr::to_json(v);
          }
          out_tiles.push_back(tj);
        }
        const sx::Rational cgal_area = sx::region_area(D);
        sx::Json out{{"tiles", out_tiles},
                     {"area", Tr::to_json(area)},
                     {"area_check", {{D.curved() ? "green_exact_area" : "cgal_exact_area", sx::ArithTraits<sx::Rational>::to_json(cgal_area)},
                                     {"abs_error", sx::to_double(sx::Rational(abs(sx::Rational(Tr::to_rational(area) - cgal_area))))}}},
                     {"tile_rule", "a tile is {(x, y): x in [x_0, x_m], y_bottom(x) <= y <= y_top(x)}; its Coons patch Q(x, l) "
                                   "= (x, y_bottom(x) + l (y_top(x) - y_bottom(x))) on [x_0, x_m] x [0, 1]; patch = surface(Q). "
                                   "y_bottom is linear between the samples, or on [x_i, x_i+1] the Bernstein polynomial with "
                                   "ordinates bottom_pieces[i] when given (likewise y_top)"}};
        if constexpr (std::is_same_v<F, sx::Rational>) {
          const auto cc = sx::certify_cover(D, tiles);
          out["cover_certificate"] = {{"proved", cc.ok},
                                      {"checks", "tiles pairwise interior-disjoint, no loop edge enters a tile, a point of "
                                                 "every part of every tile inside the region, tile areas add up to the region's"},
                                      {"pair_checks", cc.pair_checks},
                                      {"edge_checks", cc.edge_checks},
                                      {"samples", cc.samples}};
          if (!cc.ok) out["cover_certificate"]["failure"] = cc.failure;
        }
        if (ff) {
          const sx::Rational green = sx::green_integral(D, *f);
          out["integral"] = Tr::to_json(integral);
          out["integral_check"] = {{"green_exact_integral", sx::ArithTraits<sx::Rational>::to_json(green)},
                                   {"abs_error", sx::to_double(sx::Rational(abs(sx::Rational(Tr::to_rational(integral) - green))))}};
        }
        return out;
      };
      const sx::Json out = without_flint(spec, "untrim", run);
      std::cout << out.dump() << "\n";
      return 0;
    }
    if (c_compose->parsed()) {
      const auto T = sx::spline_from_json(sx::read_json_file(cp_outer, read_limits), limits, "outer");
      const auto S = sx::spline_from_json(sx::read_json_file(cp_inner, read_limits), limits, "inner");
      if (cp_method == "tensor") {
        const auto spec = sx::ArithSpec::parse(cp.arith);
        sx::TensorOptions to;
        to.boundary = cp_eps_opt->count() > 0 ? sx::TrimBoundary::polyline : sx::TrimBoundary::exact;
        to.eps = cp_eps;
        auto run = [&](auto tag) {
          using F = typename decltype(tag)::type;
          using Tr = sx::ArithTraits<F>;
          const auto A = sx::compose_tensor(sx::round_spline<F>(T, "outer"), sx::round_spline<F>(S, "inner"), to, limits);
          sx::Json tiles = sx::Json::array();
          for (const auto& t : A.tiles) {
            const auto& p = A.trimmed.patches[t.patch];
            sx::Json box = sx::Json::array();
            for (const auto& [lo, hi] : A.trimmed.inner_pieces[p.inner_piece].box) box.push_back({Tr::to_json(lo), Tr::to_json(hi)});
            tiles.push_back({{"inner_box", box},
                             {"outer_cell", p.outer_cell},
                             {"tile", tile_to_json(t.tile)},
                             {"area", Tr::to_json(t.area)},
                             {"coons_patch", sx::spline_to_json(t.Q)},
                             {"homogeneous", p.homogeneous},
                             {"patch", sx::spline_to_json(t.R)}});
          }
          return sx::Json{{"tiles", tiles},
                          {"straight_trimming_curves", A.straight_boundaries},
                          {"curved_trimming_curves", A.curved_boundaries},
                          {"gap_area", Tr::to_json(A.gap_area)},
                          {"overlap_area", Tr::to_json(A.overlap_area)},
                          {"tile_rule", "a tile is {(x, y): x in [x_0, x_m], y_bottom(x) <= y <= y_top(x)} in the inner "
                                        "spline's parameters (piecewise linear chains); its Coons patch Q(x, l) maps "
                                        "[x_0, x_m] x [0, 1] onto it and patch = T_j^e(S_i(Q))"}};
        };
        const sx::Json out = without_flint(spec, "compose --method tensor", run);
        std::cout << out.dump() << "\n";
        return 0;
      }
      if (cp_method == "trimmed") {
        const auto spec = sx::ArithSpec::parse(cp.arith);
        const sx::Json out = sx::with_arith(spec, [&](auto tag) {
          using F = typename decltype(tag)::type;
          using Tr = sx::ArithTraits<F>;
          const auto C = sx::compose_trimmed(sx::round_spline<F>(T, "outer"), sx::round_spline<F>(S, "inner"), {}, limits);
          sx::Json pieces = sx::Json::array();
          for (const auto& p : C.patches) {
            sx::Json box = sx::Json::array(), obox = sx::Json::array(), region = sx::Json::array();
            for (const auto& [lo, hi] : C.inner_pieces[p.inner_piece].box) box.push_back({Tr::to_json(lo), Tr::to_json(hi)});
            for (const auto& [lo, hi] : C.outer_pieces[p.outer_cell].box) obox.push_back({Tr::to_json(lo), Tr::to_json(hi)});
            for (const auto& c : p.region) {
              sx::Json cj{{"coordinate", c.coord}};
              if (c.check_lo) cj["at_least"] = Tr::to_json(c.lo);
              if (c.check_hi) cj[c.hi_closed ? "at_most" : "below"] = Tr::to_json(c.hi);
              region.push_back(cj);
            }
            sx::Json crossings = sx::Json::array();
            if constexpr (std::is_same_v<F, sx::Rational>) {
              // Exact end points of the trimming curves on the piece's edges (CGAL root isolation).
              for (const auto& e : sx::trimming_edge_crossings(C, &p - C.patches.data())) {
                sx::Json fixed = sx::Json::array();
                for (std::size_t l = 0; l < e.fixed.size(); ++l)
                  fixed.push_back(static_cast<int>(l) == e.free_dir ? sx::Json(nullptr) : Tr::to_json(e.fixed[l]));
                crossings.push_back({{"condition", e.condition},
                                     {"bound", e.at_upper_bound ? "upper" : "lower"},
                                     {"free_direction", e.free_dir},
                                     {"fixed", fixed},
                                     {"interval", {Tr::to_json(e.root.lo), Tr::to_json(e.root.hi)}},
                                     {"exact", e.root.lo == e.root.hi},
                                     {"multiplicity", e.root.multiplicity}});
              }
            }
            sx::Json polylines = sx::Json::array();
            if constexpr (std::is_same_v<F, double>) {
              // Float trimming curves of surface pieces: one polyline (as segments) per condition bound.
              const auto& piece = C.inner_pieces[p.inner_piece].spline;
              if (piece.dim() == 2 && !piece.is_rational())
                for (const auto& c : p.region)
                  for (bool upper : {false, true}) {
                    if ((upper && !c.check_hi) || (!upper && !c.check_lo)) continue;
                    sx::TrimmingTolerance tol;
                    tol.eps = cp_eps;
                    sx::Json segs = sx::Json::array();
                    for (const auto& sg : sx::trace_level_set(piece, c.coord, upper ? c.hi : c.lo, tol))
                      segs.push_back({{sg.a[0], sg.a[1]}, {sg.b[0], sg.b[1]}});
                    polylines.push_back({{"coordinate", c.coord}, {"level", upper ? c.hi : c.lo}, {"eps", cp_eps}, {"segments", segs}});
                  }
            }
            pieces.push_back({{"inner_box", box},
                              {"edge_crossings", crossings},
                              {"trimming_polylines", polylines},
                              {"outer_cell", p.outer_cell},
                              {"outer_box", obox},
                              {"status", p.status == sx::RegionStatus::untrimmed ? "untrimmed"
                                         : p.status == sx::RegionStatus::trimmed ? "trimmed" : "unproven_nonempty"},
                              {"region", region},
                              {"homogeneous", p.homogeneous},
                              {"patch", sx::spline_to_json(p.patch)}});
          }
          return sx::Json{{"pieces", pieces}, {"isoparametric_splits", C.isoparametric_splits},
                          {"region_rule", "each condition on the inner spline's coordinate s_c = S(r)_c: at_least lo, below hi "
                                          "(at_most hi at the outer domain's end); a homogeneous patch holds (w*R, w)"}};
        });
        std::cout << out.dump() << "\n";
        return 0;
      }
      sx::CompositionOptions o;
      o.method = cp_method == "interpolation" ? sx::CompositionMethod::interpolation : sx::CompositionMethod::symbolic;
      o.expand = cp_expand;
      const auto spec = sx::ArithSpec::parse(cp.arith);
      const sx::Json out = sx::with_arith(spec, [&](auto tag) {
        using F = typename decltype(tag)::type;
        return sx::spline_to_json(sx::compose(sx::round_spline<F>(T, "outer"), sx::round_spline<F>(S, "inner"), o, limits));
      });
      std::cout << out.dump() << "\n";
      return 0;
    }
    if (c_cross->parsed()) {
      const auto S = sx::spline_from_json(sx::read_json_file(cc_file, read_limits), limits);
      OpOptions o = cc_opts;
      if (cc_op == "elevate")
        o.elevate_method = cc_opts.insert_method == "blossom" ? "blossom" : cc_opts.insert_method == "a59" ? "a59" : "auto";
      if (cc_op == "insert-knots" && cc_opts.knots.empty())
        throw sx::UsageError("knots", "insert-knots needs --knots", "add --knots \"k1,k2,...\"");
      const auto rep = sx::crosscheck(make_op(cc_op, o), S, sx::ArithSpec::parse(cc_float, "float"), cc_grid, limits);
      std::cout << rep.to_json().dump(2) << "\n";
      return 0;
    }
    if (c_prove->parsed()) {
      if (proof_list) {
        for (const auto& e : sx::proof_registry()) std::cout << e.name << "\t" << e.identity << "\n";
        return 0;
      }
      if (proof_cases < 1 || proof_cases > 100000)
        throw sx::UsageError("cases", std::to_string(proof_cases) + " is outside [1, 100000] (0 cases would check nothing)",
                             "give --cases N with 1 <= N <= 100000");
      const auto reps = sx::run_proofs(proof_names, static_cast<std::size_t>(proof_cases));
      bool all = true;
      sx::Json j = sx::Json::array();
      for (const auto& r : reps) {
        all = all && r.as_expected();
        if (proof_json) {
          j.push_back({{"name", r.name}, {"identity", r.identity}, {"degree_bound", r.degree_bound}, {"cases", r.cases},
                       {"cells", r.cells}, {"points", r.points}, {"verdict", r.verdict_key()},
                       {"expected", r.expect_proved ? "holds" : "refuted"}, {"as_expected", r.as_expected()},
                       {"structures", r.structures}, {"undecided", r.undecided}, {"counterexample", r.counterexample}});
        } else {
          std::cout << r.name << ": " << r.verdict() << "\n  identity: " << r.identity << "\n  degree bound: " << r.degree_bound
                    << "\n  points: " << r.points << " exact comparisons in " << r.cells << " cells over " << r.cases << " cases\n";
          if (!r.structures.empty()) {
            std::cout << "  structures:";
            for (std::size_t k = 0; k < r.structures.size(); ++k) std::cout << (k ? ", " : " ") << r.structures[k];
            std::cout << "\n";
          }
          if (r.refuted()) std::cout << "  counterexample: " << r.counterexample << "\n";
        }
      }
      if (proof_json) std::cout << j.dump(2) << "\n";
      return all ? 0 : 1;
    }
    if (c_report->parsed()) return sx::run_report(report);
  } catch (const sx::Error& e) {
    std::cerr << "splinex: error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "splinex: error: " << one_line(e.path1().string()) << ": " << one_line(e.code().message())
              << " (fix: give a path that can be read or written)\n";
    return 2;
  } catch (const std::length_error&) {
    // A container asked for more elements than it can address: a size no budget can hold.
    std::cerr << "splinex: error: memory: a result too large to allocate (fix: ask for a smaller result, or lower "
                 "--max-control-points)\n";
    return 2;
  } catch (const std::bad_alloc&) {
    const auto& b = sx::current_memory_budget();
    std::cerr << "splinex: error: memory: out of memory"
              << (b.enforced ? " within the budget of " + sx::format_bytes(b.bytes) : std::string())
              << " (fix: ask for a smaller result, lower --max-control-points, or raise --max-memory)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "splinex: internal error: " << one_line(e.what()) << " (please report this with the input)\n";
    return 1;
  }
  return 0;
}
