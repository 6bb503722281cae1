// Trimmed V-cells on exact implicit regions (issue 18, What to build 1): Booleans of V-models whose
// cells are cut by curved surfaces.
//
// Many primitives have an exact implicit form: boxes (six planes), cylinders and cone frustums (a
// quadric and two planes), tori (one quartic). A `Region` is a formula over polynomial
// inequalities g(x, y, z) >= 0 (leaves) with and / or / not, read as a regularized set (closure of
// its interior; measure-zero differences do not count). Composed with a cell's trivariate
// T = (X, Y, Z) / W, a leaf becomes the tensor Bernstein polynomial G = W^k g(X/W, Y/W, Z/W) (k the
// total degree of g; the homogenized composition, exact: products of the homogeneous coordinates),
// whose sign is the sign of g o T (weights positive). Its Bernstein coefficients decide a box of
// T's parameter domain exactly: all >= 0 "in" (the box lies in the leaf's closed set), all <= 0
// "out" (it meets the leaf's interior nowhere), otherwise "mixed"; the formula combines these by
// Kleene's three-valued logic, which is sound for regularized sets. Boxes are halved (exact de
// Casteljau) until every box is decided or the budget is spent; the corner coefficients of a box
// are exact values of G, so a corner where every leaf is strictly decided is an exact witness point.
//
// A trimmed V-cell is a trivariate T restricted to the parameters where its `trim` region holds
// (T(u) in trim). classify_cell decides it: `whole` (every box in), `empty` (every box out), `cut`
// (an in-box or strict inside witness and an out-box or strict outside witness: certified), or
// `undecided` (mixed boxes left at the budget without both witnesses: tangential or near-tangential
// contact, which subdivision cannot decide - the caller gets a typed error).
//
// trimmed_boolean runs Algorithms 1-3 on such cells: intersect keeps each cell a of A restricted to
// region(B), subtract to not region(B), union is the intersection, A - B and B - A (B's cells
// restricted to not region(A)); empty cells are dropped, undecided ones are a DomainError naming
// the cell. A cell in both models holds, after its own trivariate, the trivariates of the other
// model's cells whose control-point bounding box meets its own (a superset of the cells it meets: the pairwise cells a & b of the paper would need the inverse of
// b's trivariate, which has no implicit form for a curved cell). The result's region is the Boolean
// of the input regions, so results feed further Booleans (Figure 15: one union, two subtractions).
//
// The boundary structure of a trimmed cell (trimmed_topology, below): exact V-points and V-curves on
// the trivariate's edges, certified lower bounds on its half-V-surfaces and on the trimming
// surfaces' boundary curves on its faces, exact V-points off the edges; the V-curves between two
// trimming surfaces and the trimming surfaces' curves on the faces exactly (trimmed_curves,
// below). What is not built: exact counts of the half-V-surfaces, and the gluing of trimmed
// cells. The
// Euler characteristic of a trimmed cell and of a model's point set is exact (trimmed_euler,
// model_euler, below).
//
// The volume of a trimmed cell (and moments, field integrals) is a certified enclosure, refined
// adaptively where the width is (integral_enclosures, below): in-boxes exact for polynomial cells,
// cut boxes between the exact volumes of half-spaces around the trimming surface, out-boxes 0.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "spline/bspline.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

/// A polynomial in x, y, z: exponents -> coefficient (zero coefficients are not stored).
template <class T>
struct Poly3 {
  std::map<std::array<int, 3>, T> terms;
  int degree() const;
};

