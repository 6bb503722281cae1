// The boundary structure of a trimmed V-cell (vrep/topology/trimmed_topology.cpp): corners, edge V-curves
// and V-points, half-V-surfaces and face curves, certified where stated.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The boundary structure of a trimmed cell (issue 18: the topology of trimmed cells, in part),
/// certified where stated (exact arithmetic; in double the same steps, uncertified):
///   - corners: the corners of V's domain that lie in the cell (every leaf strictly decided there,
///     the formula "in"; exact values of G);
///   - edges: each of the 12 edges of V's domain, cut exactly at the roots of every leaf along it
///     (univariate Bernstein polynomials, roots certified by the solver of solve/solver.hpp); the
///     runs of the edge inside the cell are its V-curves and their ends strictly inside the edge
///     its V-points (exact counts: `pieces`, `points`). An edge collapsed to a point, an edge on
///     which a leaf vanishes identically (it lies on a trimming surface) and an edge with a root the
///     solver leaves undecided (tangency) are said so and not counted;
///   - surfaces: the six faces of V's domain restricted to the cell (2D subdivision with the faces'
///     Bernstein coefficients) and, per leaf, its zero set where it bounds the cell (3D
///     subdivision). For each: proved absent (no box of its cover is left), and a lower bound on the
///     number of its connected pieces: components of its cover that hold a certified point (a face:
///     a box decided in; a trimming surface: a box where the leaf's corner values have both strict
///     signs, every other leaf's coefficients have one strict sign, and the formula changes with
///     the leaf), with V's own identifications joined (vrep/topology/box_components.hpp). The cover's
///     component count is shown beside it, not certified. Collapsed faces carry no surface;
///   - face curves: per face and leaf, the leaf's zero set where it bounds the face's part (the
///     trimming surface's boundary curve on that face): proved absent, or a lower bound on its
///     pieces as above (2D boxes of the face's subdivision), and its exact count (arcs and loops,
///     the certified curve graph of trimmed_curves in the face's two parameters; undecided at a
///     tangency, with the reason).
///   - V-points off the edges (below), exact where every system is decided.
/// The V-curves between two trimming surfaces are trimmed_curves' (below). What is not built:
/// counts of half-V-surfaces above the certified lower bounds.
template <class T>
struct TrimmedTopology {
  struct Edge {
    int along = 0;
    std::array<int, 3> sides{};  // sides[d] for d != along: 0 domain start, 1 end
    enum Status { curve, collapsed, on_trimming_surface };
    Uncertain<Status> status = curve;  // undecided: a solver box left (tangency), or the runs between events
    std::size_t pieces = 0;  // runs of the edge inside the cell (V-curves)
    std::size_t points = 0;  // their ends strictly inside the edge (V-points)
    std::vector<std::pair<T, T>> cuts;  // enclosures of those points' parameters (lo == hi: exact)
  };
  struct Surface {
    std::string what;          // "face w = 0" or "leaf 2 (cylinder: side)"
    int dir = -1, side = -1;   // a face of V's domain
    int leaf = -1;             // or a leaf of the trim (collect order)
    bool collapsed = false;    // a face of zero area
    bool absent = false;       // proved: it bounds the cell nowhere
    std::size_t at_least = 0;  // certified lower bound on its connected pieces
    std::size_t cover = 0;     // components of its cover (not certified)
    std::size_t boxes = 0, cover_boxes = 0;
    /// Exact where decided (vrep/topology/curve_graph.hpp: count_region for a face of the domain,
    /// count_surface for a trimming surface): the connected pieces of the interior of the part,
    /// in V's parameters (parts that touch at one point, or along a curve where a further sheet
    /// bounds, are apart); `on_identified_edges` of them reach an edge or face V identifies with
    /// another or collapses (there the count in space may be smaller). Undecided: the reason.
    bool decided = false;
    std::size_t pieces = 0, on_identified_edges = 0;
    std::string undecided_reason;
  };
  std::size_t corners = 0, corners_on_trimming = 0;  // in the cell; on a trimming surface (not counted)
  struct FaceCurve {
    int dir = 0, side = 0, leaf = 0;  // face (dir, side) of V's domain, leaf of the trim
    bool absent = false;
    std::size_t at_least = 0, cover = 0;
    /// Exact (the certified curve graph of trimmed_curves, in the face's two parameters): its
    /// pieces where the face's part depends on the leaf, cut at the face V-points where another
    /// leaf crosses; arcs end on the face's edges or at those V-points.
    bool decided = false;
    std::size_t arcs = 0, loops = 0, ends_on_edges = 0, ends_at_points = 0;
    std::string undecided_reason;
  };
  std::vector<Edge> edges;
  std::vector<Surface> surfaces;
  std::vector<FaceCurve> face_curves;  // per face (collapsed faces have none), per leaf
  /// V-points off the edges, exact: two leaves meeting on a face of the domain, three inside it,
  /// at a certified simple root where the formula depends on each of their signs (a corner of
  /// the cell's boundary). `points_undecided`: roots not certified, on a piece's boundary or with
  /// a further leaf not strictly signed near them (then the counts are lower bounds).
  struct VPoint {
    int dir = -1, side = -1;         // the face (dir, side) of V's domain, or -1 inside
    std::vector<std::size_t> leaves;  // the meeting leaves (collect order)
    std::vector<T> lo, hi;            // the root's box in V's parameters (on the face: its two directions)
  };
  std::size_t face_points = 0, interior_points = 0, points_undecided = 0;
  std::vector<VPoint> inner_points;
  std::size_t boxes = 0;  // 3D subdivision boxes of the trimming surfaces
};

template <class T>
TrimmedTopology<T> trimmed_topology(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes = 4096, const Limits& limits = {});

}  // namespace splinex
