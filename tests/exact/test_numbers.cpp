#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "base/errors.hpp"
#include "float/arith_spec.hpp"

using namespace splinex;

TEST_CASE("decimal, fraction and integer text is parsed exactly") {
  CHECK(parse_number("0.784", "x") == Rational(98, 125));
  CHECK(parse_number("1e-3", "x") == Rational(1, 1000));
  CHECK(parse_number("-2.5E+2", "x") == Rational(-250));
  CHECK(parse_number("22/7", "x") == Rational(22, 7));
  CHECK(parse_number("-3", "x") == Rational(-3));
  CHECK(parse_number("0784", "x") == Rational(784));  // not octal
  CHECK(parse_number("010/08", "x") == Rational(5, 4));
  CHECK(parse_number(" .5 ", "x") == Rational(1, 2));
  CHECK(parse_number("0.1", "x") != exact_from_double(0.1));
  CHECK(parse_number("123456789012345678901234567890.000000000000000000001", "x") ==
        Rational(Integer("123456789012345678901234567890000000000000000000001"), Integer("1000000000000000000000")));
}

TEST_CASE("malformed numbers throw ParseError naming the field") {
  for (const char* bad : {"", "nan", "NaN", "inf", "-Infinity", "1/0", "0x10", "1e", "--1", "1.2.3", "1/2/3", "e5", "1e999999", "abc"}) {
    INFO(bad);
    try {
      parse_number(bad, "knots[0][3]");
      FAIL("no exception");
    } catch (const ParseError& e) {
      CHECK(std::string(e.what()).find("knots[0][3]") == 0);
      CHECK(e.field() == "knots[0][3]");
    }
  }
}

TEST_CASE("every double converts to a rational exactly, and back") {
  CHECK(exact_from_double(0.1) == Rational(Integer("3602879701896397"), Integer("36028797018963968")));
  CHECK(exact_from_double(-0.0) == 0);
  CHECK(exact_from_double(std::ldexp(1.0, -1074)) == Rational(1) / Rational(Integer(1) << 1074));
  CHECK_THROWS_AS(exact_from_double(std::numeric_limits<double>::quiet_NaN()), ParseError);
  CHECK_THROWS_AS(exact_from_double(std::numeric_limits<double>::infinity()), ParseError);
  for (double d : {0.1, 1.0 / 3, 1e300, -7.25e-300, 12345.678}) CHECK(to_double(exact_from_double(d)) == d);
}

TEST_CASE("rational to double rounds to nearest (mpq_get_d would truncate)") {
  // 1/3 rounds up in the last place; truncation would give the value below.
  CHECK(to_double(Rational(1, 3)) == 1.0 / 3);
  // A value exactly halfway between two doubles rounds to even.
  const Rational one(1), ulp = Rational(1) / Rational(Integer(1) << 52);
  CHECK(to_double(one + ulp / 2) == 1.0);
  CHECK(to_double(one + ulp + ulp / 2) == 1.0 + 2 * std::ldexp(1.0, -52));
  CHECK(to_double(Rational(9, 10)) == 0.9);
}

TEST_CASE("MPFR values have exactly the requested precision and convert exactly") {
  Mpfr::Precision p(113);
  Mpfr a(Rational(1, 3));
  CHECK(a.bits() == 113);
  const Rational r = to_rational(a);
  // |r - 1/3| <= 2^-114 (half an ulp at 113 bits, exponent -1)
  const Rational err = abs(Rational(r - Rational(1, 3)));
  CHECK(err > 0);
  CHECK(err <= Rational(1) / Rational(Integer(1) << 115));
  CHECK(to_rational(Mpfr(Rational(3, 4))) == Rational(3, 4));
  // The decimal text reads back to the same value.
  CHECK(to_rational(Mpfr(parse_number(to_decimal_string(a), "x"))) == r);
  {
    Mpfr::Precision p24(24);
    CHECK(Mpfr(1).bits() == 24);
  }
  CHECK(Mpfr(1).bits() == 113);
  CHECK_THROWS_AS(Mpfr::Precision(23), UsageError);
}

TEST_CASE("arithmetic names", "[arith]") {
  CHECK(ArithSpec::parse("exact").is_exact());
  CHECK(ArithSpec::parse("double").kind == ArithSpec::Kind::dbl);
  CHECK(ArithSpec::parse("mpfr:24").bits == 24);
  CHECK(ArithSpec::parse("mpfr:4096").name() == "mpfr:4096");
  for (const char* bad : {"float", "mpfr", "mpfr:", "mpfr:23", "mpfr:abc", "mpfr:99999999", "Exact"})
    CHECK_THROWS_AS(ArithSpec::parse(bad), UsageError);
}

