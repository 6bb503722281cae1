// The cutting surface of papers/004 Section 4 (d = 3): a trimmed bicubic tensor-product patch
// p: Omega -> R^3, Omega a polygon in [0, 1]^2 whose edges correspond to the loop's sides, and the
// exact certificate of its validity (Section 2's conditions).
//
// Step 1, the domain polygon (Omega):
//   projection  the loop's vertices projected along the axis of the largest component of the loop's
//               Newell normal (a parallel projection onto a coordinate plane: exact), oriented
//               counter-clockwise and scaled uniformly into [0, 1]^2; used when the result is a
//               simple polygon (CGAL's is_simple_2 on exact rationals) with no collapsed side.
//   qp          Eq. 5: edge lengths x_j closest to the loop's side lengths (min sum (x_j / l_j - 1)^2)
//               along directions turning by the loop's turning angles (seen along its Newell normal,
//               scaled to sum 2 pi), subject to the polygon closing. cos and sin are not rational, so
//               each direction is an exact rational unit vector within 2^-12 rad of the angle
//               (tan of the half angle rounded to a multiple of 2^-12); the closure is then exact and
//               the least-squares solve (a 2 x 2 system) is exact. Vertices rounded to multiples of
//               2^-11 after the uniform scaling; used when every x_j > 0 and the polygon is simple
//               and counter-clockwise.
//   circle      the fallback: the vertices on the circle of radius 1/2 about (1/2, 1/2), at angles
//               proportional to the loop's arc length (cos and sin by MPFR, not double), each
//               coordinate rounded to a multiple of 2^-11 (small denominators keep the exact program
//               short), joined by straight edges (the paper's curved polygon is not built); checked
//               simple like the projection.
//   auto tries projection, then qp, then circle, as the paper does.
//
// Step 2, the control points: the quadratic initial solution of the paper (the weight of Eq. 6 set
// to zero) minimizes
//   w_bnd * mean over boundary samples of (|p(t) - L(t)|^2 + lambda (p_u . n)^2 + lambda (p_v . n)^2)
//   + w_fair * (thin-plate energy of each coordinate over [0, 1]^2)
// (Eq. 7 with its integral replaced by the mean over `boundary_samples` points per edge; n the loop
// side's unit normal, LoopSide3::normal, rounded to a multiple of 2^-20) subject to p(W_j) = L_j at every vertex (equalities) and
// t . (dp/dm) >= tangent_delta at the boundary samples (inequalities: the prescribed tangent t
// points into the patch; m the edge's inward normal in Omega, scaled to max-norm 1). Solved by a
// primal active-set method whose steps are KKT systems (exact: FLINT's Dixon solver; double:
// Eigen's LU), the tangent rows joining and leaving the working set; CGAL's QP solver on the whole
// program if it does not finish. Either way the KKT conditions of the full program are checked
// exactly (for a double solution they hold only approximately, and the check says which fails).
//
// Certificates (exact, on the patch as its exact rational control points define it):
//   vertices     p(W_j) = L_j exactly (or the largest error, for a double patch);
//   boundary     an upper bound of max |p(e_j(s)) - L_j(s)|_inf along every edge (Bernstein
//                coefficients of the composition p o e_j minus the side); the sides are interpolated
//                at the vertices only, so this is a measured deviation, not a zero;
//   tangents     t . (dp/dm) > 0 along every edge (Bernstein signs of the composed derivatives,
//                halving; an exact point with <= 0 is a witness of violation);
//   regular and  the projection P of Step 1 applied to p has a Jacobian whose symmetric part is
//   injective    positive definite on the bounding box of Omega (a monotone map on a convex set is
//                injective, and p's normal has a non-zero component along the projection axis):
//                Bernstein signs of dP1/du and 4 dP1/du dP2/dv - (dP1/dv + dP2/du)^2 (P composed with
//                the 2 x 2 fit of the projected loop to Omega). If that fails, a grid of 3 x 3 windows
//                each mapped monotonically by its own linear map, far cells with disjoint boxes
//                (grid_injectivity in the source); failing that, det DP > 0 on Omega proves
//                regularity alone and injectivity stays undecided;
//   collision    no point of p(Omega) outside the strip around the loop (max-norm distance <= strip)
//                lies on a facet: control boxes of patch pieces against those of the facets' Bezier
//                pieces, patch pieces halved; a patch point outside the solid (exact ray parity,
//                for solids of bilinear quadrilateral facets, planar or not) is a witness of collision.
// The verdict: valid when the vertices are exact and the other four are certified, invalid with a
// witness, else undecided.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "base/verdict.hpp"
#include "cut/qp.hpp"
#include "cut/solid3.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct SurfaceFacetOptions {
  std::string domain = "auto";  // "auto" (projection, else qp, else circle), "projection", "qp", "circle"
  int inner_knots = 3;          // uniform inner knots per direction (the paper: 3)
  int boundary_samples = 4;     // samples of Eq. 7 per edge (edge parameters (2i+1)/(2 m))
  Rational weight_boundary{1};  // the paper's standard weights (10, 1, 1): the second and third
  Rational weight_fair{1};
  Rational lambda{1};           // lambda of Eq. 7
  Rational tangent_delta{1, 20};
  int active_set_steps = 300;   // then CGAL's QP solver
  // certificates
  Rational strip{1, 16};
  int max_depth = 14;                // halvings of one piece
  std::size_t max_pieces = 200000;   // pieces examined per certificate
  bool progress = false;             // phase lines on stderr
};