/// `cases` is a piecewise formula: parts = {C_1, L_1, C_2, L_2, ...} stands for the union of the
/// C_i n L_i, where the pieces C_i cover space and overlap only on their boundaries (the writer's
/// claim: the piecewise surface of the sphere of seven cells, sphere_region). Kleene's logic reads
/// it through the cover: a box is in where every case has its piece out or its formula in, out
/// where every case has its piece out or its formula out (no piece at all: out, the union
/// reading). The cover is checked at a grid of points over the cells when a model's region or a
/// trimmed document is read (cases_cover_gap: sampled, not proved).
template <class T>
struct Region {
  enum Kind { leaf, all_of, any_of, complement, cases };
  Kind kind = leaf;
  Poly3<T> g;                 // leaf: g >= 0
  std::vector<Region> parts;  // all_of / any_of: the operands; complement: one; cases: piece, formula, piece, ...
  std::string label;          // where it came from ("box", "cylinder: side", ...), for messages
  /// A leaf standing for an earlier distinct leaf of the same formula (its index in collect
  /// order, counting leaves without an alias only), with the opposite sign when `flip`. Built
  /// internally (trimmed_glue: two cells' formulas over one set of distinct surfaces, so that
  /// equal surfaces are one leaf of the subdivision); never read from or written to documents.
  int alias = -1;
  bool flip = false;
};

/// Three-valued truth of a region on a point or a box: out < mixed (or "on the surface") < in.
enum class Truth { out = 0, mixed = 1, in = 2 };
const char* to_string(Truth t);

template <class T>
Region<T> region_leaf(Poly3<T> g, std::string label = {});
template <class T>
Region<T> region_and(std::vector<Region<T>> parts);
template <class T>
Region<T> region_or(std::vector<Region<T>> parts);
template <class T>
Region<T> region_not(Region<T> r);
/// The piecewise region of (piece, formula) pairs (Region::cases; the pieces must cover space).
template <class T>
Region<T> region_cases(std::vector<std::pair<Region<T>, Region<T>>> cases);

/// The exact regions of the primitives of vrep/primitives/primitives.hpp (in their standard placement).
template <class T>
Region<T> box_region(const std::vector<T>& lo, const std::vector<T>& hi);
template <class T>
Region<T> cylinder_region(const T& r, const T& h);
template <class T>
Region<T> cone_region(const T& r0, const T& r1, const T& h);
template <class T>
Region<T> torus_region(const T& R, const T& r);
/// A point of the grid of (n + 1)^3 points over the box of the cells' control points (those in
/// R^3) where every piece of some `cases` node of R is out: a gap in the cover the node claims.
/// The cover checked at those points only (sampled), not proved.
template <class T>
std::optional<std::vector<T>> cases_cover_gap(const Region<T>& R, const std::vector<BSpline<T>>& cells, int n = 8);

/// The exact point set of the sphere of seven cells (vrep/primitives/primitives.hpp: sphere_cells with the same
/// r, degree and pieces): any_of(the cube [-r/2, r/2]^3, cases over the six faces' cones cut into
/// the patch's pieces). On the piece of face +z over s in [s_a, s_b], t in [t_a, t_b] (the cone
/// x - s_a z >= 0, s_b z - x >= 0, y - t_a z >= 0, t_b z - y >= 0) the cell is z P(x/z, y/z) <= r,
/// P the piece's polynomial of degree `degree` in s and in t; times z^(2 degree) / z (z > 0 there):
/// the leaf r z^(2 degree - 1) - z^(2 degree) P(x / z, y / z) >= 0, of degree 2 degree (<= 8: degree
/// 2..4). The other faces by the cube's rotations, as the cells. The cube is the same set again: it
/// decides the boxes about the centre, where every cone meets.
template <class T>
Region<T> sphere_region(const T& r, int degree = 3, int pieces = 4);
/// The ball |x - c| <= r: the leaf r^2 - |x - c|^2 >= 0 (label "ball").
template <class T>
Region<T> ball_region(const std::array<T, 3>& c, const T& r);

/// The convex planar cells' half-spaces as a region (any_of over cells of all_of over faces), if
/// every cell has them (vrep/boolean/boolean.hpp: convex_planes).
template <class T>
std::optional<Region<T>> planar_region(const VModel<T>& M, const T& eps = T(0));

