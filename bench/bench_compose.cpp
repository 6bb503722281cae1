// Algorithm 1 (composition across knot lines into trimmed patches) on the teapot star pattern:
// 7 x 7 stars per teapot surface, exact (GMP), exact (FLINT) and double; prints exact/double.
// Algorithm 2 (untrimming into tensor-product tiles, polylines within 1e-2) on one star of each
// surface, exact (GMP) and double; prints exact/double and the bit sizes of the exact tiles'
// coefficients (numerator + denominator bits), against the input's.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"
#include <gmp.h>

#include <iomanip>
#include <iostream>
#include <map>

#include "fixtures/teapot.hpp"
#include "exact/flint_rational.hpp"
#include "experiments/teapot_stars.hpp"
#include "float/mpfr.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/algorithm2.hpp"

using namespace splinex;

namespace {

template <class T>
void pattern(benchmark::State& st, const TeapotSurface& surf) {
  auto conv = [](const Rational& x) { return ArithTraits<T>::from_rational(x); };
  const BSpline<T> outer = convert<T>(surf.surface, conv);
  std::vector<BSpline<T>> stars;
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i)
      stars.push_back(convert<T>(star_in_tile(i, j, 7, surf.surface.domain_hi(0), surf.surface.domain_hi(1)), conv));
  std::size_t patches = 0;
  for (auto _ : st) {
    patches = 0;
    for (const auto& s : stars) patches += compose_trimmed(outer, s).patches.size();
  }
  st.counters["patches"] = static_cast<double>(patches);
}

std::size_t bits(const Rational& x) {
  return mpz_sizeinbase(mpq_numref(x.backend().data()), 2) + mpz_sizeinbase(mpq_denref(x.backend().data()), 2);
}

struct BitStats {
  double mean = 0;
  std::size_t max = 0;
};
std::map<std::string, BitStats> tile_bits, input_bits;

// Algorithm 2 on the star in tile (0, 2) of the 7 x 7 pattern.
template <class T>
void untrim_star(benchmark::State& st, const TeapotSurface& surf) {
  auto conv = [](const Rational& x) { return ArithTraits<T>::from_rational(x); };
  const BSpline<T> outer = convert<T>(surf.surface, conv);
  const BSpline<Rational> star = star_in_tile(0, 2, 7, surf.surface.domain_hi(0), surf.surface.domain_hi(1));
  const BSpline<T> inner = convert<T>(star, conv);
  TensorOptions to;
  to.boundary = TrimBoundary::polyline;
  to.eps = 1e-2;
  to.grid = 8;
  std::size_t tiles = 0, cps = 0;
  for (auto _ : st) {
    const auto A = compose_tensor(outer, inner, to);
    tiles = A.tiles.size();
    cps = 0;
    for (const auto& t : A.tiles) cps += t.R.net.size();
    if constexpr (std::is_same_v<T, Rational>) {
      BitStats b, in;
      std::size_t n = 0;
      for (const auto& t : A.tiles)
        for (const auto& x : t.R.net.points) {
          const std::size_t k = bits(x);
          b.mean += static_cast<double>(k);
          b.max = std::max(b.max, k);
          ++n;
        }
      b.mean /= static_cast<double>(n);
      n = 0;
      for (const auto* S : {&surf.surface, &star})
        for (const auto& x : S->points) {
          const std::size_t k = bits(x);
          in.mean += static_cast<double>(k);
          in.max = std::max(in.max, k);
          ++n;
        }
      in.mean /= static_cast<double>(n);
      tile_bits[surf.name] = b;
      input_bits[surf.name] = in;
    }
  }
  st.counters["tiles"] = static_cast<double>(tiles);
  st.counters["control_points"] = static_cast<double>(cps);
}


}  // namespace

int main(int argc, char** argv) {
  static const auto surfaces = teapot_surfaces(read_bpt(data_path("teapot.bpt")));
  for (const auto& s : surfaces) {
    benchmark::RegisterBenchmark(("stars/double/" + s.name).c_str(), [&s](benchmark::State& st) { pattern<double>(st, s); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("stars/flint/" + s.name).c_str(), [&s](benchmark::State& st) { pattern<FlintRational>(st, s); })
        ->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("stars/exact/" + s.name).c_str(), [&s](benchmark::State& st) { pattern<Rational>(st, s); })
        ->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  for (const auto& s : surfaces) {
    benchmark::RegisterBenchmark(("untrim_star/double/" + s.name).c_str(), [&s](benchmark::State& st) { untrim_star<double>(st, s); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("untrim_star/exact/" + s.name).c_str(), [&s](benchmark::State& st) { untrim_star<Rational>(st, s); })
        ->Unit(benchmark::kMillisecond);  // timed like double (min time), not one cold first call
  }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  double te = 0, tf = 0, td = 0;
  std::cout << "\nAlgorithm 1 on the teapot star pattern (49 stars per surface):\nsurface   exact(GMP)/double  flint/double\n";
  for (const auto& s : surfaces) {
    const double d = rep.ns["stars/double/" + s.name], e = rep.ns["stars/exact/" + s.name], f = rep.ns["stars/flint/" + s.name];
    if (d == 0 || e == 0 || f == 0) continue;  // filtered out
    te += e;
    tf += f;
    td += d;
    std::cout << std::left << std::setw(10) << s.name << std::setw(19) << std::fixed << std::setprecision(1) << e / d << f / d << "\n";
  }
  std::cout << "all four: exact(GMP) " << std::setprecision(2) << te / 1e3 << " s, flint " << tf / 1e3 << " s, double " << td / 1e3
            << " s\n";
  std::cout << "\nAlgorithm 2 on one star (tile (0, 2), polylines within 1e-2):\n"
               "surface   exact(GMP)/double  tile coefficient bits mean/max  input bits mean/max\n";
  for (const auto& s : surfaces) {
    const double d = rep.ns["untrim_star/double/" + s.name], e = rep.ns["untrim_star/exact/" + s.name];
    if (d == 0 || e == 0) continue;
    std::cout << std::left << std::setw(10) << s.name << std::setw(19) << std::setprecision(1) << e / d << std::setw(32)
              << (std::to_string(static_cast<long>(tile_bits[s.name].mean)) + " / " + std::to_string(tile_bits[s.name].max))
              << std::to_string(static_cast<long>(input_bits[s.name].mean)) + " / " + std::to_string(input_bits[s.name].max)
              << "\n";
  }
  benchmark::Shutdown();
  return 0;
}
