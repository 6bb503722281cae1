// splinex untrim: tile a trimmed domain with Coons patches (straight and polynomial graph edges);
// exact areas and integrals, cross-checked by CGAL and Green's theorem, and the cover certificate.
#include <iostream>
#include <memory>
#include <optional>
#include <type_traits>

#include "apps/command.hpp"
#include "compose/compose.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"
#include "io/trimmed_domain_io.hpp"

namespace splinex::app {

namespace {

struct Options {
  std::string arith = "exact", surface, density, monomial, file;
};

int run_untrim(const Options& o, const Context& ctx) {
  const auto D = read_trimmed_domain(o.file, ctx.read_limits);
  std::optional<BSpline<Rational>> S, f;
  std::array<std::vector<Rational>, 2> knot_lines;
  if (!o.surface.empty()) {
    S = read_spline(o.surface, ctx.limits, ctx.read_limits, "surface");
    knot_lines = surface_knot_lines(*S, D);
  }
  if (!o.density.empty() && !o.monomial.empty())
    throw UsageError("density", "--density and --monomial both given", "give one density");
  if (!o.density.empty()) f = read_spline(o.density, ctx.limits, ctx.read_limits, "density");
  if (!o.monomial.empty()) {
    const std::string hint = "write --monomial \"a,b\" for x^a y^b";
    const auto ab = parse_number_list(o.monomial, "monomial");
    if (ab.size() != 2) throw UsageError("monomial", "needs two exponents", hint);
    const int max = ctx.limits.max_degree;
    const auto e = whole_numbers(ab, "monomial", max, "exponents must be integers in [0, " + std::to_string(max) + "]", hint);
    f = monomial_density(e[0], e[1], D);
  }
  if (f && f->q != 1) throw ValidationError("density", "has " + std::to_string(f->q) + " coordinates", "give a scalar density (q = 1)");
  const auto spec = ArithSpec::parse(o.arith);
  print_document(with_arith<UntrimArithmetics>(spec, "untrim", [&](auto tag) {
    return untrim_document(untrim_run<typename decltype(tag)::type>(D, S, f, knot_lines, ctx.limits));
  }));
  return 0;
}

}  // namespace

Commands add_untrim(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* c = app.add_subcommand("untrim",
                               "tile a trimmed domain (loops of straight and polynomial graph edges) with Coons patches; "
                               "exact areas and integrals, cross-checked");
  add_arith_option(c, o->arith, "exact, double or mpfr:BITS");
  c->add_option("--surface", o->surface, "compose every tile into this surface (its knot lines split the tiles)");
  c->add_option("--density", o->density, "integrate this polynomial density (one Bezier piece, q = 1) over the region");
  c->add_option("--monomial", o->monomial, "integrate x^a y^b over the region, given as \"a,b\"");
  c->add_option("FILE", o->file, "trimmed domain document")->required();
  return {{c, [o](const Context& ctx) { return run_untrim(*o, ctx); }}};
}

}  // namespace splinex::app
