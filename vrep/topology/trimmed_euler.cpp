// The Euler characteristic of a trimmed cell (vrep/trimmed/trimmed.hpp: trimmed_euler), instantiated for
// Rational and double.
//
// The method: the compactly supported Euler characteristic chi_c is additive over a partition into
// cells (open boxes, their open faces, edges, vertices), so chi(S) = sum over the open cells C of
// a box subdivision of chi_c(S cap C). On one open cell C of dimension d:
//   - the formula decided on the closed cell (every relevant leaf's Bernstein coefficients of one
//     sign): chi_c = (-1)^d if it holds, 0 if not;
//   - every undecided leaf monotone along one free direction t of C, with the formula monotone
//     the same way (closed "up": the fibre over each point y of the open face is empty, [t0, b) or
//     the whole (a, b)): chi_c of the fibre is 0, 0 or -1, and it is whole exactly where the
//     formula holds at t = a, so chi_c(S cap C) = -chi_c(S cap C_a), C_a the open face at t = a;
//     "down" is the mirror (C_b). Strictly monotone on every fibre: the derivative's Bernstein
//     coefficients all >= 0 with one > 0 (all Bernstein basis functions are positive inside);
//     a leaf independent of t (derivative 0) is both up and down;
//   - otherwise C is halved: two open halves and the open face between them.
// The interior's chi_c uses strict atoms on the open domain: fibres empty or (t0, b) (chi_c -1),
// nonempty exactly where the formula holds at the other end, so the faces swap. For a compact
// 3-manifold with boundary M, chi_c(int M) = chi(M) - chi(bd M) = -chi(M): the duality check.
//
// In V's image, the open cells of the domain's boundary that V identifies (equal faces, equal
// edges, one point for equal corners) count once, and collapsed faces and edges not at all (their
// image lies on their edges' or corners'); V is assumed injective otherwise.
#include <algorithm>
#include <array>
#include <functional>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_euler.hpp"

