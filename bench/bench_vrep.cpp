// V-rep (issue 17): constructing, gluing and certifying the primitives (cylinder, cone, torus of
// five cells, the sphere of seven), exact (GMP rationals) and double, in one run; prints exact/double per step.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"

#include <iomanip>
#include <iostream>
#include <map>

#include "float/mpfr.hpp"
#include "vrep/primitives.hpp"
#include "vrep/regularity.hpp"
#include "vrep/vmodel.hpp"

using namespace splinex;

namespace {

template <class T>
std::vector<BSpline<T>> build(const std::string& name) {
  if (name == "cylinder") return cylinder_cells<T>(T(2), T(3));
  if (name == "cone") return cone_cells<T>(T(2), T(1), T(3));
  if (name == "torus") return torus_cells<T>(T(3), T(1));
  return sphere_cells<T>(T(2));
}

template <class T>
void step(benchmark::State& st, const std::string& name, const std::string& what) {
  const auto cells = build<T>(name);
  const T eps = std::is_same_v<T, double> ? T(1e-12) : T(0);
  for (auto _ : st) {
    if (what == "construct") benchmark::DoNotOptimize(build<T>(name));
    else if (what == "glue") benchmark::DoNotOptimize(glue(cells, eps));
    else
      for (const auto& V : cells) benchmark::DoNotOptimize(certify_regularity(V));
  }
}


}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> prims{"cylinder", "cone", "torus", "sphere"}, steps{"construct", "glue", "certify"};
  for (const auto& p : prims)
    for (const auto& s : steps) {
      benchmark::RegisterBenchmark(("vrep/" + s + "/double/" + p).c_str(), [p, s](benchmark::State& st) { step<double>(st, p, s); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("vrep/" + s + "/exact/" + p).c_str(), [p, s](benchmark::State& st) { step<Rational>(st, p, s); })
          ->Unit(benchmark::kMillisecond);
    }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nV-rep primitives: exact(GMP)/double\nprimitive   construct   glue   certify\n";
  for (const auto& p : prims) {
    std::cout << std::left << std::setw(12) << p << std::right;
    for (const auto& s : steps) {
      const double d = rep.ns["vrep/" + s + "/double/" + p], e = rep.ns["vrep/" + s + "/exact/" + p];
      std::cout << std::fixed << std::setprecision(1) << std::setw(9) << (d > 0 ? e / d : 0.0) << "  ";
    }
    std::cout << "\n";
  }
  benchmark::Shutdown();
  return 0;
}
