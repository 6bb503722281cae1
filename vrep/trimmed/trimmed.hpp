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
// The topology of trimmed cells is in vrep/topology/, one header per implementation file: the
// boundary structure (trimmed_topology.hpp), the V-curves between two trimming surfaces
// (trimmed_curves.hpp), the gluing into one V-model (trimmed_glue.hpp) and the Euler
// characteristic (trimmed_euler.hpp).
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
#include "base/verdict.hpp"
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
  enum Kind { whole, empty, cut };
  Uncertain<Kind> kind = whole;  // undecided: mixed boxes left at the budget without both witnesses
  std::size_t boxes = 0, mixed = 0;   // boxes at the end, of them mixed
  std::vector<T> inside, outside;     // witness parameters (u, v, w) strictly inside / outside
};
template <class T>
const char* to_string(const Uncertain<typename CellClass<T>::Kind>& k);
/// The kind from what the classification found: with no mixed box left (`settled`) whole, empty or
/// cut by where the boxes lie; otherwise cut when a point inside and one outside were found, else
/// undecided.
template <class T>
Uncertain<typename CellClass<T>::Kind> cell_kind(bool settled, bool in, bool out) {
  using K = typename CellClass<T>::Kind;
  if (settled) return in && out ? K::cut : in ? K::whole : K::empty;
  if (in && out) return K::cut;
  return Uncertain<K>::undecided("mixed boxes left at the budget without both witnesses (a point inside and one outside)");
}

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