namespace splinex {

namespace {

using namespace vrep_detail;

/// The formula in negation normal form: atoms "leaf >= 0" (sign +1) or "leaf <= 0" (sign -1), read
/// non-strictly (closure) or strictly (interior).
struct Nnf {
  // by_reading: parts[0] for the closed reading, parts[1] for the strict one (a `cases` region).
  enum Kind { atom, all_of, any_of, by_reading } kind = atom;
  int leaf = 0, sign = 1;
  std::vector<Nnf> parts;
};

template <class T>
Nnf to_nnf(const Region<T>& R, bool negate, int& next_leaf) {
  Nnf n;
  switch (R.kind) {
    case Region<T>::leaf:
      n.leaf = R.alias < 0 ? next_leaf++ : R.alias;
      n.sign = (negate != R.flip) ? -1 : 1;
      return n;
    case Region<T>::complement: return to_nnf(R.parts.front(), !negate, next_leaf);
    case Region<T>::all_of:
    case Region<T>::any_of:
      n.kind = (R.kind == Region<T>::all_of) != negate ? Nnf::all_of : Nnf::any_of;
      for (const auto& p : R.parts) n.parts.push_back(to_nnf(p, negate, next_leaf));
      return n;
    case Region<T>::cases: {
      // The pieces covering space: the closed set is the union of piece and formula per case (its
      // complement's, of piece and not formula); the open set the intersection over the cases of
      // (outside the piece or inside the formula), which keeps the pieces' common boundaries
      // where both formulas hold strictly (the union's strict reading would drop them).
      // Each case read twice over the same leaves: piece and formula (closed), not piece or formula (open).
      Nnf closed, open;
      closed.kind = Nnf::any_of;
      open.kind = Nnf::all_of;
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        const int first = next_leaf;
        Nnf both, either;
        both.kind = Nnf::all_of;
        both.parts.push_back(to_nnf(R.parts[i], false, next_leaf));
        both.parts.push_back(to_nnf(R.parts[i + 1], negate, next_leaf));
        next_leaf = first;  // the same leaves again
        either.kind = Nnf::any_of;
        either.parts.push_back(to_nnf(R.parts[i], true, next_leaf));
        either.parts.push_back(to_nnf(R.parts[i + 1], negate, next_leaf));
        closed.parts.push_back(std::move(both));
        open.parts.push_back(std::move(either));
      }
      n.kind = Nnf::by_reading;
      n.parts.push_back(std::move(closed));
      n.parts.push_back(std::move(open));
      return n;
    }
  }
  return n;
}

struct Undecided {
  std::string where;
};

/// The signs of a leaf's Bernstein coefficients on a closed cell.
struct Signs {
  bool nonneg = true, nonpos = true, pos = true, neg = true;
};

template <class T>
Signs signs_of(const Bernstein<T>& G) {
  Signs s;
  for (const auto& x : G.c) {
    const bool p = T(0) < x, n = x < T(0);
    s.nonneg = s.nonneg && !n;
    s.nonpos = s.nonpos && !p;
    s.pos = s.pos && p;
    s.neg = s.neg && n;
  }
  return s;
}

/// An atom's truth on the closed cell: leaf >= 0 / <= 0 (closed) or > 0 / < 0 (strict).
Truth atom_truth(const Signs& s, int sign, bool strict) {
  const bool ge = sign > 0;
  if (strict) {
    if (ge ? s.pos : s.neg) return Truth::in;
    if (ge ? s.nonpos : s.nonneg) return Truth::out;
  } else {
    if (ge ? s.nonneg : s.nonpos) return Truth::in;
    if (ge ? s.neg : s.pos) return Truth::out;
  }
  return Truth::mixed;
}

Truth eval(const Nnf& n, const std::vector<Signs>& s, bool strict) {
  switch (n.kind) {
    case Nnf::by_reading: return eval(n.parts[strict ? 1 : 0], s, strict);
    case Nnf::atom: return atom_truth(s[static_cast<std::size_t>(n.leaf)], n.sign, strict);
    case Nnf::all_of: {
      Truth t = Truth::in;
      for (const auto& p : n.parts) t = std::min(t, eval(p, s, strict));
      return t;
    }
    case Nnf::any_of: {
      Truth t = Truth::out;
      for (const auto& p : n.parts) t = std::max(t, eval(p, s, strict));
      return t;
    }
  }
  return Truth::mixed;
}

/// The leaves of the atoms undecided on the cell.
void undecided_leaves(const Nnf& n, const std::vector<Signs>& s, bool strict, std::vector<char>& out) {
  if (n.kind == Nnf::by_reading) return undecided_leaves(n.parts[strict ? 1 : 0], s, strict, out);
  if (n.kind != Nnf::atom) {
    for (const auto& p : n.parts) undecided_leaves(p, s, strict, out);
    return;
  }
  if (atom_truth(s[static_cast<std::size_t>(n.leaf)], n.sign, strict) == Truth::mixed) out[static_cast<std::size_t>(n.leaf)] = 1;
}

/// Whether every undecided atom is closed upwards (+1) or downwards (-1) along a direction in
/// which its leaf is increasing (mono +1), decreasing (-1) or constant (0; both senses). False
/// when two atoms disagree or a leaf is not monotone (2).
bool sense_of(const Nnf& n, const std::vector<Signs>& s, bool strict, const std::vector<int>& mono, int& sense) {
  if (n.kind == Nnf::by_reading) return sense_of(n.parts[strict ? 1 : 0], s, strict, mono, sense);
  if (n.kind != Nnf::atom) {
    for (const auto& p : n.parts)
      if (!sense_of(p, s, strict, mono, sense)) return false;
    return true;
  }
  if (atom_truth(s[static_cast<std::size_t>(n.leaf)], n.sign, strict) != Truth::mixed) return true;
  const int m = mono[static_cast<std::size_t>(n.leaf)];
  if (m == 2) return false;
  if (m == 0) return true;
  const int x = m * n.sign;
  if (sense != 0 && sense != x) return false;
  sense = x;
  return true;
}

/// +1: all coefficients >= 0 and one > 0 (strictly increasing on every line of the open cell); -1
/// the mirror; 0: all zero; 2: otherwise.
template <class T>
int monotone(const Bernstein<T>& D) {
  const Signs s = signs_of(D);
  if (s.nonneg && s.nonpos) return 0;
  return s.nonneg ? 1 : s.nonpos ? -1 : 2;
}

template <class T>
double approx(const T& x) {
  if constexpr (std::is_same_v<T, double>) return x;
  else return to_double(x);
}

/// The sign of a leaf (G on a piece) just inside the domain next to a stratum of the piece's
/// boundary on which it vanishes: per inward direction of the stratum, the derivative either
/// vanishes on the whole piece (the leaf does not depend on it) or has one strict sign on the
/// stratum (every Bernstein coefficient); all those signs agree and there is at least one. Then
/// G(p + sum a_i n_i) = sum a_i dG_i(p) + O(|a|^2) has that sign for small a_i >= 0, not all 0.
/// 0 when the rule does not apply.
template <class T>
int inward_sign(const Bernstein<T>& G, const std::array<int, 3>& state, const std::vector<std::pair<int, int>>& boundary) {
  int sign = 0;
  for (const auto& [d, side] : boundary) {
    const Bernstein<T> D = bern_derivative(G, d);
    if (all_zero(D)) continue;
    Bernstein<T> on = D;
    for (int e = 2; e >= 0; --e)
      if (state[e] != 0) on = bern_face(on, e, state[e] == 2 ? 1 : 0);
    const Signs s = signs_of(on);
    const int here = s.pos ? 1 : s.neg ? -1 : 0;
    if (here == 0) return 0;
    const int inward = side == 0 ? here : -here;
    if (sign != 0 && sign != inward) return 0;
    sign = inward;
  }
  return sign;
}

template <class T>
class EulerRun {
 public:
  EulerRun(const Nnf& f, std::size_t leaves, std::size_t max_cells, int max_level, T split)
      : f_(f), leaves_(leaves), max_cells_(max_cells), max_level_(max_level), split_(std::move(split)) {}

