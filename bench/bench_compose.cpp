// Algorithm 1 (composition across knot lines into trimmed patches) on the teapot star pattern:
// 7 x 7 stars per teapot surface, exact (GMP), exact (FLINT) and double; prints exact/double.
#include <benchmark/benchmark.h>

#include <iomanip>
#include <iostream>
#include <map>

#include "exact/bpt.hpp"
#include "exact/flint_rational.hpp"
#include "experiments/teapot_stars.hpp"
#include "float/mpfr.hpp"
#include "spline/kernel.hpp"

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

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) ns[r.run_name.function_name] = r.GetAdjustedRealTime();  // without "/iterations:1"
    ConsoleReporter::ReportRuns(runs);
  }
};

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
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  double te = 0, tf = 0, td = 0;
  std::cout << "\nAlgorithm 1 on the teapot star pattern (49 stars per surface):\nsurface   exact(GMP)/double  flint/double\n";
  for (const auto& s : surfaces) {
    const double d = rep.ns["stars/double/" + s.name], e = rep.ns["stars/exact/" + s.name], f = rep.ns["stars/flint/" + s.name];
    te += e;
    tf += f;
    td += d;
    std::cout << std::left << std::setw(10) << s.name << std::setw(19) << std::fixed << std::setprecision(1) << e / d << f / d << "\n";
  }
  std::cout << "all four: exact(GMP) " << std::setprecision(2) << te / 1e3 << " s, flint " << tf / 1e3 << " s, double " << td / 1e3
            << " s\n";
  benchmark::Shutdown();
  return 0;
}
