// Regions (vrep/trimmed/trimmed.hpp) and their three-valued logic on boxes: building formulas,
// polynomials in x, y, z, Kleene's combination of the leaves' truths, which leaves a box still
// depends on, the truth of a leaf from its Bernstein coefficients, and the limits of the leaves
// composed with a trivariate. Internal to vrep/trimmed/ (included by trimmed_impl.hpp).
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <deque>
#include <iterator>
#include <optional>
#include <queue>

#include "base/verdict.hpp"
#include "bernstein/subdivide.hpp"
#include "spline/bezier.hpp"
#include "spline/insert.hpp"
#include "spline/knots.hpp"
#include "vrep/boolean/boolean_impl.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/primitives/primitives_impl.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

template <class T>
int Poly3<T>::degree() const {
  int k = -1;
  for (const auto& [e, c] : terms) k = std::max(k, e[0] + e[1] + e[2]);
  return k;
}

template <class T>
Region<T> region_leaf(Poly3<T> g, std::string label) {
  for (auto it = g.terms.begin(); it != g.terms.end();)
    it = it->second == T(0) ? g.terms.erase(it) : std::next(it);
  if (g.terms.empty()) throw ValidationError("region" + (label.empty() ? std::string() : " (" + label + ")"), "has the zero polynomial as a leaf",
                                             "give a non-zero polynomial g (the leaf is g >= 0)");
  for (const auto& [e, c] : g.terms)
    if (e[0] < 0 || e[1] < 0 || e[2] < 0) throw ValidationError("region", "has a negative exponent", "give exponents >= 0");
  Region<T> r;
  r.kind = Region<T>::leaf;
  r.g = std::move(g);
  r.label = std::move(label);
  return r;
}
namespace vrep_detail {
template <class T>
Region<T> region_of(typename Region<T>::Kind kind, std::vector<Region<T>> parts) {
  Region<T> r;
  r.kind = kind;
  r.parts = std::move(parts);
  return r;
}
}  // namespace vrep_detail
template <class T>
Region<T> region_and(std::vector<Region<T>> parts) {
  return vrep_detail::region_of(Region<T>::all_of, std::move(parts));
}
template <class T>
Region<T> region_or(std::vector<Region<T>> parts) {
  return vrep_detail::region_of(Region<T>::any_of, std::move(parts));
}
template <class T>
Region<T> region_not(Region<T> x) {
  if (x.kind == Region<T>::complement) return std::move(x.parts.front());
  Region<T> r;
  r.kind = Region<T>::complement;
  r.parts.push_back(std::move(x));
  return r;
}

template <class T>
Region<T> region_cases(std::vector<std::pair<Region<T>, Region<T>>> cases) {
  Region<T> r;
  r.kind = Region<T>::cases;
  for (auto& [piece, formula] : cases) {
    r.parts.push_back(std::move(piece));
    r.parts.push_back(std::move(formula));
  }
  return r;
}

namespace vrep_detail {

template <class T>
Poly3<T> poly_add(Poly3<T> a, const Poly3<T>& b, const T& s = T(1)) {
  for (const auto& [e, c] : b.terms) {
    T& x = a.terms[e];
    x += s * c;
  }
  for (auto it = a.terms.begin(); it != a.terms.end();)
    it = it->second == T(0) ? a.terms.erase(it) : std::next(it);
  return a;
}
template <class T>
Poly3<T> poly_mul(const Poly3<T>& a, const Poly3<T>& b) {
  Poly3<T> r;
  for (const auto& [e, c] : a.terms)
    for (const auto& [f, d] : b.terms) r.terms[{e[0] + f[0], e[1] + f[1], e[2] + f[2]}] += c * d;
  for (auto it = r.terms.begin(); it != r.terms.end();)
    it = it->second == T(0) ? r.terms.erase(it) : std::next(it);
  return r;
}
/// c0 + c1 x + c2 y + c3 z.
template <class T>
Poly3<T> poly_linear(const T& c0, const T& c1, const T& c2, const T& c3) {
  Poly3<T> p;
  if (c0 != T(0)) p.terms[{0, 0, 0}] = c0;
  if (c1 != T(0)) p.terms[{1, 0, 0}] = c1;
  if (c2 != T(0)) p.terms[{0, 1, 0}] = c2;
  if (c3 != T(0)) p.terms[{0, 0, 1}] = c3;
  return p;
}
template <class T>
Poly3<T> poly_pow(const Poly3<T>& p, int k) {
  Poly3<T> r = poly_linear(T(1), T(0), T(0), T(0));
  for (int i = 0; i < k; ++i) r = poly_mul(r, p);
  return r;
}

/// The leaves of a region in depth-first order.
template <class T>
void collect_leaves(const Region<T>& R, std::vector<const Poly3<T>*>& out) {
  if (R.kind == Region<T>::leaf) {
    if (R.alias < 0) out.push_back(&R.g);
    return;
  }
  for (const auto& p : R.parts) collect_leaves(p, out);
}

/// Kleene's three-valued combination of the leaves' truths (consumed in collect_leaves' order).
template <class T>
Truth combine(const Region<T>& R, const std::vector<Truth>& leaf, std::size_t& k) {
  switch (R.kind) {
    case Region<T>::leaf: {
      if (R.alias < 0) return leaf[k++];
      const Truth t = leaf[static_cast<std::size_t>(R.alias)];
      return !R.flip ? t : t == Truth::in ? Truth::out : t == Truth::out ? Truth::in : Truth::mixed;
    }
    case Region<T>::complement: {
      const Truth t = combine(R.parts.front(), leaf, k);
      return t == Truth::in ? Truth::out : t == Truth::out ? Truth::in : Truth::mixed;
    }
    case Region<T>::all_of: {
      Truth t = Truth::in;
      for (const auto& p : R.parts) t = std::min(t, combine(p, leaf, k));
      return t;
    }
    case Region<T>::any_of: {
      Truth t = Truth::out;
      for (const auto& p : R.parts) t = std::max(t, combine(p, leaf, k));
      return t;
    }
    case Region<T>::cases: {
      // In: every case has its piece out or its formula in; out: its piece out or its formula out.
      bool in = true, out = true, some_piece = false, some_in = false;
      const bool planted = vrep_testing::is_planted(vrep_testing::Plant::cases_ignore_pieces);
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        const Truth c = combine(R.parts[i], leaf, k), f = combine(R.parts[i + 1], leaf, k);
        some_in = some_in || f == Truth::in;
        if (planted) continue;
        if (c == Truth::out) continue;
        some_piece = true;
        in = in && f == Truth::in;
        out = out && f == Truth::out;
      }
      if (planted) return some_in ? Truth::in : Truth::mixed;
      // No piece at all (a sign pattern the pieces' cover rules out, which callers that force
      // leaves may ask about): the union reading, out.
      if (!some_piece) return Truth::out;
      return in ? Truth::in : out ? Truth::out : Truth::mixed;
    }
  }
  return Truth::mixed;
}

