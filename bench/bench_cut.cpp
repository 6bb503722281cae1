// Cutting curves (issue 20, papers/004 d = 2): each step exact vs double in one run: the guide's QP
// (assembly + CGAL's solver: exact on Rational data, and on the doubles of the rounded program),
// the certified separation of the guide, the march + fit of the cutting curve, its validity.
// Prints the ratios exact/double per step.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"

#include <iomanip>
#include <iostream>

#include "cut/curve_facet.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "cut/surface_facet.hpp"

using namespace splinex;

int main(int argc, char** argv) {
  const std::vector<std::string> cases{"L", "U", "K"};
  for (const auto& c : cases) {
    benchmark::RegisterBenchmark(("cut/guide/exact/" + c).c_str(), [c](benchmark::State& st) {
      const auto e = cut_example(c);
      for (auto _ : st) benchmark::DoNotOptimize(guide_curve<Rational>(e.solid, e.cut));
    })->Unit(benchmark::kMillisecond)->Iterations(2);
    benchmark::RegisterBenchmark(("cut/guide/double/" + c).c_str(), [c](benchmark::State& st) {
      const auto e = cut_example(c);
      for (auto _ : st) benchmark::DoNotOptimize(guide_curve<double>(e.solid, e.cut));
    })->Unit(benchmark::kMillisecond)->Iterations(2);
    benchmark::RegisterBenchmark(("cut/separation/exact/" + c).c_str(), [c](benchmark::State& st) {
      const auto e = cut_example(c);
      const auto R = guide_curve<Rational>(e.solid, e.cut);
      for (auto _ : st) benchmark::DoNotOptimize(certify_separation(R.solid, R.cut, R.f, GuideOptions{}.strip));
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cut/separation/double/" + c).c_str(), [c](benchmark::State& st) {
      // the double guide's coefficients, decided exactly (the certificate has no float variant)
      const auto e = cut_example(c);
      const auto D = guide_curve<double>(e.solid, e.cut);
      const auto& f = D.f_exact;
      for (auto _ : st) benchmark::DoNotOptimize(certify_separation(D.solid, D.cut, f, GuideOptions{}.strip));
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cut/fit/exact/" + c).c_str(), [c](benchmark::State& st) {
      const auto e = cut_example(c);
      const auto R = guide_curve<Rational>(e.solid, e.cut);
      for (auto _ : st) benchmark::DoNotOptimize(fit_cutting_curve(R.solid, R.cut, R.f));
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cut/validity/exact/" + c).c_str(), [c](benchmark::State& st) {
      const auto e = cut_example(c);
      const auto R = guide_curve<Rational>(e.solid, e.cut);
      const auto cc = fit_cutting_curve(R.solid, R.cut, R.f);
      for (auto _ : st) benchmark::DoNotOptimize(certify_cutting_curve(R.solid, R.cut, cc.curve));
    })->Unit(benchmark::kMillisecond);
  }
  // d = 3: the guiding surface of the smallest and of the modelled bi-slotted example (settings of
  // the report), and its certified separation.
  const std::vector<std::string> cases3{"tower", "slotted"};
  auto options3 = [] {
    GuideOptions3 o;
    o.base.samples = 1;
    o.loop_samples = 2;
    return o;
  };
  for (const auto& c : cases3) {
    benchmark::RegisterBenchmark(("cut3/guide/exact/" + c).c_str(), [c, options3](benchmark::State& st) {
      const auto e = cut_example3(c);
      for (auto _ : st) benchmark::DoNotOptimize(guide_surface<Rational>(e.solid, e.cut, options3()));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("cut3/guide/double/" + c).c_str(), [c, options3](benchmark::State& st) {
      const auto e = cut_example3(c);
      for (auto _ : st) benchmark::DoNotOptimize(guide_surface<double>(e.solid, e.cut, options3()));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("cut3/separation/exact/" + c).c_str(), [c, options3](benchmark::State& st) {
      const auto e = cut_example3(c);
      const auto R = guide_surface<Rational>(e.solid, e.cut, options3());
      for (auto _ : st) benchmark::DoNotOptimize(certify_separation(R.solid, R.loop, e.cut.positive, R.f_exact, options3().base.strip));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  // d = 3: the cutting surface's initial patch (Step 1 and 2) exactly and in double, and its
  // certificates, on the slotted block (projection domain) and the maiden (circle domain, active set).
  const std::vector<std::string> surfaces{"slotted", "maiden"};
  for (const auto& c : surfaces) {
    auto loop_of = [c] {
      const auto e = cut_example3(c);
      return validate_cut(to_frame(e.solid, unit_frame(e.solid)), e.cut);
    };
    benchmark::RegisterBenchmark(("cut3/patch/exact/" + c).c_str(), [loop_of](benchmark::State& st) {
      const auto loop = loop_of();
      for (auto _ : st) benchmark::DoNotOptimize(cutting_surface<Rational>(loop));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("cut3/patch/double/" + c).c_str(), [loop_of](benchmark::State& st) {
      const auto loop = loop_of();
      for (auto _ : st) benchmark::DoNotOptimize(cutting_surface<double>(loop));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("cut3/certificates/exact/" + c).c_str(), [c, loop_of](benchmark::State& st) {
      const auto e = cut_example3(c);
      const auto Sn = to_frame(e.solid, unit_frame(e.solid));
      const auto loop = loop_of();
      const auto R = cutting_surface<Rational>(loop);
      for (auto _ : st) benchmark::DoNotOptimize(certify_cutting_surface(Sn, loop, R.domain, R.patch));
    })->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nCutting curves: ms per step (guide: assembly + QP; double: the rounded program on the same exact solver)\n"
            << "case   guide exact  guide double  exact/double   separation  fit (march+LSQ)  validity\n";
  for (const auto& c : cases) {
    const auto t = [&](const std::string& a) { return rep.ns["cut/" + a + "/" + c]; };
    std::cout << std::left << std::setw(6) << c << std::right << std::fixed << std::setprecision(1) << std::setw(12) << t("guide/exact")
              << std::setw(14) << t("guide/double") << std::setprecision(2) << std::setw(14)
              << (t("guide/double") > 0 ? t("guide/exact") / t("guide/double") : 0.0) << std::setprecision(1) << std::setw(13)
              << t("separation/exact") << std::setw(17) << t("fit/exact") << std::setw(10) << t("validity/exact") << "\n";
  }
  std::cout << "\nCutting surfaces (d = 3): ms per step (1 inner knot, 1 sample per facet, 2 points per loop side)\n"
            << "case      guide exact  guide double  exact/double   separation\n";
  for (const auto& c : cases3) {
    const auto t = [&](const std::string& a) { return rep.ns["cut3/" + a + "/" + c]; };
    std::cout << std::left << std::setw(9) << c << std::right << std::fixed << std::setprecision(1) << std::setw(12) << t("guide/exact")
              << std::setw(14) << t("guide/double") << std::setprecision(2) << std::setw(14)
              << (t("guide/double") > 0 ? t("guide/exact") / t("guide/double") : 0.0) << std::setprecision(1) << std::setw(13)
              << t("separation/exact") << "\n";
  }
  std::cout << "\nCutting surfaces, the initial patch (3 inner knots, 147 variables): ms\n"
            << "case      patch exact  patch double  exact/double  certificates (exact)\n";
  for (const auto& c : surfaces) {
    const auto t = [&](const std::string& a) { return rep.ns["cut3/" + a + "/" + c]; };
    std::cout << std::left << std::setw(9) << c << std::right << std::fixed << std::setprecision(1) << std::setw(12) << t("patch/exact")
              << std::setw(14) << t("patch/double") << std::setprecision(2) << std::setw(14)
              << (t("patch/double") > 0 ? t("patch/exact") / t("patch/double") : 0.0) << std::setprecision(1) << std::setw(22)
              << t("certificates/exact") << "\n";
  }
  return 0;
}