  /// chi_c of the formula's set on an open cell: G[l] the leaves on it (Bernstein over [0, 1]^d), dirs
  /// the V directions of its free directions in order, lo/hi its parameter box in V. Depth first on
  /// the engine (bernstein/subdivide.hpp), in the order of the recursion chi(A) + chi(B) + chi(M) it
  /// is: a cell decided in counts (-1)^d times its sign, one decided out 0; a cell with a monotone
  /// direction is replaced by its face there with the sign turned (chi_c(cell) = -chi_c(face)); any
  /// other is halved across the direction halved least so far, into two open halves and the open
  /// middle face between them. The budget of max_cells counts every cell of the run (all calls).
  long chi(std::vector<Bernstein<T>> G, std::vector<int> dirs, std::array<T, 3> lo, std::array<T, 3> hi, bool strict) {
    struct Cell {
      std::vector<Bernstein<T>> G;
      std::vector<int> dirs;
      std::array<T, 3> lo, hi;
      std::array<int, 3> level{};
      long sign = 1;
      int face = -1, side = 0;  // examine's choice: the monotone direction's face, or -1: halve
    };
    long sum = 0;
    std::string why;
    auto examine = [&](Cell& c, int) {
      const int d = static_cast<int>(c.dirs.size());
      std::vector<Signs> s(leaves_);
      for (std::size_t l = 0; l < leaves_; ++l) s[l] = signs_of(c.G[l]);
      const Truth t = eval(f_, s, strict);
      if (t == Truth::in) sum += c.sign * (d % 2 ? -1 : 1);
      if (t != Truth::mixed) return Examined::settled;
      std::vector<char> open(leaves_, 0);
      undecided_leaves(f_, s, strict, open);
      // A direction along which every undecided leaf is monotone, the formula closed the same way.
      for (int j = 0; j < d; ++j) {
        std::vector<int> mono(leaves_, 0);
        bool ok = true;
        for (std::size_t l = 0; l < leaves_ && ok; ++l) {
          if (!open[l]) continue;
          mono[l] = monotone(bern_derivative(c.G[l], j));
          ok = mono[l] != 2;
        }
        int sense = 0;
        if (!ok || !sense_of(f_, s, strict, mono, sense)) continue;
        // Closed: up -> the face at the start; strict: up -> the face at the end.
        c.face = j;
        c.side = sense == 0 ? 0 : ((sense > 0) == strict ? 1 : 0);
        return Examined::split;
      }
      if (c.level[c.dirs[least_halved(c)]] >= max_level_) {
        why = "no monotone direction within " + std::to_string(max_level_) + " halvings" + at(c.lo, c.hi) +
              " (a singular or tangential point of the trimming surfaces)";
        return Examined::left;
      }
      return Examined::split;
    };
    auto split = [&](Cell&& c, int, auto&& emit) {
      if (c.face >= 0) {
        const int j = c.face, vd = c.dirs[static_cast<std::size_t>(j)];
        for (auto& g : c.G) g = bern_face(g, j, c.side);
        if (c.side) c.lo[vd] = c.hi[vd];
        else c.hi[vd] = c.lo[vd];
        c.dirs.erase(c.dirs.begin() + j);
        c.sign = vrep_testing::is_planted(vrep_testing::Plant::euler_monotone_sign) ? c.sign : -c.sign;  // (planted: tests only)
        c.face = -1;
        emit(std::move(c));
        return;
      }
      const int j = least_halved(c), vd = c.dirs[static_cast<std::size_t>(j)];
      Cell A{std::vector<Bernstein<T>>(leaves_), c.dirs, c.lo, c.hi, c.level, c.sign}, B = A, M = A;
      for (std::size_t l = 0; l < leaves_; ++l) {
        std::tie(A.G[l], B.G[l]) = bern_split(c.G[l], j, split_);
        M.G[l] = bern_face(A.G[l], j, 1);
      }
      const T mid = c.lo[vd] + split_ * (c.hi[vd] - c.lo[vd]);
      for (Cell* x : {&A, &B, &M}) ++x->level[vd];
      A.hi[vd] = B.lo[vd] = M.lo[vd] = M.hi[vd] = mid;
      M.dirs.erase(M.dirs.begin() + j);
      // Depth first takes the last child first: A, then B, then M.
      if (!vrep_testing::is_planted(vrep_testing::Plant::euler_drops_mid_face)) emit(std::move(M));  // (planted: tests only)
      emit(std::move(B));
      emit(std::move(A));
    };
    // The cell that would have been examined next when the budget ran out: the last one left.
    std::array<T, 3> next_lo{}, next_hi{};
    auto leave = [&](Cell&& c, Left) { next_lo = c.lo, next_hi = c.hi; };
    Budget budget;
    budget.max_boxes = max_cells_ - cells_;
    std::vector<Cell> root(1);
    root[0].G = std::move(G), root[0].dirs = std::move(dirs), root[0].lo = lo, root[0].hi = hi;
    const Subdivision run = subdivide(std::move(root), Walk{Order::depth_first, 3, true}, budget, examine, split, leave);
    cells_ += run.examined;
    if (run.stop == Subdivision::Stop::boxes) {
      ++cells_;  // the cell found over the budget
      throw Undecided{"the budget of " + std::to_string(max_cells_) + " cells is spent" + at(next_lo, next_hi)};
    }
    if (run.stop == Subdivision::Stop::left) throw Undecided{why};
    return sum;
  }

