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
#include "io/result_json.hpp"
#include "io/trimmed_domain_io.hpp"
#include "untrim/curved.hpp"
#include "untrim/loops.hpp"
#include "untrim/tile_integrals.hpp"

namespace splinex::app {

namespace {

struct Options {
  std::string arith = "exact", surface, density, monomial, file;
};

// The knot lines of S inside its domain, per direction (they split the tiles).
std::array<std::vector<Rational>, 2> surface_knot_lines(const BSpline<Rational>& S, const TrimmedDomain& D) {
  std::array<std::vector<Rational>, 2> knot_lines;
  if (S.dim() != 2) throw ValidationError("surface", "has " + std::to_string(S.dim()) + " parameters", "give a surface");
  for (int d = 0; d < 2; ++d) {
    if (D.lo[d] < S.domain_lo(d) || S.domain_hi(d) < D.hi[d])
      throw DomainError("surface", "its domain in direction " + std::to_string(d) + " does not contain the trimmed domain's box",
                        "give a box inside the surface's parameter domain");
    for (const auto& k : S.knots[d])
      if (S.domain_lo(d) < k && k < S.domain_hi(d) && (knot_lines[d].empty() || !(knot_lines[d].back() == k)))
        knot_lines[d].push_back(k);
  }
  return knot_lines;
}

template <class F>
Json untrim_result(const TrimmedDomain& D, const std::optional<BSpline<Rational>>& S, const std::optional<BSpline<Rational>>& f,
                   const std::array<std::vector<Rational>, 2>& knot_lines, const Limits& limits) {
  using Tr = ArithTraits<F>;
  const auto tiles = untrim_domain<F>(D, knot_lines);
  Json out_tiles = Json::array();
  F area(0), integral(0);
  std::optional<BSpline<F>> Sf, ff;
  if (S) Sf = round_spline<F>(*S, "surface");
  if (f) ff = round_spline<F>(*f, "density");
  CompositionOptions co;
  co.expand = true;
  for (const auto& t : tiles) {
    const auto Q = tile_spline(t);
    const F a = tile_area(t);
    area = area + a;
    Json tj{{"tile", tile_to_json(t)}, {"area", Tr::to_json(a)}, {"coons_patch", spline_to_json(Q)}};
    if (Sf) tj["patch"] = spline_to_json(compose(*Sf, Q, co, limits));
    if (ff) {
      const F v = integrate_over_tile(*ff, t, limits)[0];
      integral = integral + v;
      tj["integral"] = Tr::to_json(v);
    }
    out_tiles.push_back(tj);
  }
  const auto error_of = [](const F& value, const Rational& exact) {
    return to_double(Rational(abs(Rational(Tr::to_rational(value) - exact))));
  };
  const Rational exact_area = region_area(D);
  Json out{{"tiles", out_tiles},
           {"area", Tr::to_json(area)},
           {"area_check", {{D.curved() ? "green_exact_area" : "cgal_exact_area", ArithTraits<Rational>::to_json(exact_area)},
                           {"abs_error", error_of(area, exact_area)}}},
           {"tile_rule", "a tile is {(x, y): x in [x_0, x_m], y_bottom(x) <= y <= y_top(x)}; its Coons patch Q(x, l) "
                         "= (x, y_bottom(x) + l (y_top(x) - y_bottom(x))) on [x_0, x_m] x [0, 1]; patch = surface(Q). "
                         "y_bottom is linear between the samples, or on [x_i, x_i+1] the Bernstein polynomial with "
                         "ordinates bottom_pieces[i] when given (likewise y_top)"}};
  if constexpr (std::is_same_v<F, Rational>) {
    const auto cc = certify_cover(D, tiles);
    out["cover_certificate"] = {{"proved", cc.ok},
                                {"checks", "tiles pairwise interior-disjoint, no loop edge enters a tile, a point of "
                                           "every part of every tile inside the region, tile areas add up to the region's"},
                                {"pair_checks", cc.pair_checks},
                                {"edge_checks", cc.edge_checks},
                                {"samples", cc.samples}};
    if (!cc.ok) out["cover_certificate"]["failure"] = cc.failure;
  }
  if (ff) {
    const Rational green = green_integral(D, *f);
    out["integral"] = Tr::to_json(integral);
    out["integral_check"] = {{"green_exact_integral", ArithTraits<Rational>::to_json(green)},
                             {"abs_error", error_of(integral, green)}};
  }
  return out;
}

int run_untrim(const Options& o, const Context& ctx) {
  const auto D = trimmed_domain_from_json(read_json_file(o.file, ctx.read_limits));
  std::optional<BSpline<Rational>> S, f;
  std::array<std::vector<Rational>, 2> knot_lines;
  if (!o.surface.empty()) {
    S = spline_from_json(read_json_file(o.surface, ctx.read_limits), ctx.limits, "surface");
    knot_lines = surface_knot_lines(*S, D);
  }
  if (!o.density.empty() && !o.monomial.empty())
    throw UsageError("density", "--density and --monomial both given", "give one density");
  if (!o.density.empty()) f = spline_from_json(read_json_file(o.density, ctx.read_limits), ctx.limits, "density");
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
  const Json out = with_arith_except_flint(spec, "untrim", [&](auto tag) {
    return untrim_result<typename decltype(tag)::type>(D, S, f, knot_lines, ctx.limits);
  });
  std::cout << out.dump() << "\n";
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