/// Placement: x -> P x + offset with P the cyclic permutation taking the z axis to `axis` (0, 1, 2:
/// x, y, z; 2 is the identity), exact; applied to a region and to trivariates alike.
template <class T>
Region<T> place_region(const Region<T>& R, int axis, const std::vector<T>& offset);
template <class T>
BSpline<T> place_trivariate(const BSpline<T>& V, int axis, const std::vector<T>& offset);

template <class T>
T poly_at(const Poly3<T>& g, const T* x);

/// The region at a point, exactly: in (every deciding leaf strictly), out, or mixed (x lies on the
/// zero set of a leaf that decides it: boundary, or interior where two pieces touch).
template <class T>
Truth classify_point(const Region<T>& R, const std::vector<T>& x, const T& eps = T(0));

/// The region with its coefficients rounded to double (figures, the float Boolean).
Region<double> region_to_double(const Region<Rational>& R);

/// A cell of a trimmed V-model: its trivariate (index into `trivariates`) restricted to `trim`.
template <class T>
struct TrimmedModel {
  struct Cell {
    std::size_t trivariate = 0;
    Region<T> trim;                      // an all_of with no parts: untrimmed
    std::string name;
    std::string category;                // "A", "both", "B" after a Boolean ("" for an input)
    std::vector<std::size_t> inherited;  // further trivariates that contain it (indices into `trivariates`)
    Truth status = Truth::in;            // in: whole trivariate; mixed: cut (certified)
    std::map<std::string, std::vector<T>> constants;
    std::map<std::string, BSpline<T>> fields;  // attribute trivariates on its trivariate's parameters
    std::vector<std::string> not_carried;       // fields of the other model's cells it meets, not taken over
  };
  std::vector<BSpline<T>> trivariates;
  std::vector<Cell> cells;
  Region<T> region;                      // the model's point set
};

/// A trimmed model rounded to double (trivariates, regions, constants) for the same Boolean in floats.
TrimmedModel<double> trimmed_to_double(const TrimmedModel<Rational>& M);

/// A V-model as untrimmed cells with the given region (its constants carried along).
template <class T>
TrimmedModel<T> as_trimmed(const VModel<T>& M, Region<T> region);

/// A primitive placed (place_trivariate on its cells, place_region on its region) and glued, as
/// untrimmed cells: an operand for trimmed_boolean.
template <class T>
TrimmedModel<T> placed_primitive(std::vector<BSpline<T>> cells, const Region<T>& region, int axis, const std::vector<T>& offset);

struct TrimOptions {
  std::size_t max_boxes = 4096;  // per cell: the subdivision budget of the classification
};

/// The decision on one trimmed cell, with exact witness parameters where they were found.
template <class T>
struct CellClass {
  enum Kind { whole, empty, cut, undecided } kind = whole;
  std::size_t boxes = 0, mixed = 0;   // boxes at the end, of them mixed
  std::vector<T> inside, outside;     // witness parameters (u, v, w) strictly inside / outside
};
template <class T>
const char* to_string(typename CellClass<T>::Kind k);

template <class T>
CellClass<T> classify_cell(const BSpline<T>& V, const Region<T>& trim, const TrimOptions& options = {}, const T& eps = T(0),
                           const Limits& limits = {});

template <class T>
TrimmedModel<T> trimmed_boolean(const TrimmedModel<T>& A, const TrimmedModel<T>& B, BooleanOp op, Blend blend = Blend::sum_clipped,
                                const TrimOptions& options = {}, const T& eps = T(0), const Limits& limits = {});