/// Which leaves can still change the formula's truth, given their truths on a box (`lt`, collect
/// order; mixed: open): not a leaf under a part the others decide (a false part of an all_of, a
/// true part of an any_of, the formula of a case whose piece is out). Marks the open leaves that
/// can in `marks`; returns the part's value (1 true, 0 false) or -1 (open). A leaf that is not live
/// may keep any truth Kleene's logic allows it (its last one): the formula's truth does not change.
template <class T>
int mark_live(const Region<T>& R, const std::vector<Truth>& lt, std::size_t& k, std::vector<std::size_t>& marks) {
  auto value = [](Truth t) { return t == Truth::in ? 1 : t == Truth::out ? 0 : -1; };
  switch (R.kind) {
    case Region<T>::leaf: {
      const std::size_t at = R.alias < 0 ? k++ : static_cast<std::size_t>(R.alias);
      const int v = value(lt[at]);
      if (v >= 0) return R.flip ? 1 - v : v;
      marks.push_back(at);
      return -1;
    }
    case Region<T>::complement: {
      const int v = mark_live(R.parts.front(), lt, k, marks);
      return v < 0 ? v : 1 - v;
    }
    case Region<T>::all_of:
    case Region<T>::any_of: {
      const int absorbing = R.kind == Region<T>::all_of ? 0 : 1;
      const std::size_t first = marks.size();
      bool open = false, absorbed = false;
      for (const auto& p : R.parts) {
        const int v = mark_live(p, lt, k, marks);  // (every part: k must pass all leaves)
        if (v == absorbing) absorbed = true;
        else if (v < 0) open = true;
      }
      if (absorbed || !open) {
        marks.resize(first);
        return absorbed ? absorbing : 1 - absorbing;
      }
      return -1;
    }
    case Region<T>::cases: {
      const std::size_t first = marks.size();
      int common = -2;  // the formulas' common value over the cases whose piece is not out (-1: differ or open)
      bool any = false;
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        const std::size_t before = marks.size();
        const int c = mark_live(R.parts[i], lt, k, marks);
        const int f = mark_live(R.parts[i + 1], lt, k, marks);
        if (c == 0) {
          marks.resize(before);
          continue;
        }
        any = true;
        common = common == -2 ? f : common == f ? f : -1;
      }
      if (!any || common >= 0) {
        marks.resize(first);
        return any ? common : 0;
      }
      return -1;
    }
  }
  return -1;
}

/// The leaves live on a box (mark_live over the whole formula); true when the formula is open.
template <class T>
bool live_leaves(const Region<T>& R, const std::vector<Truth>& lt, std::vector<char>& live) {
  live.assign(lt.size(), 0);
  std::vector<std::size_t> marks;
  std::size_t k = 0;
  const int v = mark_live(R, lt, k, marks);
  for (std::size_t at : marks) live[at] = 1;
  return v < 0;
}