/// The checks of the options (typed errors naming the option), before any work.
void validate_surface_options(const SurfaceFacetOptions& o);

struct DomainPolygon {
  std::string method;                             // "projection", "qp" (Eq. 5) or "circle"
  std::string why_not_projection;                 // when another method was used
  std::string why_not_qp;                         // when the circle was used
  std::vector<std::array<Rational, 2>> vertices;  // counter-clockwise; vertex j <-> loop side j's start
  std::array<int, 2> axes{0, 1};                  // the coordinates the projection keeps (P = (x_a0, x_a1))
};

/// The loop's Newell normal (twice its vector area), exactly, and the projection Step 1 uses: the
/// two coordinates other than the normal's largest component, ordered so that the projected loop
/// runs counter-clockwise.
std::array<Rational, 3> newell_normal(const std::vector<LoopSide3>& loop);
std::array<int, 2> projection_axes(const std::vector<LoopSide3>& loop);

/// Step 1 for the loop (normalized coordinates; sides in cycle order).
DomainPolygon domain_polygon(const std::vector<LoopSide3>& loop, const std::string& method = "auto");

template <class T>
struct CuttingSurface {
  DomainPolygon domain;
  BSpline<Rational> patch;             // exact control points (double: the doubles' exact values); normalized coordinates
  std::vector<Rational> coefficients;  // the program's minimizer (double: of the rounded program)
  std::string solver;                  // which solve gave it
  bool kkt_holds = false;              // the full program's KKT conditions, checked exactly
  std::string kkt_failed;
  std::size_t variables = 0, equalities = 0, inequalities = 0, active_inequalities = 0;
  QuadraticProgram<Rational> program;  // exactly (double: its doubles' values); rows: each equality as a >= and a <= row, then the tangent rows
  double seconds = 0;
};

/// The domain Step 2 uses: domain_polygon(loop, options.domain), except that under "auto" a qp
/// polygon whose vertex interpolation conditions are dependent for options.inner_knots (many
/// vertices on a line, like the maiden's unfolded wave) gives way to the circle, with why_not_qp
/// saying so.
DomainPolygon patch_domain(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& options);

/// Before any work: the options, Step 1, and the vertex interpolation conditions' rank (exact), so
/// that a singular program is a typed error before the first progress line.
void check_patch_program(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& options);

/// Step 2. solid and loop normalized (GuideResult3's solid and loop, or to_frame + validate_cut).
template <class T>
CuttingSurface<T> cutting_surface(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& options = {});

/// The nonlinear step of Step 2: the first term of the objective, Eq. 6, w_guide times the mean of
/// omega(t) f*(p(t))^2 over the grid points t of Omega (omega: the distance to the boundary of Omega
/// over its largest value, so 0 on the boundary and 1 at the most central sample), added to the
/// quadratic program's objective, minimized from the initial solution by Gauss-Newton steps in
/// double with the vertex equalities and the tangent rows active at the start held as equalities
/// (each step an Eigen LU on the KKT system; steps halved until the objective decreases). The
/// paper uses Matlab's fmincon here. The final doubles, which interpolate the vertices only within
/// rounding, are projected exactly onto the vertex equalities (the least change, solved exactly);
/// every certificate is then decided exactly on that patch.
struct GuidedOptions {
  double weight_guide = 10;  // the paper's standard weights (10, 1, 1): the first
  int grid = 16;             // grid x grid points over Omega's bounding box (those in Omega)
  int iterations = 30;
};
struct GuidedResult {
  BSpline<Rational> patch;
  int iterations = 0;
  double objective_before = 0, objective_after = 0;
  double max_abs_f_before = 0, max_abs_f_after = 0;  // max |f*(p(t))| over the samples
  std::size_t samples = 0;
  double seconds = 0;
};
void validate_guided_options(const GuidedOptions& options);
/// f: the guide on [0,1]^3 (normalized coordinates); points p(t) outside [0,1]^3 are clamped into it
/// for f*'s evaluation.
GuidedResult refine_with_guide(const CuttingSurface<Rational>& initial, const BSpline<double>& f, const GuidedOptions& options = {});