/// Certified, adaptive enclosures of volumes, moments and field integrals over (trimmed) cells
/// (vrep/trimmed/enclosure_impl.hpp has the method). One priority queue of parameter boxes over all the
/// cells: the box with the widest bounds is halved (exact de Casteljau) until the summed width is
/// at most rel_width times the summed volumes' lower bound (each moment's: rel_width times that
/// times its scale, the largest |coordinate| or |field component| of the control points) or the
/// budget of max_boxes boxes per cell (in all: max_boxes times the cells) is spent; rel_width 0
/// spends the budget (unless every bound is exact first). Per box: out of the trim 0; in it, exact
/// for a polynomial cell (the mean of the integrand's Bernstein coefficients), for a rational one
/// Taylor's formula of W^-p of order 6 with a certified remainder, and Jensen / chord; cut by one
/// trimming surface that is a graph over two parameter directions, the part's integral through a
/// certified biquadratic approximation of the graph (within eps, from the composition of the
/// surface's polynomial with it); other cut boxes between the exact volumes of two half-spaces
/// around the surface, or between none and all of the box. Each bound is rounded outward to about
/// 64 significant bits once its numbers pass 128 bits (exact values stay exact). A negatively
/// oriented cell's volume is the integral's magnitude (the orientation decided exactly, from the
/// integral of det J's numerator over the cell's first piece; the volume's lower bound then at
/// least 0). A box where det J's numerator changes sign gives the integral of det J, not of
/// |det J|: give regular trivariates.
template <class T>
struct IntegrandCell {
  const BSpline<T>* trivariate = nullptr;
  const Region<T>* trim = nullptr;    // nullptr: the whole trivariate
  const BSpline<T>* field = nullptr;  // the components integrated are this field's (F det J), else point coordinates (X_c det J)
};
template <class T>
struct IntegralEnclosures {
  std::vector<VolumeEnclosure<T>> volume;               // per cell (boxes: its boxes at the end)
  std::vector<std::vector<VolumeEnclosure<T>>> moment;  // per cell, per component asked for
  VolumeEnclosure<T> total;                             // the volumes' sum (boxes: all)
  std::vector<VolumeEnclosure<T>> total_moment;         // per component, summed over the cells
  std::vector<T> scale;                                 // per component: the moment's scale (see above)
  std::size_t budget = 0;                               // the boxes allowed in all
  bool reached = false;                                 // the widths are within the target (else the budget was spent)
};
template <class T>
IntegralEnclosures<T> integral_enclosures(const std::vector<IntegrandCell<T>>& cells, const std::vector<int>& components, const T& rel_width,
                                          std::size_t max_boxes = 4096, const Limits& limits = {});

/// Certified volume enclosure of a trimmed cell (integral_enclosures with one cell; by default
/// within 1% or the budget).
template <class T>
VolumeEnclosure<T> trimmed_volume(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes = 4096, const Limits& limits = {},
                                  const T& rel_width = T(1) / T(100));

/// The volume and the integral of point coordinate `coordinate` (0..2: x, y, z, the centroid's
/// numerator; 3..q-1: an attribute coordinate carried by the trivariate) over a trimmed cell, both
/// certified enclosures from the same subdivision (integral_enclosures: Q = X_c N over W^5).
template <class T>
struct MomentEnclosure {
  VolumeEnclosure<T> volume, moment;
};
template <class T>
MomentEnclosure<T> trimmed_moment(const BSpline<T>& V, const Region<T>& trim, int coordinate, std::size_t max_boxes = 4096,
                                  const Limits& limits = {}, const T& rel_width = T(1) / T(100));

/// The volume and the integral of a field's component over a trimmed cell (the integrand F det J
/// over the trimmed parameter region; papers/002 Section 3.1.2's attribute fields), certified as
/// trimmed_moment is: F and the trivariate are refined to common breakpoints, Q = F N over W^4;
/// exact for a polynomial cell and field where the cell is decided whole. The field must be a
/// polynomial trivariate on the cell's parameter domain (rational: DomainError).
template <class T>
MomentEnclosure<T> trimmed_field_integral(const BSpline<T>& V, const Region<T>& trim, const BSpline<T>& field, int component = 0,
                                          std::size_t max_boxes = 4096, const Limits& limits = {}, const T& rel_width = T(1) / T(100));

