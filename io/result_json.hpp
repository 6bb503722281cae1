// The JSON of results (tiles, Bezier pieces, trimmed and tensor compositions), written per
// arithmetic: fractions for exact, round-trip doubles, all MPFR digits (ArithTraits<F>::to_json).
#pragma once
#include <type_traits>
#include <vector>

#include "compose/trimming_end_points.hpp"
#include "io/json_io.hpp"
#include "spline/bezier.hpp"
#include "untrim/algorithm2.hpp"
#include "untrim/sweep.hpp"
#include "untrim/trimming_polyline.hpp"

namespace splinex {

/// A tile's chains: {"x": [...], "y_bottom": [...], "y_top": [...]} (+ Bezier pieces when curved).
template <class F>
Json tile_to_json(const Tile<F>& t) {
  Json xs = Json::array(), yb = Json::array(), yt = Json::array();
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    xs.push_back(ArithTraits<F>::to_json(t.x[i]));
    yb.push_back(ArithTraits<F>::to_json(t.yb[i]));
    yt.push_back(ArithTraits<F>::to_json(t.yt[i]));
  }
  Json j{{"x", xs}, {"y_bottom", yb}, {"y_top", yt}};
  if (t.curved()) {
    auto pieces = [](const std::vector<std::vector<F>>& c) {
      Json a = Json::array();
      for (const auto& piece : c) {
        Json p = Json::array();
        for (const auto& v : piece) p.push_back(ArithTraits<F>::to_json(v));
        a.push_back(p);
      }
      return a;
    };
    j["bottom_pieces"] = pieces(t.bottom);
    j["top_pieces"] = pieces(t.top);
  }
  return j;
}

/// A parameter box [[lo, hi], ...].
template <class F>
Json box_to_json(const std::vector<std::pair<F, F>>& box) {
  Json j = Json::array();
  for (const auto& [lo, hi] : box) j.push_back({ArithTraits<F>::to_json(lo), ArithTraits<F>::to_json(hi)});
  return j;
}

/// Bezier extraction (NURBS Book A5.6 per direction): {"pieces": [{"box": ..., "spline": ...}, ...]}.
template <class T>
Json bezier_pieces_to_json(const std::vector<BezierPiece<T>>& pieces) {
  Json out = Json::array();
  for (const auto& pc : pieces) out.push_back({{"box", box_to_json(pc.box)}, {"spline", spline_to_json(pc.spline)}});
  return Json{{"pieces", out}};
}

/// Algorithm 2 (papers/000): the untrimmed tensor-product tiles of T(S).
template <class F>
Json tensor_composition_to_json(const TensorComposition<F>& A) {
  using Tr = ArithTraits<F>;
  Json tiles = Json::array();
  for (const auto& t : A.tiles) {
    const auto& p = A.trimmed.patches[t.patch];
    tiles.push_back({{"inner_box", box_to_json(A.trimmed.inner_pieces[p.inner_piece].box)},
                     {"outer_cell", p.outer_cell},
                     {"tile", tile_to_json(t.tile)},
                     {"area", Tr::to_json(t.area)},
                     {"coons_patch", spline_to_json(t.Q)},
                     {"homogeneous", p.patch.weighted},
                     {"patch", spline_to_json(t.R.net)}});
  }
  return Json{{"tiles", tiles},
              {"straight_trimming_curves", A.straight_boundaries},
              {"curved_trimming_curves", A.curved_boundaries},
              {"gap_area", Tr::to_json(A.gap_area)},
              {"overlap_area", Tr::to_json(A.overlap_area)},
              {"tile_rule", "a tile is {(x, y): x in [x_0, x_m], y_bottom(x) <= y <= y_top(x)} in the inner "
                            "spline's parameters (piecewise linear chains); its Coons patch Q(x, l) maps "
                            "[x_0, x_m] x [0, 1] onto it and patch = T_j^e(S_i(Q))"}};
}

/// Algorithm 1 (papers/000): the trimmed patches of T(S) with their regions; exact: the trimming
/// curves' end points on the pieces' edges (CGAL root isolation); double: trimming polylines
/// within eps of surface pieces' trimming curves.
template <class F>
Json trimmed_composition_to_json(const TrimmedComposition<F>& C, double eps) {
  using Tr = ArithTraits<F>;
  Json pieces = Json::array();
  for (const auto& p : C.patches) {
    Json region = Json::array();
    for (const auto& c : p.region) {
      Json cj{{"coordinate", c.coord}};
      if (c.check_lo) cj["at_least"] = Tr::to_json(c.lo);
      if (c.check_hi) cj[c.hi_closed ? "at_most" : "below"] = Tr::to_json(c.hi);
      region.push_back(cj);
    }
    Json crossings = Json::array();
    if constexpr (std::is_same_v<F, Rational>) {
      for (const auto& e : trimming_edge_crossings(C, &p - C.patches.data())) {
        Json fixed = Json::array();
        for (std::size_t l = 0; l < e.fixed.size(); ++l)
          fixed.push_back(static_cast<int>(l) == e.free_dir ? Json(nullptr) : Tr::to_json(e.fixed[l]));
        crossings.push_back({{"condition", e.condition},
                             {"bound", e.at_upper_bound ? "upper" : "lower"},
                             {"free_direction", e.free_dir},
                             {"fixed", fixed},
                             {"interval", {Tr::to_json(e.root.lo), Tr::to_json(e.root.hi)}},
                             {"exact", e.root.lo == e.root.hi},
                             {"multiplicity", e.root.multiplicity}});
      }
    }
    Json polylines = Json::array();
    if constexpr (std::is_same_v<F, double>) {
      /// One polyline (as segments) per condition bound.
      const auto& piece = C.inner_pieces[p.inner_piece].spline;
      if (piece.dim() == 2 && !piece.is_rational())
        for (const auto& c : p.region)
          for (bool upper : {false, true}) {
            if ((upper && !c.check_hi) || (!upper && !c.check_lo)) continue;
            TrimmingTolerance tol;
            tol.eps = eps;
            Json segs = Json::array();
            for (const auto& sg : trace_level_set(piece, c.coord, upper ? c.hi : c.lo, tol))
              segs.push_back({{sg.a[0], sg.a[1]}, {sg.b[0], sg.b[1]}});
            polylines.push_back({{"coordinate", c.coord}, {"level", upper ? c.hi : c.lo}, {"eps", eps}, {"segments", segs}});
          }
    }
    pieces.push_back({{"inner_box", box_to_json(C.inner_pieces[p.inner_piece].box)},
                      {"edge_crossings", crossings},
                      {"trimming_polylines", polylines},
                      {"outer_cell", p.outer_cell},
                      {"outer_box", box_to_json(C.outer_pieces[p.outer_cell].box)},
                      {"status", p.status == RegionStatus::untrimmed ? "untrimmed"
                                 : p.status == RegionStatus::trimmed ? "trimmed" : "unproven_nonempty"},
                      {"region", region},
                      {"homogeneous", p.patch.weighted},
                      {"patch", spline_to_json(p.patch.net)}});
  }
  return Json{{"pieces", pieces}, {"isoparametric_splits", C.isoparametric_splits},
              {"region_rule", "each condition on the inner spline's coordinate s_c = S(r)_c: at_least lo, below hi "
                              "(at_most hi at the outer domain's end); a homogeneous patch holds (w*R, w)"}};
}

}  // namespace splinex
