#include "experiments/curved_untrim.hpp"
#include "experiments/section.hpp"

#include <chrono>
#include <iomanip>
#include <sstream>

#include "io/json_io.hpp"
#include "io/trimmed_domain_io.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg.hpp"
#include "experiments/svg_plot.hpp"
#include "float/mpfr.hpp"
#include "untrim/tile_integrals.hpp"
#include "untrim/curved.hpp"
#include "untrim/poly.hpp"

namespace splinex {

namespace {

const char* kDomain = R"({"type": "trimmed_domain", "domain": [[0, 1], [0, 1]],
 "loops": [[[0.1, 0.5], {"controls": [["11/30", 0.1], ["19/30", 0.2]]}, [0.9, 0.5], {"controls": [["19/30", 0.95], ["11/30", 0.8]]}],
           [[0.4, 0.45], [0.6, 0.45], [0.5, 0.6]]]}
)";

}  // namespace

std::string run_curved_untrim(const std::string& out_dir, bool& ok) {
  std::istringstream in(kDomain);
  const TrimmedDomain D = trimmed_domain_from_json(read_json(in, "untrim_curved_domain.json"));
  write_file_atomically(out_dir + "/untrim_curved_domain.json", kDomain);
  const Rational h(1, 2);
  const std::array<std::vector<Rational>, 2> kl{{{Rational(1, 4), h, Rational(2, 3)}, {h}}};
  const auto t0 = std::chrono::steady_clock::now();
  const auto tiles = untrim_curved(D, kl);
  const double t_tiles = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto cc = certify_cover(D, tiles);
  const double t_cert = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() - t_tiles;
  ok = ok && cc.ok;
  int dmax = 1;
  for (const auto& t : tiles) dmax = std::max(dmax, tile_spline(t).degrees[0]);

  // Integrals of x^a y^b: exact tiles = Green; the rounded tiles in double and MPFR 113, measured.
  // The same tiles rounded, once for all densities.
  const auto td = untrim_domain<double>(D, kl);
  std::vector<Tile<Mpfr>> tm;
  {
    Mpfr::Precision scope(113);
    tm = untrim_domain<Mpfr>(D, kl);
  }
  std::ostringstream rows;
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {0, 1}, {2, 1}, {1, 3}}) {
    const auto f = monomial_density(a, b, D);
    const Rational green = green_integral(D, f);
    Rational ex = 0;
    for (const auto& t : tiles) ex += integrate_over_tile(f, t)[0];
    ok = ok && ex == green;
    const auto fd = convert<double>(f, [](const Rational& x) { return to_double(x); });
    double sd = 0;
    for (const auto& t : td) sd += integrate_over_tile(fd, t)[0];
    Rational em;
    {
      Mpfr::Precision scope(113);
      const auto fm = convert<Mpfr>(f, [](const Rational& x) { return ArithTraits<Mpfr>::from_rational(x); });
      Mpfr sm(0);
      for (const auto& t : tm) sm = sm + integrate_over_tile(fm, t)[0];
      em = abs(Rational(ArithTraits<Mpfr>::to_rational(sm) - green));
    }
    const Rational ed = abs(Rational(exact_from_double(sd) - green));
    rows << "| x^" << a << " y^" << b << " | " << to_fraction_string(green) << " | " << (ex == green ? "equal" : "DIFFERENT") << " | "
         << fmt(to_double(ed)) << " | " << fmt(to_double(em)) << " |\n";
  }

  // A knot line with irrational crossings: exact refuses, double approximates the crossing.
  const std::array<std::vector<Rational>, 2> kl_irr{{{}, {Rational(3, 10)}}};
  std::string refused;
  try {
    untrim_curved(D, kl_irr);
  } catch (const DomainError& e) {
    refused = e.what();
  }
  ok = ok && !refused.empty();
  const auto ta = untrim_curved(D, kl_irr, 53 + 16);
  Rational a_irr = 0, stray = 0;
  for (const auto& t : ta) {
    a_irr += tile_area(t);
    // How far the tile crosses the knot line: per chain piece, the side of y = 3/10 its middle lies
    // on, against its end samples.
    for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
      const Rational ym = (poly::bernstein_eval(t.bottom_piece(i), h) + poly::bernstein_eval(t.top_piece(i), h)) / 2;
      for (std::size_t j : {i, i + 1})
        stray = std::max(stray, ym > kl_irr[1][0] ? Rational(kl_irr[1][0] - t.yb[j]) : Rational(t.yt[j] - kl_irr[1][0]));
    }
  }
  const Rational area_err = abs(Rational(a_irr - region_area(D)));
  ok = ok && stray > 0 && stray < Rational(1, Integer(1) << 60);

  // Figure: tiles filled, knot lines dashed; the chains drawn through 24 samples per piece (drawing only).
  const double W = 520, m = 30;
  const auto X = [&](const Rational& x) { return m + W * to_double(x); };
  const auto Y = [&](const Rational& y) { return m + W * (1 - to_double(y)); };
  svg::Canvas fig(W + 2 * m, W + 2 * m);
  fig.rect(m, m, W, W, svg::attr("fill", "white") + svg::attr("stroke", "black"));
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto& t = tiles[k];
    std::vector<std::pair<double, double>> pts;
    for (int side = 0; side < 2; ++side) {
      std::vector<std::pair<double, double>> chain;
      for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
        const auto c = side == 0 ? t.bottom_piece(i) : t.top_piece(i);
        for (int s = 0; s <= 24; ++s) {
          const Rational u(s, 24);
          chain.emplace_back(X(t.x[i] + (t.x[i + 1] - t.x[i]) * u), Y(poly::bernstein_eval(c, u)));
        }
      }
      if (side == 1) std::reverse(chain.begin(), chain.end());
      pts.insert(pts.end(), chain.begin(), chain.end());
    }
    fig.polygon(pts, svg::attr("fill", svg::palette_light(k)) + svg::attr("stroke", "#333") + svg::attr("stroke-width", 1));
    const std::size_t mid = (t.x.size() - 1) / 2;
    const Rational cx = (t.x[mid] + t.x[mid + 1]) / 2;
    const auto yb = poly::bernstein_eval(t.bottom_piece(mid), h), yt = poly::bernstein_eval(t.top_piece(mid), h);
    fig.text(X(cx), Y(Rational((yb + yt) / 2)) + 4, std::to_string(k), 11, svg::Anchor::middle);
  }
  for (const auto& k : kl[0])
    fig.line(X(k), m, X(k), m + W, svg::attr("stroke", "#d62728") + svg::attr("stroke-dasharray", "5,4"));
  for (const auto& k : kl[1])
    fig.line(m, Y(k), m + W, Y(k), svg::attr("stroke", "#d62728") + svg::attr("stroke-dasharray", "5,4"));
  fig.caption(std::to_string(tiles.size()) + " exact tiles with cubic sides (Coons patches of degree (" + std::to_string(dmax) +
              ", 1)); dashed: knot lines (tiles end at them); cover " + (cc.ok ? "proved exactly" : "NOT proved"), 12);
  write_file_atomically(out_dir + "/untrim_curved.svg", fig.str());

  return ReportTemplate("curved-untrim")
      .set("tiles", tiles.size())
      .set("dmax", dmax)
      .set("t_tiles", fmt(t_tiles))
      .when("cover", cc.ok)
      .set("failure", cc.failure)
      .set("pair_checks", cc.pair_checks)
      .set("edge_checks", cc.edge_checks)
      .set("samples", cc.samples)
      .set("t_cert", fmt(t_cert))
      .set("tile_area_sum", to_fraction_string(cc.tile_area_sum))
      .set("region_area", to_fraction_string(cc.region_area))
      .set("refused", refused)
      .set("stray", fmt(to_double(stray)))
      .set("area_err", fmt(to_double(area_err)))
      .set("rows", rows.str())
      .render();
}

void curved_untrim_section(ReportContext& ctx) {
  ctx.progress("untrimming with curved tile sides");
  ctx.markdown["curved-untrim"] = run_curved_untrim(ctx.options.out_dir, ctx.ok);
}

}  // namespace splinex