namespace vrep_testing {
/// Test seam (tests only; nothing in the program or the library sets it): while a
/// ScopedEnclosurePlant is alive, integral_enclosures runs an unsound variant, so tests can show
/// that a wrong enclosure fails to contain the true value. drop_crossing: boxes cut by a trimming
/// surface count as empty; shrink_last_bit: each cell's upper volume bound is lowered by one unit
/// in its 64th significant bit. Off: one read of a plain enum per run.
enum class EnclosurePlant { none, drop_crossing, shrink_last_bit };
inline EnclosurePlant planted_enclosure = EnclosurePlant::none;
class ScopedEnclosurePlant {
 public:
  explicit ScopedEnclosurePlant(EnclosurePlant p) : previous_(planted_enclosure) { planted_enclosure = p; }
  ~ScopedEnclosurePlant() { planted_enclosure = previous_; }
  ScopedEnclosurePlant(const ScopedEnclosurePlant&) = delete;
  ScopedEnclosurePlant& operator=(const ScopedEnclosurePlant&) = delete;

 private:
  EnclosurePlant previous_;
};
}  // namespace vrep_testing

/// That the model lies in its region: every cell's trivariate classifies `whole` against it (the
/// cells of a primitive against the primitive's region), and every boundary face lies on the
/// zero set of a leaf of the region (the face's coefficients of that leaf's G are all zero).
/// Returns the failures (empty: both hold).
template <class T>
std::vector<std::string> check_region(const VModel<T>& M, const Region<T>& R, const TrimOptions& options = {}, const Limits& limits = {});

}  // namespace splinex

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
    enum Status { curve, collapsed, on_trimming_surface, undecided } status = curve;
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

/// The gluing of a trimmed V-model (issue 18: Definition 3.9 for trimmed cells), exact where
/// decided. The halves are every cell's faces of its domain (not collapsed) and its distinct
/// trimming surfaces (proportional leaves are one surface). Per half, by certified subdivision
/// (count_region on the face, count_surface on the surface; vrep/topology/curve_graph.hpp), the pieces of
/// its part where the other side lies in the model (`internal`: a V-surface shared with another
/// cell, or the cell itself across a seam) and where it does not (`boundary`). The twins:
///   - one trivariate, the two sides of one trimming surface (a cell and its complement in a
///     Boolean): the pieces of the surface where one cell lies on each side, exact;
///   - faces of two trivariates equal as surfaces (exact same_surface; seams of one trivariate
///     too): the pieces of the face where both cells lie, exact;
///   - contacts: a face half's internal part not on an exact twin (a cell of one operand against
///     the trimming surface of a cell of the other, which is not a parameter face of both), matched
///     at exact witness points: rational points of the face part, each located exactly on a
///     trimming surface's part of a cell of another trivariate (its leaves' exact signs; inside its
///     trivariate by the exact affine inverse or the certified solver). Decided when the two halves
///     met only each other and their unmatched parts have equal piece counts: a sampled match,
///     said so (`witness_points`), not a proof that the two parts are one set.
/// Counts are in the trivariates' parameters, like trimmed_topology's. The V-model counts:
/// `boundary_v_surfaces` (the boundary pieces) and `internal_v_surfaces` (the twins' pieces).
struct TrimmedGlueOptions {
  std::size_t max_boxes = 4096;  // per count and attempt (count_region / count_surface)
  std::size_t witnesses = 16;    // per face half with an unmatched part
};

