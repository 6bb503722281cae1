// Whether a double run of freeform_cell decided every box as the exact run did (vrep/freeform/freeform.hpp).
#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "exact/rational.hpp"
#include "vrep/freeform/freeform.hpp"

namespace splinex {

bool same_boxes(const FreeformCell<Rational>& exact, const FreeformCell<double>& dbl) {
  if (exact.boxes.size() != dbl.boxes.size()) return false;
  // As sets: the runs may make the same boxes in another order (the split order follows keys that
  // rounding may reorder where the exact ones tie).
  using Key = std::tuple<std::array<Rational, 3>, std::array<Rational, 3>, int>;
  std::vector<Key> e, d;
  for (const auto& b : exact.boxes) e.emplace_back(b.lo, b.hi, static_cast<int>(b.truth));
  for (const auto& b : dbl.boxes) {
    Key k;
    for (std::size_t a = 0; a < 3; ++a) {
      std::get<0>(k)[a] = exact_from_double(b.lo[a]);
      std::get<1>(k)[a] = exact_from_double(b.hi[a]);
    }
    std::get<2>(k) = static_cast<int>(b.truth);
    d.push_back(std::move(k));
  }
  std::sort(e.begin(), e.end());
  std::sort(d.begin(), d.end());
  return e == d;
}

}  // namespace splinex