  std::size_t cells() const { return cells_; }

 private:
  /// The free direction halved least so far (the first of equals).
  template <class Cell>
  static int least_halved(const Cell& c) {
    int j = 0;
    for (int k = 1; k < static_cast<int>(c.dirs.size()); ++k)
      if (c.level[c.dirs[k]] < c.level[c.dirs[j]]) j = k;
    return j;
  }

  static std::string at(const std::array<T, 3>& lo, const std::array<T, 3>& hi) {
    std::string s = " near (u, v, w) = (";
    for (int d = 0; d < 3; ++d) {
      if (d) s += ", ";
      s += std::to_string(approx((lo[d] + hi[d]) / T(2)));
    }
    s += ")";
    return s;
  }

  const Nnf& f_;
  std::size_t leaves_, max_cells_;
  int max_level_;
  T split_;
  std::size_t cells_ = 0;
};

/// V's identifications (geometry): kept faces, edges and corners of the domain.
struct Kept {
  std::array<std::array<bool, 2>, 3> face{};
  std::array<std::array<std::array<bool, 2>, 2>, 3> edge{};  // [along][side of the lower other][side of the upper other]
  std::array<bool, 8> corner{};
};

template <class T>
Kept kept_cells(const BSpline<T>& V, const Limits& limits, TrimmedEuler<T>& out) {
  Kept kept;
  std::vector<BSpline<T>> kept_faces;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      const BSpline<T> S = face(V, d, s);
      bool keep = !collapsed(S, 0) && !collapsed(S, 1);
      for (const auto& K : kept_faces)
        if (keep && corner_set(K) == corner_set(S) && same_surface(K, S, T(0), limits)) keep = false;
      if (keep) kept_faces.push_back(S);
      kept.face[d][s] = keep;
      if (!keep) ++out.identified_faces;
    }
  std::vector<BSpline<T>> kept_edges;
  for (int along = 0; along < 3; ++along)
    for (int s1 = 0; s1 < 2; ++s1)
      for (int s2 = 0; s2 < 2; ++s2) {
        std::array<int, 3> sides{};
        const int a = along == 0 ? 1 : 0, b = along == 2 ? 1 : 2;
        sides[a] = s1;
        sides[b] = s2;
        const BSpline<T> C = edge_curve(V, along, sides);
        bool keep = !curve_collapsed(C);
        for (const auto& K : kept_edges)
          if (keep && same_curve(K, C, T(0), true, limits)) keep = false;
        if (keep) kept_edges.push_back(C);
        kept.edge[along][s1][s2] = keep;
        if (!keep) ++out.identified_edges;
      }
  std::vector<std::vector<T>> kept_corners;
  for (int c = 0; c < 8; ++c) {
    std::vector<T> x(3);
    for (int d = 0; d < 3; ++d) x[d] = (c >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d);
    std::vector<T> p = evaluate(V, x);
    p.resize(3);
    kept.corner[c] = std::find(kept_corners.begin(), kept_corners.end(), p) == kept_corners.end();
    if (kept.corner[c]) kept_corners.push_back(p);
    else ++out.identified_corners;
  }
  return kept;
}