template <class T>
struct TrimmedGluing {
  struct Half {
    std::size_t cell = 0;
    std::string what;
    int dir = -1, side = -1;  // a face of the cell's domain
    int leaf = -1;            // or a trimming surface (collect order in the cell's trim)
    bool decided = false;
    std::size_t internal = 0, boundary = 0;  // pieces of the part with the other side in / out of the model
    std::size_t unmatched = 0;               // pieces of the internal part on no exact twin
    std::string undecided_reason;
  };
  struct Twin {
    std::size_t a = 0, b = 0;  // halves
    std::string how;
    bool decided = false;
    std::size_t pieces = 0;     // of the shared part (V-surfaces)
    std::size_t witnesses = 0;  // contacts: the witness points located on both
    std::string undecided_reason;
  };
  std::vector<Half> halves;
  std::vector<Twin> twins;
  std::size_t part_pieces = 0;          // internal + boundary pieces over the halves (before twins split them)
  std::size_t half_v_surfaces = 0;      // of the glued V-model: boundary + 2 internal
  std::size_t boundary_v_surfaces = 0;  // boundary pieces
  std::size_t internal_v_surfaces = 0;  // pieces of the twins' shared parts
  std::size_t contacts = 0, witness_points = 0;  // of them matched at witness points
  std::size_t unmatched_halves = 0;     // halves with an unmatched part and no partner found
  bool decided = false;                 // every count above decided
};

template <class T>
TrimmedGluing<T> trimmed_glue(const TrimmedModel<T>& M, const TrimmedGlueOptions& options = {}, const Limits& limits = {});

/// The V-curves between two trimming surfaces of a trimmed cell (issue 18), per pair of leaves
/// (i, j): the parts of the curve {g_i = g_j = 0} in the open parameter domain along which the
/// formula depends on both signs (the two surfaces meet in an edge of the cell's boundary), cut at
/// the V-points where a third trimming surface crosses it. Counted exactly from a certified graph:
/// the domain is subdivided (split fraction 1/2, retried at 7/16 and 13/32 when a crossing falls
/// on a split line) until, in every box where both leaves may vanish and the edge may matter,
///   - one component of grad g_i x grad g_j has one strict sign (Bernstein coefficients): the
///     curve is smooth there and monotone along that direction, so it holds no closed loop and
///     each of its pieces in the box runs from one face of the box to another;
///   - the crossings of the curve with the box's six faces (2x2 systems, the certified solver of
///     solve/solver.hpp: simple roots strictly inside the face) are exactly two: one arc, or none:
///     no curve;
///   - every other leaf has one strict sign, or exactly one leaf k does not and
///     det(grad g_i, grad g_j, grad g_k) has one strict sign: g_k is monotone along the arc, so
///     the arc meets g_k = 0 at most once, exactly when g_k has opposite strict signs at its ends.
/// Crossings on a face two boxes share are matched (every root box overlaps exactly one on the
/// other side); an arc's activity is the formula's dependence on both signs with the other leaves
/// at their signs there. V-points (the formula depends on all three signs) cut the curves.
/// Components with ends (on the domain's faces or at V-points) are arcs, the others loops.
/// The counts are in V's parameter domain: a V-curve that meets a face V identifies with another
/// (a seam) or collapses is counted once per side (`ends_on_identified_faces` says how often).
/// Undecided (the reason said) for a pair when a curve is tangent to a face or a split plane, two
/// crossings cannot be told apart, a trimming surface contains a face or a split plane, more than
/// three surfaces meet, or the box budget is spent. Exact in exact arithmetic; in double the same
/// steps on rounded values, uncertified.
struct CurveOptions {
  std::size_t max_boxes = 6000;       // subdivision boxes per pair and attempt
  int max_level = 36;                 // splits of one box (all directions together)
  std::size_t max_total_boxes = 200000;  // over all pairs and attempts of one cell: the pairs left are undecided
};
template <class T>
struct TrimmedCurves {
  struct Pair {
    std::size_t i = 0, j = 0;  // the leaves (collect order)
    bool decided = false;
    std::size_t arcs = 0, loops = 0;                    // V-curves with two ends; closed ones
    std::size_t ends_on_faces = 0, ends_at_points = 0;  // ends of the arcs: on the domain's faces, at V-points
    std::size_t ends_on_identified_faces = 0;           // of those on faces: on a seam or a collapsed face
    std::size_t boxes = 0, crossings = 0;               // boxes of the deciding attempt; face crossings found
    T split = T(0);                                     // the split fraction that decided it
    std::string undecided_reason;
  };
  std::vector<Pair> pairs;  // every pair of leaves whose zero sets may meet in the domain
  bool decided = true;      // every pair decided
  std::size_t arcs = 0, loops = 0;  // totals over the decided pairs
};
template <class T>
TrimmedCurves<T> trimmed_curves(const BSpline<T>& V, const Region<T>& trim, const CurveOptions& options = {}, const Limits& limits = {});