/// Whether the formula, the leaves outside `which` fixed at `fixed`, is decided for every sign
/// pattern of the leaves in `which` and depends on each of them (they meet at a corner or along
/// an edge of the cell's boundary there, rather than one passing the other by).
template <class T>
bool depends_on_each(const Region<T>& R, std::vector<Truth> fixed, const std::vector<std::size_t>& which) {
  const std::size_t m = which.size();
  std::vector<Truth> value(std::size_t(1) << m);
  for (std::size_t pattern = 0; pattern < value.size(); ++pattern) {
    for (std::size_t q = 0; q < m; ++q) fixed[which[q]] = (pattern >> q) & 1 ? Truth::in : Truth::out;
    std::size_t k = 0;
    value[pattern] = combine(R, fixed, k);
    if (value[pattern] == Truth::mixed) return false;
  }
  for (std::size_t q = 0; q < m; ++q) {
    bool depends = false;
    for (std::size_t pattern = 0; pattern < value.size(); ++pattern) depends = depends || value[pattern] != value[pattern ^ (std::size_t(1) << q)];
    if (!depends) return false;
  }
  return true;
}

template <class T>
Truth value_truth(const T& v, const T& eps) {
  return eps < v ? Truth::in : v < -eps ? Truth::out : Truth::mixed;
}

/// The truth of G >= 0 on a box from its Bernstein coefficients (within eps in float).
template <class T>
Truth coefficient_truth(const Bernstein<T>& G, const T& eps) {
  bool nonneg = true, nonpos = true;
  for (const auto& x : G.c) {
    nonneg = nonneg && !(x < -eps);
    nonpos = nonpos && !(eps < x);
  }
  if (nonpos) return Truth::out;  // also when G = 0 within eps: no interior there
  return nonneg ? Truth::in : Truth::mixed;
}

/// The coefficients of the region's leaves that the subdivision boxes alive carry, against the
/// limit (counted as they are made: a box carries only the leaves that can still change its truth).
struct CarriedCoefficients {
  const Limits& limits;
  std::size_t n = 0;
  template <class Leaves>
  static std::size_t of(const Leaves& G) {
    std::size_t k = 0;
    for (const auto& g : G) k += g.c.size();
    return k;
  }
  void add(std::size_t k, const std::string& who = "the boxes") {
    n += k;
    if (n > limits.max_control_points)
      throw SizeLimitError("region composed on the subdivision boxes",
                           who + " would carry " + std::to_string(n) + " coefficients of the region's leaves, above the limit of " +
                               std::to_string(limits.max_control_points),
                           "lower --boxes, or raise the limit with --max-control-points");
  }
  void remove(std::size_t k) { n -= k; }
};

/// Whether every Bernstein coefficient is > eps or every one < -eps (then every value is too).
template <class T>
bool strictly_signed(const Bernstein<T>& G, const T& eps) {
  bool pos = true, neg = true;
  for (const auto& x : G.c) {
    pos = pos && eps < x;
    neg = neg && x < -eps;
  }
  return !G.c.empty() && (pos || neg);
}

/// Positive weights: then the sign of g o T is the sign of the composed numerator W^k g(X/W, ...).
template <class T>
void require_positive_weights(const BSpline<T>& V) {
  for (const auto& w : V.weights)
    if (!(T(0) < w))
      throw DomainError("trivariate.weights", "has a weight that is not positive: the sign of g o T is not the sign of its numerator", "give positive weights");
}

/// Clamped in every direction, so that the faces and edges of V's domain are layers of its net.
template <class T>
void require_clamped(const BSpline<T>& V) {
  for (int d = 0; d < V.dim(); ++d)
    if (!is_clamped(V.knots[d], V.degrees[d], V.count(d)))
      throw ValidationError("trivariate.knots[" + std::to_string(d) + "]", "is not clamped: its faces and edges are not layers of the net",
                            "clamp the trivariate first");
}

template <class T>
bool all_zero(const Bernstein<T>& G) {
  return std::all_of(G.c.begin(), G.c.end(), [](const T& x) { return x == T(0); });
}

/// Limits before the work: each leaf composed with V has prod (k p_d + 1) coefficients per Bezier
/// piece; all leaves together are bounded like one spline's control points. Returns that count.
template <class T>
std::size_t composed_leaves_size(const BSpline<T>& V, const std::vector<const Poly3<T>*>& leaves, const Limits& limits) {
  std::size_t per_piece = 0;
  for (const auto* g : leaves) {
    if (g->degree() > 8) throw SizeLimitError("region", "has a leaf of degree " + std::to_string(g->degree()) + " (at most 8)", "give polynomials of degree <= 8");
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d) {
      limits.check_degree(static_cast<long>(g->degree()) * V.degrees[d], "region composed with the trivariate");
      n = checked_product(n, static_cast<std::size_t>(g->degree() * V.degrees[d] + 1), limits, "region composed with the trivariate");
    }
    per_piece += n;
  }
  limits.check_count(per_piece, "region composed with the trivariate");
  return per_piece;
}

}  // namespace vrep_detail

}  // namespace splinex