/// A stratum of the piece grid with its leaves, box, place on the domain's boundary.
template <class T>
struct GridStratum {
  std::vector<Bernstein<T>> H;
  std::vector<int> dirs;
  std::array<T, 3> lo, hi;
  bool inside = false;  // in the open domain (the interior's chi_c counts it)
  bool kept = true;     // counted in the image
};

/// The strata of the piece grid: per direction, the open segment (state 0), its start (1) or, for
/// the last segment, its end (2); each with its leaves, box, place on the domain's boundary.
template <class T>
std::vector<GridStratum<T>> grid_strata(const BezierForm<T>& F, const std::vector<std::vector<Bernstein<T>>>& G, const Kept& kept,
                                        TrimmedEuler<T>& out) {
  std::array<std::size_t, 3> n{};
  for (int d = 0; d < 3; ++d) n[d] = F.breaks[d].size() - 1;
  std::vector<GridStratum<T>> strata;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const std::array<std::size_t, 3> idx{k % n[0], (k / n[0]) % n[1], k / (n[0] * n[1])};
    for (int st = 0; st < 27; ++st) {
      const std::array<int, 3> state{st % 3, (st / 3) % 3, st / 9};
      bool valid = true;
      for (int d = 0; d < 3; ++d) valid = valid && (state[d] != 2 || idx[d] + 1 == n[d]);
      if (!valid) continue;
      GridStratum<T> z;
      z.H = G[k];
      std::vector<std::pair<int, int>> boundary;  // (direction, side) of the domain it lies on
      for (int d = 0; d < 3; ++d) {
        z.lo[d] = F.breaks[d][idx[d]];
        z.hi[d] = F.breaks[d][idx[d] + 1];
        if (state[d] == 0) z.dirs.push_back(d);
        else {
          (state[d] == 1 ? z.hi : z.lo)[d] = state[d] == 1 ? z.lo[d] : z.hi[d];
          if (state[d] == 1 && idx[d] == 0) boundary.push_back({d, 0});
          if (state[d] == 2) boundary.push_back({d, 1});
        }
      }
      // Fix the directions from the last: direction d is then still at index d of every leaf.
      for (int d = 2; d >= 0; --d)
        if (state[d] != 0)
          for (auto& h : z.H) h = bern_face(h, d, state[d] == 2 ? 1 : 0);
      // A leaf that vanishes on the whole stratum (a face of the cell on a trimming surface:
      // coplanar contact) is read by its sign just inside the domain, so the closed reading is
      // the closure of the cell's interior there, not a thin sheet. At an inner knot (fixed
      // directions inside the domain) the stratum is shared by the pieces on both sides: the
      // leaf must vanish on each one's part of the domain's face (or edge) there, and read the
      // same sign inside each.
      if (!boundary.empty()) {
        std::vector<int> inner;
        for (int d = 0; d < 3; ++d)
          if (state[d] != 0 && std::find_if(boundary.begin(), boundary.end(), [&](const auto& b) { return b.first == d; }) == boundary.end())
            inner.push_back(d);
        for (std::size_t l = 0; l < z.H.size(); ++l) {
          if (!all_zero(z.H[l])) continue;
          int near = 0;
          bool ok = true;
          for (std::size_t mask = 0; mask < (std::size_t(1) << inner.size()) && ok; ++mask) {
            auto at = idx;
            auto sp = state;
            for (std::size_t q = 0; q < inner.size(); ++q)
              if ((mask >> q) & 1) {  // the piece below the knot: the stratum is at its end
                --at[inner[q]];
                sp[inner[q]] = 2;
              }
            const auto& GP = G[at[0] + n[0] * (at[1] + n[1] * at[2])][l];
            Bernstein<T> carrier = GP;  // the leaf on this piece's part of the boundary stratum's carrier
            for (int d = 2; d >= 0; --d)
              for (const auto& [bd, bs] : boundary)
                if (bd == d) carrier = bern_face(carrier, d, bs);
            const int here = all_zero(carrier) ? inward_sign(GP, sp, boundary) : 0;
            ok = here != 0 && (near == 0 || near == here);
            near = here;
          }
          if (!ok) {
            ++out.unresolved_contacts;
            continue;
          }
          ++out.resolved_contacts;
          Bernstein<T> c;
          c.deg.assign(std::max<std::size_t>(z.dirs.size(), 1), 0);
          c.c = {T(near)};
          z.H[l] = std::move(c);
        }
      }
      z.inside = boundary.empty();
      if (boundary.size() == 1) z.kept = kept.face[boundary[0].first][boundary[0].second];
      else if (boundary.size() == 2) z.kept = kept.edge[3 - boundary[0].first - boundary[1].first][boundary[0].second][boundary[1].second];
      else if (boundary.size() == 3) z.kept = kept.corner[boundary[0].second | (boundary[1].second << 1) | (boundary[2].second << 2)];
      strata.push_back(std::move(z));
    }
  }
  return strata;
}