/// The Euler characteristic of a trimmed cell, exactly (vrep/topology/trimmed_euler.cpp has the method):
/// chi_c is additive over the open cells of a box subdivision of V's parameter domain; on an open
/// cell where every undecided leaf is monotone along one direction and the formula closed that
/// way, chi_c is minus that of one open face (the fibres are half-open or whole intervals), where
/// the formula is decided it is (-1)^dim or 0, otherwise the cell is halved. The set is the
/// closed one (leaves read g >= 0, complements g <= 0): the regularized cell wherever the trimming
/// surfaces are regular.
///   - chi: of the cell in V's parameter domain;
///   - image_chi: of T(cell), V's own identifications counted once (faces equal by same_surface,
///     edges by same_curve, corners at one point; collapsed faces and edges not at all); V is
///     assumed injective otherwise (valid trivariate);
///   - interior_chi_c: chi_c of the open set (strict leaves on the open domain); for a compact
///     3-manifold with boundary it is -chi (duality: a necessary check, not a proof of regularity).
/// Undecided (a singular point of a trimming surface, a tangency with the domain or with a split
/// plane; the split fraction 1/2 is retried at 7/16 and 13/32) when no cell's direction is
/// monotone within max_level halvings or the cell budget is spent. Exact in exact arithmetic; in
/// double the same steps on rounded signs, uncertified.
struct EulerOptions {
  std::size_t max_cells = 400000;  // open cells visited per attempt
  int max_level = 24;              // halvings per direction
};
template <class T>
struct TrimmedEuler {
  bool decided = false;
  long chi = 0, image_chi = 0, interior_chi_c = 0;
  bool duality = false;  // interior_chi_c == -chi
  std::size_t identified_faces = 0, identified_edges = 0, identified_corners = 0;  // not counted in the image
  std::size_t resolved_contacts = 0;    // boundary strata on a trimming surface read from inside
  std::size_t unresolved_contacts = 0;  // ... where the sign inside is not one strict sign (left as 0)
  std::size_t cells = 0;  // open cells visited (all attempts)
  T split = T(0);         // the split fraction that decided it
  std::string undecided_reason;
};
template <class T>
TrimmedEuler<T> trimmed_euler(const BSpline<T>& V, const Region<T>& trim, const EulerOptions& options = {}, const Limits& limits = {});

/// The Euler characteristic of a region of space inside the box [lo, hi] (the region as the trim
/// of the box's identity trivariate), and of a trimmed model's point set (its region in its
/// cells' control-point box grown by a sixteenth of its largest side, at least 1/16, all round,
/// so no face of the box meets it): the model's chi after a Boolean, with the regularized
/// Booleans' inclusion-exclusion chi(A u B) = chi(A) + chi(B) - chi(A n B) to check it by.
template <class T>
TrimmedEuler<T> region_euler(const Region<T>& R, const std::vector<T>& lo, const std::vector<T>& hi, const EulerOptions& options = {},
                             const Limits& limits = {});
template <class T>
TrimmedEuler<T> model_euler(const TrimmedModel<T>& M, const EulerOptions& options = {}, const Limits& limits = {});

}  // namespace splinex
