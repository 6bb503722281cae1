// The hybrid patch (papers/003): exact (GMP rationals) and double evaluation per point, and the
// exact first derivatives (dual numbers), for n = 5, 6, 8 sides and d = 6 (Examples 2.1 and 3.1
// domains, p = 2, Example 2.1's knots); prints exact/double per n.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"

#include <iomanip>
#include <iostream>
#include <map>

#include "fixtures/hybrid_examples.hpp"
#include "float/mpfr.hpp"
#include "hybrid/hybrid.hpp"

using namespace splinex;

namespace {

HybridPatch<Rational> patch(int n) {
  const std::vector<Rational> U{0, 0, 0, Rational(1, 5), Rational(2, 5), Rational(3, 5), Rational(4, 5), 1, 1, 1};
  const auto V = n == 5 ? hybrid_example_2_1().vertices : n == 6 ? hybrid_example_3_1_hexagon().vertices : hybrid_example_3_1_octagon().vertices;
  return hybrid_dome(V, 6, std::vector<int>(V.size(), 2), std::vector<std::vector<Rational>>(V.size(), U));
}

// 16 interior points: the centroid pulled towards each vertex and each side midpoint.
std::vector<std::array<Rational, 2>> points(const HybridPatch<Rational>& P) {
  std::array<Rational, 2> g{0, 0};
  for (const auto& v : P.vertices) {
    g[0] += v[0] / static_cast<long>(P.sides());
    g[1] += v[1] / static_cast<long>(P.sides());
  }
  std::vector<std::array<Rational, 2>> X;
  for (std::size_t k = 0; X.size() < 16; k = (k + 1) % P.sides()) {
    const Rational t(static_cast<long>(1 + X.size() % 7), 8);
    X.push_back({g[0] + t * (P.vertices[k][0] - g[0]), g[1] + t * (P.vertices[k][1] - g[1])});
  }
  return X;
}

template <class T>
void eval(benchmark::State& st, int n, bool derivatives) {
  const auto P = patch(n);
  const auto Q = convert_hybrid<T>(P, [](const Rational& r) { return ArithTraits<T>::from_rational(r); });
  std::vector<std::array<T, 2>> X;
  for (const auto& x : points(P)) X.push_back({ArithTraits<T>::from_rational(x[0]), ArithTraits<T>::from_rational(x[1])});
  for (auto _ : st)
    for (const auto& x : X) {
      if (derivatives) benchmark::DoNotOptimize(hybrid_derivatives(Q, x));
      else benchmark::DoNotOptimize(hybrid_evaluate(Q, x));
    }
  st.SetItemsProcessed(static_cast<long>(st.iterations() * X.size()));
}


}  // namespace

int main(int argc, char** argv) {
  for (int n : {5, 6, 8})
    for (const bool der : {false, true}) {
      const std::string what = der ? "derivatives" : "value";
      benchmark::RegisterBenchmark(("hybrid/" + what + "/double/n" + std::to_string(n)).c_str(),
                                   [n, der](benchmark::State& st) { eval<double>(st, n, der); })
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("hybrid/" + what + "/exact/n" + std::to_string(n)).c_str(),
                                   [n, der](benchmark::State& st) { eval<Rational>(st, n, der); })
          ->Unit(benchmark::kMicrosecond);
    }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nHybrid patch, d = 6, p = 2, 16 points per iteration: exact(GMP)/double per point\n"
               "n   value   derivatives (u and v)\n";
  for (int n : {5, 6, 8}) {
    auto r = [&](const std::string& w) {
      const double d = rep.ns["hybrid/" + w + "/double/n" + std::to_string(n)], e = rep.ns["hybrid/" + w + "/exact/n" + std::to_string(n)];
      return d > 0 && e > 0 ? e / d : 0.0;
    };
    std::cout << n << "   " << std::fixed << std::setprecision(0) << std::setw(6) << r("value") << "  " << std::setw(6) << r("derivatives") << "\n";
  }
  benchmark::Shutdown();
  return 0;
}