namespace {

/// The spec naming T (mpfr at 77 bits, so the precision scope is seen).
template <class T>
ArithSpec spec_of() {
  return ArithSpec::parse(std::is_same_v<T, Mpfr> ? std::string("mpfr:77") : std::string(ArithOf<T>::name));
}

/// with_arith<List> runs f in T for every T of the list: the tag's type, the row's name, MPFR's bits.
template <class... T>
void check_dispatch(Arithmetics<T...>) {
  using List = Arithmetics<T...>;
  auto one = [](auto want) {
    using W = typename decltype(want)::type;
    const std::string got = with_arith<List>(spec_of<W>(), "test", [](auto tag) {
      using G = typename decltype(tag)::type;
      static_assert((std::is_same_v<G, T> || ...), "f instantiated for an arithmetic outside the list");
      CHECK(std::is_same_v<G, W>);
      if constexpr (std::is_same_v<G, Mpfr>) return ArithTraits<G>::name();  // "mpfr:77": the scope's bits
      else return std::string(ArithOf<G>::name);
    });
    CHECK(got == spec_of<W>().name());
  };
  (one(ArithTag<T>{}), ...);
}

std::string refusal(const std::string& arith, auto list) {
  try {
    with_arith<decltype(list)>(ArithSpec::parse(arith), "vrep construct", [](auto) { return 0; });
  } catch (const UsageError& e) {
    CHECK(e.field() == "arith");
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("the arithmetics are one table: every row's name round-trips", "[arith]") {
  std::vector<ArithSpec::Kind> kinds;
  for (const auto& row : arith_rows) {
    const std::string name = row.kind == ArithSpec::Kind::mpfr ? "mpfr:113" : row.name;
    CAPTURE(name);
    const auto spec = ArithSpec::parse(name);
    CHECK(spec.kind == row.kind);
    CHECK(spec.name() == name);
    // The row's type carries the row's name: a row naming the wrong type fails here.
    CHECK(with_arith<KernelArithmetics>(spec, "test", [](auto tag) {
            using T = typename decltype(tag)::type;
            return std::string(std::is_same_v<T, Mpfr> ? "mpfr:113" : ArithOf<T>::name);
          }) == name);
    for (auto k : kinds) CHECK(k != row.kind);
    kinds.push_back(row.kind);
  }
  CHECK(kinds.size() == 5);
  CHECK(std::string(arith_rows[4].name) == "mpfr:BITS");
  CHECK(ArithSpec::parse("gmp").is_exact());
  CHECK(ArithSpec::parse("flint").is_exact());
  CHECK(!ArithSpec::parse("mpfr:64").is_exact());
  CHECK_THROWS_WITH(ArithSpec::parse("quad"),
                    "arith: unknown arithmetic \"quad\" (fix: use exact, gmp, flint, double, or mpfr:BITS with 24 <= BITS <= 1000000)");
}

TEST_CASE("with_arith dispatches each package's list to its types", "[arith]") {
  const auto bits = Mpfr::current_bits();
  REQUIRE(bits != 77);
  check_dispatch(KernelArithmetics{});
  check_dispatch(ComposeArithmetics{});
  check_dispatch(TensorArithmetics{});
  check_dispatch(UntrimArithmetics{});
  check_dispatch(HybridArithmetics{});
  check_dispatch(VrepArithmetics{});
  check_dispatch(Arithmetics<double>{});
  CHECK(std::is_same_v<VrepArithmetics, Arithmetics<Rational, double, Mpfr>>);
  CHECK(std::is_same_v<HybridArithmetics, Arithmetics<Rational, double, Mpfr>>);
  CHECK(Mpfr::current_bits() == bits);  // the scope (mpfr:77, checked by the name) ended with the call
}

TEST_CASE("with_arith refuses an arithmetic outside the list, naming the list", "[arith]") {
  CHECK(refusal("flint", VrepArithmetics{}) ==
        "arith: vrep construct runs in exact, gmp, double or mpfr:BITS (not flint) (fix: use --arith exact, gmp, double or mpfr:BITS)");
  CHECK(refusal("exact", Arithmetics<double>{}) == "arith: vrep construct runs in double (not exact) (fix: use --arith double)");
  CHECK(refusal("flint", Arithmetics<double>{}) == "arith: vrep construct runs in double (not flint) (fix: use --arith double)");
  CHECK(refusal("mpfr:64", Arithmetics<double>{}) == "arith: vrep construct runs in double (not mpfr:64) (fix: use --arith double)");
  CHECK(refusal("double", Arithmetics<double>{}) == "no error");
  CHECK(refusal("exact", Arithmetics<Rational, Mpfr>{}) == "no error");
  CHECK(refusal("double", Arithmetics<Rational, Mpfr>{}) ==
        "arith: vrep construct runs in exact, gmp or mpfr:BITS (not double) (fix: use --arith exact, gmp or mpfr:BITS)");
  for (const char* a : {"exact", "gmp", "flint", "double", "mpfr:64"}) CHECK(refusal(a, KernelArithmetics{}) == "no error");
  CHECK(refusal("gmp", Arithmetics<ExactFF, double>{}) ==
        "arith: vrep construct runs in exact or double (not gmp) (fix: use --arith exact or double)");
}

TEST_CASE("exact runs the fraction-free kernel where a package has it, GMP elsewhere, and gmp always GMP", "[arith]") {
  auto type_of = [](const char* a, auto list) {
    return with_arith<decltype(list)>(ArithSpec::parse(a), "test", [](auto tag) {
      using T = typename decltype(tag)::type;
      return std::string(std::is_same_v<T, ExactFF> ? "ExactFF" : std::is_same_v<T, Rational> ? "Rational" : "other");
    });
  };
  CHECK(type_of("exact", KernelArithmetics{}) == "ExactFF");
  CHECK(type_of("gmp", KernelArithmetics{}) == "Rational");
  CHECK(type_of("exact", VrepArithmetics{}) == "Rational");
  CHECK(type_of("gmp", VrepArithmetics{}) == "Rational");
  CHECK(type_of("exact", ComposeArithmetics{}) == "Rational");
}