/// Section 2's conditions of a cutting surface, each a Verdict; their words in documents and
/// tables are certificate_word (tangents), status_name (regular, injective: proved or undecided),
/// collision_word and validity_word (the whole surface; cut/solid.hpp).
struct SurfaceValidity {
  Verdict verdict;  // valid (proved), invalid (refuted: the witness) or undecided
  bool vertices_exact = false;
  Rational vertex_error{0};        // max |p(W_j) - L_j|_inf
  Rational boundary_deviation{0};  // upper bound of max |p(e_j(s)) - L_j(s)|_inf
  Verdict tangents;                // refuted: the tangent witness
  Verdict regular, injective;      // proved or undecided (the method says why)
  std::string regularity_method;
  Verdict collision;  // no collision outside the strip; undecided: pieces left, or not examined (another condition failed)
  std::size_t collision_pieces = 0, collision_excluded = 0, collision_undecided = 0;
  std::string membership;  // how the witness test decides inside/outside, or why it cannot
  struct Witness {
    std::string condition;
    std::array<Rational, 2> param;  // in Omega
    std::array<Rational, 3> point;  // p there (normalized)
    Rational value{0};              // t . dp/dm for a tangent witness
    std::string detail;
  };
  std::optional<Witness> witness;
  double seconds = 0;
};

/// The collision condition's word: "none outside the strip (certified)", "violated", "undecided", or
/// "not examined (another condition failed)".
inline std::string collision_word(const Verdict& v) {
  if (v.is_proved()) return "none outside the strip (certified)";
  if (v.is_refuted()) return "violated";
  return v.reason().rfind("not examined", 0) == 0 ? v.reason() : status_name(v.status());
}

/// The certificates above, exactly. solid and loop normalized.
SurfaceValidity certify_cutting_surface(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const DomainPolygon& domain,
                                        const BSpline<Rational>& patch, const SurfaceFacetOptions& options = {});

/// Eq. 6's weight chosen automatically: refine_with_guide from the initial patch with each weight in
/// turn (smallest first; each run starts from the initial patch, so the steps are independent), the
/// result certified exactly, until one is valid. The paper's weight 10 is too weak for loops whose
/// plane cuts the solid (the vase needs about 10^5 at thin-plate weight 1). Returns every step run;
/// the last is the valid one, or the last weight's when none is.
struct GuidedStep {
  double weight = 0;
  GuidedResult result;
  SurfaceValidity validity;
};
std::vector<GuidedStep> refine_with_guide_sweep(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const CuttingSurface<Rational>& initial,
                                                const BSpline<double>& f, const GuidedOptions& base, const std::vector<double>& weights,
                                                const SurfaceFacetOptions& options = {});

/// Whether x lies inside the solid, outside, or on its boundary, exactly, for solids whose facets
/// are bilinear quadrilaterals: ray parity with rational rays; planar convex facets as two
/// triangles, non-planar ones (injective hyperbolic paraboloids) by the roots of the quadratic their
/// ray equations leave, signs decided on exact quadratic irrationals p + s sqrt(D); a ray through an
/// edge, a vertex or tangent to a facet is replaced by the next. nullopt for other solids (other
/// degrees, planar non-convex quadrilaterals).
enum class Membership { inside, outside, boundary };
std::optional<Membership> point_in_solid(const Solid3<Rational>& solid, const std::array<Rational, 3>& x);

/// The two sub-solids of a split along a valid cutting surface: facet lists (b with the patch,
/// b-bar with the patch reversed). The patch is trimmed (Omega), so the parts are not Solid3's.
struct SurfaceSplit {
  std::vector<std::size_t> part1, part2;  // facets of b, of b-bar
};
SurfaceSplit split_by_surface(const Solid3<Rational>& solid, const std::vector<std::size_t>& positive);

}  // namespace splinex
