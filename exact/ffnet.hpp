// A fraction-free exact spline net (issue 49; the plan is docs/design/fraction_free_plan.md).
//
// The same splines as BSpline<Rational>, stored so that exact work costs about what its arithmetic
// costs and not what copying rationals costs:
//   - a knot vector is integers k_j over one denominator K > 0 (u_j = k_j / K);
//   - a control point is m integers N_c over one denominator E > 0, its homogeneous coordinates
//     N_c / E: the q Cartesian coordinates of a polynomial spline, or (w*P, w) of a rational one
//     (m = q + 1), so a weight needs no division anywhere;
//   - every K is the lcm of its knots' reduced denominators (a knot vector's form is unique); a
//     point is divided by gcd(N_1..N_m, E) whenever its E passes 2^48, so its integers stay short
//     without a gcd per step, and is made canonical (reduced mpq) only at the boundary;
//   - the integers are FLINT fmpz words: a value below 2^62 in magnitude is the word itself, so a
//     net of small values is an array of 64-bit integers, copied by memcpy, and the operations
//     work on them with 128-bit products checked against FLINT's small range, falling back to
//     FLINT's big integers value by value when a product leaves it (never a silent overflow).
// Operations are written fraction-free per span: each new point is one integer blend of two old
// ones over (knot difference) * E, reduced once; nothing passes through a rational per coefficient.
//
// Conversions to and from BSpline<Rational> are exact and are the boundary (I/O, JSON, the GMP
// kernel as the reference): `to_bspline(from_bspline(S)) == S` field by field.
//
// Status: knot insertion (one knot any number of times; many knots at once, A5.4), clamping,
// Bezier form and pieces, degree elevation (A5.9; by one at p >= 3 the blossom), evaluation (de Boor, any dimension) and the
// conversions. Derivatives, integration and the certified engines are not ported.
#pragma once
#include <flint/fmpz.h>

#include <cstddef>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex::ff {

/// An owning array of FLINT integers (zero-initialised). Copies of small values are memcpy.
/// The destructor frees FLINT's big integers, which needs a pass over the words unless the array
/// is known to hold none: `known_small` is set by the copy constructor (its copy pass sees every
/// word) and by an operation that checked what it wrote (mark_small), and cleared by every
/// mutable access, so a value written after the mark is never left unfreed.
class ZVec {
 public:
  ZVec() = default;
  explicit ZVec(std::size_t n);
  ZVec(const ZVec& o);
  ZVec(ZVec&& o) noexcept : p_(o.p_), n_(o.n_), known_small_(o.known_small_) { o.p_ = nullptr; o.n_ = 0; }
  ZVec& operator=(const ZVec& o);
  ZVec& operator=(ZVec&& o) noexcept;
  ~ZVec();

  std::size_t size() const { return n_; }
  fmpz* data() { known_small_ = false; return p_; }
  const fmpz* data() const { return p_; }
  fmpz* operator+(std::size_t i) { known_small_ = false; return p_ + i; }
  const fmpz* operator+(std::size_t i) const { return p_ + i; }
  /// After the last write: the caller has checked that no word holds a big integer.
  void mark_small() { known_small_ = true; }
  bool known_small() const { return known_small_; }
  /// Heap bytes: the words plus the limbs of values past the small range.
  std::size_t heap_bytes() const;
  bool operator==(const ZVec& o) const;

 private:
  fmpz* p_ = nullptr;
  std::size_t n_ = 0;
  bool known_small_ = false;
};

/// A knot vector: u_j = k[j] / den, den > 0 the lcm of the reduced denominators.
struct FFKnots {
  ZVec k;
  ZVec den{1};  // one word, set to 1 below
  FFKnots() { fmpz_one(den.data()); }
  std::size_t size() const { return k.size(); }
};

struct FFNet {
  std::vector<int> degrees;
  std::vector<FFKnots> knots;
  int q = 0;               // Cartesian coordinates per point
  bool rational = false;   // homogeneous (w*P, w): m() = q + 1
  ZVec words;              // size() points of stride() words: N_1..N_m, E

  int dim() const { return static_cast<int>(degrees.size()); }
  std::size_t count(int d) const { return knots[d].size() - degrees[d] - 1; }
  std::size_t size() const;
  int m() const { return q + (rational ? 1 : 0); }
  std::size_t stride() const { return static_cast<std::size_t>(m()) + 1; }
};

