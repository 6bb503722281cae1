// The arithmetic concept of spline/arith.hpp, checked by the compiler: Strict has exactly the
// operations the concept allows (T(int), T(long), copies, + - * / and their compound forms, unary
// -, == and <) and nothing else, and the kernel, composition and the hybrid patch are instantiated
// for it below. A use of >, <=, >=, !=, abs, sqrt or a double in generic code no longer compiles.
// At run time Strict is an exact rational, so its results must equal Rational's exactly.
#include <catch2/catch.hpp>

#include "compose/instantiate.hpp"
#include "exact/rational.hpp"
#include "fixtures/random_spline.hpp"
#include "hybrid/instantiate.hpp"
#include "spline/instantiate.hpp"
#include "untrim/sweep.hpp"
#include "untrim/tile_integrals.hpp"

namespace splinex {

class Strict {
 public:
  Strict() = default;
  Strict(int x) : v_(x) {}   // NOLINT: the concept's T(int)
  Strict(long x) : v_(x) {}  // NOLINT: the concept's T(long)
  static Strict of(const Rational& x) {
    Strict s;
    s.v_ = x;
    return s;
  }
  const Rational& value() const { return v_; }

  Strict& operator+=(const Strict& o) { v_ += o.v_; return *this; }
  Strict& operator-=(const Strict& o) { v_ -= o.v_; return *this; }
  Strict& operator*=(const Strict& o) { v_ *= o.v_; return *this; }
  Strict& operator/=(const Strict& o) { v_ /= o.v_; return *this; }
  friend Strict operator+(Strict a, const Strict& b) { return a += b; }
  friend Strict operator-(Strict a, const Strict& b) { return a -= b; }
  friend Strict operator*(Strict a, const Strict& b) { return a *= b; }
  friend Strict operator/(Strict a, const Strict& b) { return a /= b; }
  friend Strict operator-(const Strict& a) { return of(Rational(-a.v_)); }
  friend bool operator==(const Strict& a, const Strict& b) { return a.v_ == b.v_; }
  friend bool operator<(const Strict& a, const Strict& b) { return a.v_ < b.v_; }
  // Outside the concept: generic code must write !(a == b), b < a, !(b < a).
  friend bool operator!=(const Strict&, const Strict&) = delete;
  friend bool operator>(const Strict&, const Strict&) = delete;
  friend bool operator<=(const Strict&, const Strict&) = delete;
  friend bool operator>=(const Strict&, const Strict&) = delete;

 private:
  Rational v_;
};

// The C++20 concept accepts Strict and every arithmetic of the project, and rejects a scalar that
// lacks one operation of the list (here <).
struct NoLess {
  NoLess() = default;
  NoLess(int) {}   // NOLINT
  NoLess(long) {}  // NOLINT
  friend NoLess operator+(NoLess, NoLess) { return {}; }
  friend NoLess operator-(NoLess, NoLess) { return {}; }
  friend NoLess operator*(NoLess, NoLess) { return {}; }
  friend NoLess operator/(NoLess, NoLess) { return {}; }
  friend NoLess operator-(NoLess) { return {}; }
  NoLess& operator+=(NoLess) { return *this; }
  NoLess& operator-=(NoLess) { return *this; }
  NoLess& operator*=(NoLess) { return *this; }
  NoLess& operator/=(NoLess) { return *this; }
  friend bool operator==(NoLess, NoLess) { return true; }
};
static_assert(Arithmetic<Strict>);
static_assert(Arithmetic<Rational>);
static_assert(Arithmetic<double>);
static_assert(!Arithmetic<NoLess>);
static_assert(!Arithmetic<int*>);

template <>
struct ArithTraits<Strict> {
  static constexpr bool exact = true;
  static std::string name() { return "strict"; }
  static int precision_bits() { return 0; }
  static Strict from_rational(const Rational& x) { return Strict::of(x); }
  static Rational to_rational(const Strict& x) { return x.value(); }
  static nlohmann::json to_json(const Strict& x) { return to_fraction_string(x.value()); }
  static std::string to_string(const Strict& x) { return to_fraction_string(x.value()); }
};

using T_Seg = Segment2<Strict>;
SPLINEX_INSTANTIATE_KERNEL(Strict)
SPLINEX_INSTANTIATE_COMPOSE(Strict)
SPLINEX_INSTANTIATE_HYBRID(Strict)
// The untrimming sweep and its tiles (header templates).
template std::vector<T_Seg> planar_subdivision(const std::vector<T_Seg>&);
template std::vector<Trapezoid<Strict>> vertical_decomposition(const std::vector<T_Seg>&);
template std::vector<Tile<Strict>> merge_trapezoids(const std::vector<Trapezoid<Strict>>&, const std::vector<int>&,
                                                    std::vector<Strict>);
template std::vector<Strict> elevate_ordinates(const std::vector<Strict>&, int);
template BSpline<Strict> tile_spline(const Tile<Strict>&);
template Strict tile_area(const Tile<Strict>&);
template std::vector<Point2<Strict>> tile_polygon(const Tile<Strict>&);
template std::vector<Strict> integrate_over_tile(const BSpline<Strict>&, const Tile<Strict>&, const Limits&);

}  // namespace splinex

using namespace splinex;

namespace {

BSpline<Strict> to_strict(const BSpline<Rational>& S) { return convert<Strict>(S, [](const Rational& x) { return Strict::of(x); }); }
BSpline<Rational> to_rational(const BSpline<Strict>& S) { return convert<Rational>(S, [](const Strict& x) { return x.value(); }); }

}  // namespace

TEST_CASE("the arithmetic concept: the kernel in Strict equals the kernel in Rational", "[concept]") {
  std::mt19937_64 rng(4242);
  for (int trial = 0; trial < 20; ++trial) {
    const auto c = structured_case(rng);
    const BSpline<Rational>& S = c.spline;
    const auto T = to_strict(S);
    const int d = static_cast<int>(rng() % S.dim());
    const Rational x = random_inside(S.domain_lo(d), S.domain_hi(d), rng);
    CHECK(same_net(to_rational(insert_knot(T, d, Strict::of(x), 1)), insert_knot(S, d, x, 1)));
    CHECK(same_net(to_rational(elevate_degree(T, d, 1, ElevationMethod::blossom)), elevate_degree(S, d, 1, ElevationMethod::blossom)));
    std::vector<Rational> at;
    for (int l = 0; l < S.dim(); ++l) at.push_back(random_inside(S.domain_lo(l), S.domain_hi(l), rng));
    std::vector<Strict> at_s;
    for (const auto& a : at) at_s.push_back(Strict::of(a));
    const auto vs = evaluate(T, at_s);
    const auto vr = evaluate(S, at);
    REQUIRE(vs.size() == vr.size());
    for (std::size_t k = 0; k < vr.size(); ++k) CHECK(vs[k].value() == vr[k]);
  }
}
