#include "compose/trimming_end_points.hpp"

namespace splinex {

std::vector<EdgeCrossing> trimming_edge_crossings(const TrimmedComposition<Rational>& C, std::size_t pi, int refine_bits) {
  const auto& P = C.patches.at(pi);
  const BSpline<Rational>& S = C.inner_pieces[P.inner_piece].spline;
  const int k = S.dim();
  std::vector<EdgeCrossing> out;
  for (int free = 0; free < k; ++free) {
    // Every edge in direction `free`: the other parameters at the lower or upper end of the box.
    const int others = k - 1;
    for (int mask = 0; mask < (1 << others); ++mask) {
      std::vector<Rational> fixed(k);
      std::vector<int> fixed_idx(k, 0);
      for (int l = 0, bit = 0; l < k; ++l) {
        if (l == free) continue;
        const bool up = (mask >> bit++) & 1;
        fixed[l] = up ? S.domain_hi(l) : S.domain_lo(l);
        fixed_idx[l] = up ? S.degrees[l] : 0;
      }
      // The edge's Bernstein coefficients: the control points along `free` at the fixed corner indices.
      std::vector<std::size_t> stride(k);
      std::size_t st = 1;
      for (int l = 0; l < k; ++l) { stride[l] = st; st *= S.count(l); }
      for (std::size_t ci = 0; ci < P.region.size(); ++ci) {
        const auto& cond = P.region[ci];
        for (bool upper : {false, true}) {
          if ((upper && !cond.check_hi) || (!upper && !cond.check_lo)) continue;
          const Rational bound = upper ? cond.hi : cond.lo;
          std::vector<Rational> bern;
          for (int i = 0; i <= S.degrees[free]; ++i) {
            std::size_t g = 0;
            for (int l = 0; l < k; ++l) g += (l == free ? i : fixed_idx[l]) * stride[l];
            const Rational w = S.is_rational() ? S.weights[g] : Rational(1);
            bern.push_back(S.points[g * S.q + cond.coord] * w - bound * w);  // X_c - bound * W
          }
          bool all_zero = true;
          for (const auto& x : bern) all_zero = all_zero && x == 0;
          if (all_zero) continue;  // the edge lies on the knot line: no isolated crossing
          const Rational lo = S.domain_lo(free), width = S.domain_hi(free) - lo;
          for (auto root : isolate_real_roots(bernstein_to_power(bern), Rational(0), Rational(1), refine_bits)) {
            root.lo = lo + width * root.lo;
            root.hi = lo + width * root.hi;
            out.push_back({static_cast<int>(ci), upper, free, fixed, root});
          }
        }
      }
    }
  }
  return out;
}

}  // namespace splinex
