#include "hybrid/wachspress_check.hpp"

#include <CGAL/Barycentric_coordinates_2/Wachspress_coordinates_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <iterator>

namespace splinex {

std::vector<Rational> cgal_wachspress(const std::vector<std::array<Rational, 2>>& polygon, const std::array<Rational, 2>& x) {
  using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
  const auto to_q = [](const Rational& r) { return CGAL::Gmpq(r.str()); };
  std::vector<K::Point_2> poly;
  for (const auto& v : polygon) poly.emplace_back(to_q(v[0]), to_q(v[1]));
  std::vector<CGAL::Gmpq> w;
  CGAL::Barycentric_coordinates::wachspress_coordinates_2(poly, K::Point_2(to_q(x[0]), to_q(x[1])), std::back_inserter(w));
  std::vector<Rational> out;
  for (const auto& q : w) {
    Rational r;
    mpq_set(r.backend().data(), q.mpq());
    out.push_back(r);
  }
  return out;
}

}  // namespace splinex
