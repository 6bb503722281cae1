// Algorithm 2 of papers/000: composition into tensor-product patches by untrimming.
//
// Steps 1-2 are Algorithm 1 (compose_trimmed): T cut into polynomial pieces T_j, S into Bezier
// pieces S_i (isoparametric crossings split), each (i, j) a trimmed region with its composed patch
// T_j^e(S_i). Step 5 (untrim): per inner piece, the trimming curves s_c = u_k are turned into a
// planar straight-line subdivision of the piece's box and tiled by the vertical line sweep of
// untrim/sweep.hpp; each tile is labelled with the region that owns its interior. Step 9: the
// tile's Coons patch Q (degree (1, 1)) is composed into the region's patch: R = T_j^e(S_i(Q)),
// degree 1 x (sum of the patch's degrees) per direction. Step 7 (expansion of T_j) is automatic:
// the patch is the polynomial T_j^e, defined off T_j's box (Observation 1), so tiles that stray
// across a knot line by the trimming tolerance are still composed.
//
// Trimming boundaries:
//  - exact: where s_c is affine on the piece, the trimming curve is a straight segment with
//    rational end points and the whole construction is exact; a curved trimming curve is a
//    DomainError (exact untrimming would need algebraic tile sides).
//  - polyline: curved trimming curves are traced as polylines within eps (float/trimming_polyline),
//    their double vertices taken exactly; straight ones stay exact. Tiles are labelled by the
//    polylines' sides, so the misassignment between polyline and true curve is the only error.
// Inner surfaces only (k = 2); T of any dimension n (surfaces into surfaces or trivariates).
#pragma once
#include <vector>

#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/sweep.hpp"

namespace splinex {

enum class TrimBoundary { exact, polyline };

struct TensorOptions {
  TrimBoundary boundary = TrimBoundary::exact;
  double eps = 1e-6;  // polyline tolerance (parameter units of the piece box scaled to [0, 1]^2)
  int grid = 16;      // marching-squares cells per direction for polylines
  TrimmedOptions trimmed;
};

template <class T>
struct TensorTile {
  std::size_t patch = 0;  // index into TensorComposition::trimmed.patches
  Tile<T> tile;           // in the inner piece's parameters (x = r_0, y = r_1)
  BSpline<T> Q;           // the tile's Coons patch, degree (1, 1), on [x_0, x_m] x [0, 1]
  Homogeneous<T> R;       // T_j^e(S_i(Q)), weighted when the patch is
  T area;                 // exact parameter area of the tile (in S's parameters)
};

template <class T>
struct TensorComposition {
  TrimmedComposition<T> trimmed;
  std::vector<TensorTile<T>> tiles;
  std::vector<std::vector<Segment2<T>>> subdivisions;  // per inner piece, the segments tiled
  std::size_t trapezoids = 0;
  std::size_t curved_boundaries = 0;    // trimming curves traced as polylines
  std::size_t straight_boundaries = 0;  // exact straight trimming segments
  T gap_area = T(0);      // parameter area no region's polyline sides claim (0 when exact)
  T overlap_area = T(0);  // parameter area claimed by two regions (0 when exact)
  /// R of tile k at (x, l), divided by the weight for homogeneous patches.
  std::vector<T> evaluate_tile(std::size_t k, const std::vector<T>& xl) const;
};

/// Size: every tile's net within limits.max_control_points, and all of them together within
/// limits.max_total_control_points, checked on their least sizes once the tiles are known, before
/// any is composed (SizeLimitError naming eps when polylines made the tiles).
template <class T>
TensorComposition<T> compose_tensor(const BSpline<T>& outer, const BSpline<T>& inner, const TensorOptions& options = {},
                                    const Limits& limits = {});

}  // namespace splinex