/// chi_c summed over the strata; a split fraction that leaves a cell undecided is retried.
template <class T>
void sum_over_strata(const Nnf& f, std::size_t leaves, const std::vector<GridStratum<T>>& strata, const EulerOptions& options,
                     TrimmedEuler<T>& out) {
  const std::vector<T> fractions{T(1) / T(2), T(7) / T(16), T(13) / T(32)};
  for (const T& split : fractions) {
    EulerRun<T> run(f, leaves, options.max_cells, options.max_level, split);
    try {
      long param = 0, image = 0, interior = 0;
      for (const auto& z : strata) {
        const long c = run.chi(z.H, z.dirs, z.lo, z.hi, false);
        param += c;
        if (z.kept) image += c;
        if (z.inside) interior += run.chi(z.H, z.dirs, z.lo, z.hi, true);
      }
      out.decided = true;
      out.chi = param;
      out.image_chi = image;
      out.interior_chi_c = interior;
      out.duality = interior == -param;
      out.split = split;
      out.cells += run.cells();
      out.undecided_reason.clear();
      return;
    } catch (const Undecided& u) {
      out.cells += run.cells();
      out.undecided_reason = u.where;
    }
  }
}

}  // namespace

template <class T>
TrimmedEuler<T> trimmed_euler(const BSpline<T>& V, const Region<T>& trim, const EulerOptions& options, const Limits& limits) {
  require_jacobian_input(V, limits);
  require_clamped(V);
  if (options.max_cells < 1) throw ValidationError("cells", "must be at least 1", "give a positive cell budget");
  if (options.max_level < 1 || options.max_level > 60) throw ValidationError("level", "must be in 1..60", "give a halving depth in 1..60");
  require_positive_weights(V);
  require_continuous(V);
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(trim, leaves);
  // Limits before the work, as the classification checks them.
  const std::size_t per_piece = composed_leaves_size(V, leaves, limits);
  int next = 0;
  const Nnf f = to_nnf(trim, false, next);
  const BezierForm<T> F = bezier_form(V, limits);
  checked_product(per_piece, F.size(), limits, "region composed with the trivariate's pieces");
  std::vector<std::vector<Bernstein<T>>> G(F.size());
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    for (const auto* g : leaves) G[k].push_back(compose_leaf(*g, pc.spline));
  }

  // V's identifications (geometry): kept faces, edges and corners of the domain.
  TrimmedEuler<T> out;
  const Kept kept = kept_cells(V, limits, out);

  const std::vector<GridStratum<T>> strata = grid_strata(F, G, kept, out);

  // chi_c summed over the strata; a split fraction that leaves a cell undecided is retried.
  sum_over_strata(f, leaves.size(), strata, options, out);
  return out;
}