/// Homogeneous points of an evaluation: per point m numerators and one positive denominator.
/// `to_points` gives the Cartesian values evaluate_points() returns (canonical).
struct FFPoints {
  int q = 0;
  bool rational = false;
  ZVec words;
};

/// Exact conversion from a validated spline (call validate() first; weights must be positive).
FFNet from_bspline(const BSpline<Rational>& S);
/// Exact conversion back; canonical mpq values, so the result compares equal to the GMP kernel's.
BSpline<Rational> to_bspline(const FFNet& F);
/// The Cartesian coordinates of evaluated points, point-major (as evaluate_points returns them).
std::vector<Rational> to_points(const FFPoints& P);

/// The same value: equal knot vectors (words), points equal by cross-multiplication.
bool same_value(const FFNet& A, const FFNet& B);
/// Heap bytes of the net's integers (knots and points), for the benchmark's bytes per coefficient.
std::size_t heap_bytes(const FFNet& F);

/// Which integers the operations may use: `small_first` (64-bit words, falling back to FLINT's
/// big integers value by value on overflow) or `big_only` (FLINT calls throughout; the tests run
/// every case both ways so the fallback is exercised everywhere).
enum class Tier { small_first, big_only };
struct Policy {
  Tier tier = Tier::small_first;
};
/// The policy of every thread (a test switch: change it only through PolicyScope, while no
/// fraction-free operation runs; a plain global, read in every step, costs nothing, where a
/// thread_local read through __tls_get_addr cost 2% of elevation).
inline Policy current_policy;
inline Policy& policy() { return current_policy; }
struct PolicyScope {
  explicit PolicyScope(Policy p) : saved_(policy()) { policy() = p; }
  ~PolicyScope() { policy() = saved_; }
  PolicyScope(const PolicyScope&) = delete;
  PolicyScope& operator=(const PolicyScope&) = delete;

 private:
  Policy saved_;
};
/// Counts of this thread's small-range products that overflowed into FLINT's big integers.
inline thread_local std::size_t promotion_count = 0;
inline std::size_t& promotions() { return promotion_count; }

/// The kernel's insert_knot (spline/insert.hpp): the same result, errors and limits.
FFNet insert_knot(const FFNet& F, int d, const Rational& x, int times = 1, const Limits& limits = {});
/// The kernel's refine_knots (A5.4): the same result, errors and limits.
FFNet refine_knots(const FFNet& F, int d, std::vector<Rational> X, const Limits& limits = {});
/// The kernel's evaluate_points: `params` holds N points of dim() parameters each; the same
/// checks and error fields ("params[i]"). The values are homogeneous.
FFPoints evaluate_points(const FFNet& F, const std::vector<Rational>& params);

/// The kernel's clamp (spline/insert.hpp): both domain ends of direction d raised to
/// multiplicity p+1 and the net cut there; the net itself when already clamped.
FFNet clamp(const FFNet& F, int d, const Limits& limits = {});

/// The kernel's BezierForm (spline/bezier.hpp): every interior breakpoint of every direction at
/// multiplicity p (A5.4), its breakpoints as numerators over that direction's knot denominator,
/// and the first control point of every segment.
struct FFBezierForm {
  FFNet spline;
  std::vector<ZVec> breaks;
  std::vector<std::vector<std::size_t>> first;
  std::size_t size() const;
  /// Piece k (direction 0 fastest) as a net of its own.
  FFNet piece(std::size_t k) const;
  /// The breakpoints as rationals (the boundary).
  std::vector<std::vector<Rational>> break_values() const;
};
FFBezierForm bezier_form(const FFNet& F, const Limits& limits = {});
/// Every piece (extract_bezier): bezier_form, then one net per piece.
std::vector<FFNet> extract_bezier(const FFNet& F, const Limits& limits = {});

/// The kernel's elevate_degree (spline/elevate.hpp) by A5.9 on the clamped net, cut at C^-1 knots
/// as the kernel cuts it (by one at degree >= 3: the symmetrized blossom, which keeps the integers
/// shorter): the same result (values are exact, so the kernel's `method` does not
/// change them), errors and limits.
FFNet elevate_degree(const FFNet& F, int d, int t, const Limits& limits = {});

}  // namespace splinex::ff