template <class T>
TrimmedEuler<T> region_euler(const Region<T>& R, const std::vector<T>& lo, const std::vector<T>& hi, const EulerOptions& options, const Limits& limits) {
  if (lo.size() != 3 || hi.size() != 3) throw ValidationError("box", "needs three lower and three upper bounds", "give lo and hi in R^3");
  for (int d = 0; d < 3; ++d)
    if (!(lo[d] < hi[d])) throw ValidationError("box", "has lo >= hi in direction " + std::to_string(d), "give lo < hi");
  return trimmed_euler(box_cells<T>(lo, hi).front(), R, options, limits);
}

template <class T>
TrimmedEuler<T> model_euler(const TrimmedModel<T>& M, const EulerOptions& options, const Limits& limits) {
  std::vector<T> lo(3), hi(3);
  bool first = true;
  for (const auto& c : M.cells) {
    if (c.trivariate >= M.trivariates.size())
      throw ValidationError("model.cells", "names trivariate " + std::to_string(c.trivariate) + " of " + std::to_string(M.trivariates.size()),
                            "give each cell the index of one of the model's trivariates");
    const auto b = control_bounds(M.trivariates[c.trivariate]);
    for (int d = 0; d < 3; ++d) {
      if (first || b[d] < lo[d]) lo[d] = b[d];
      if (first || hi[d] < b[d + 3]) hi[d] = b[d + 3];
    }
    first = false;
  }
  if (first) throw ValidationError("model", "has no cells", "give a model with cells");
  // A margin of a 1/16 of the largest side (at least 1) all round: the region then meets the
  // box's faces nowhere, as the model lies in its cells' control boxes.
  T side = T(1);
  for (int d = 0; d < 3; ++d)
    if (side < hi[d] - lo[d]) side = hi[d] - lo[d];
  for (int d = 0; d < 3; ++d) {
    lo[d] -= side / T(16);
    hi[d] += side / T(16);
  }
  return region_euler(M.region, lo, hi, options, limits);
}

template TrimmedEuler<Rational> region_euler(const Region<Rational>&, const std::vector<Rational>&, const std::vector<Rational>&, const EulerOptions&,
                                             const Limits&);
template TrimmedEuler<double> region_euler(const Region<double>&, const std::vector<double>&, const std::vector<double>&, const EulerOptions&, const Limits&);
template TrimmedEuler<Rational> model_euler(const TrimmedModel<Rational>&, const EulerOptions&, const Limits&);
template TrimmedEuler<double> model_euler(const TrimmedModel<double>&, const EulerOptions&, const Limits&);
template TrimmedEuler<Rational> trimmed_euler(const BSpline<Rational>&, const Region<Rational>&, const EulerOptions&, const Limits&);
template TrimmedEuler<double> trimmed_euler(const BSpline<double>&, const Region<double>&, const EulerOptions&, const Limits&);

}  // namespace splinex
