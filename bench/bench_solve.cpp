// Certified vs float solving (issue 19): point projection and surface distance, exact (GMP
// rationals: certified), MPFR at 53 and 200 bits and double (the same subdivision, uncertified), and
// Newton from a 16 x 16 grid (what a CAD kernel does), in one run; prints the ratios.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"

#include <iomanip>
#include <iostream>

#include "fixtures/solve_examples.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "solve/contact.hpp"
#include "solve/projection.hpp"

using namespace splinex;

namespace {

struct Case {
  BSpline<Rational> S;
  std::vector<Rational> P;
};

Case projection_case(const std::string& name) {
  if (name == "bumps") return {cubic_bumps(), {Rational(7, 5), Rational(8, 5), Rational(3)}};
  return {stereographic_sphere(), {Rational(1), Rational(1), Rational(0)}};
}

template <class T>
void project_step(benchmark::State& st, const std::string& name, long bits) {
  Mpfr::Precision prec(bits);
  const auto c = projection_case(name);
  const auto S = round_spline<T>(c.S, "surface");
  const auto P = round_values<T>(c.P, "point");
  for (auto _ : st) benchmark::DoNotOptimize(project_point(S, P));
}

void sampled_step(benchmark::State& st, const std::string& name) {
  const auto c = projection_case(name);
  const auto S = round_spline<double>(c.S, "surface");
  const std::array<double, 3> P{to_double(c.P[0]), to_double(c.P[1]), to_double(c.P[2])};
  for (auto _ : st) benchmark::DoNotOptimize(project_point_sampled(S, P, 16));
}

template <class T>
void contact_step(benchmark::State& st, long bits) {
  Mpfr::Precision prec(bits);
  const auto S1 = stereographic_sphere();
  auto S2 = S1;
  for (std::size_t i = 0; i < S2.size(); ++i) {
    S2.points[3 * i] = Rational(3, 2) - S2.points[3 * i];
    S2.points[3 * i + 1] = Rational(3, 2) - S2.points[3 * i + 1];
  }
  const auto A = round_spline<T>(S1, "first"), B = round_spline<T>(S2, "second");
  for (auto _ : st) benchmark::DoNotOptimize(surface_distance(A, B));
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> cases{"bumps", "sphere"};
  for (const auto& c : cases) {
    benchmark::RegisterBenchmark(("solve/project/exact/" + c).c_str(), [c](benchmark::State& st) { project_step<Rational>(st, c, 53); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("solve/project/mpfr200/" + c).c_str(), [c](benchmark::State& st) { project_step<Mpfr>(st, c, 200); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("solve/project/mpfr53/" + c).c_str(), [c](benchmark::State& st) { project_step<Mpfr>(st, c, 53); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("solve/project/double/" + c).c_str(), [c](benchmark::State& st) { project_step<double>(st, c, 53); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("solve/project/newton16/" + c).c_str(), [c](benchmark::State& st) { sampled_step(st, c); })
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("solve/contact/exact/spheres", [](benchmark::State& st) { contact_step<Rational>(st, 53); })
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
  benchmark::RegisterBenchmark("solve/contact/mpfr200/spheres", [](benchmark::State& st) { contact_step<Mpfr>(st, 200); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("solve/contact/double/spheres", [](benchmark::State& st) { contact_step<double>(st, 53); })
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nCertified vs float solving: ms per solve, and / double\n"
            << "case              exact   mpfr200    mpfr53    double  newton16   exact/double  mpfr200/double\n";
  for (const auto& c : cases) {
    const auto t = [&](const std::string& a) { return rep.ns["solve/project/" + a + "/" + c]; };
    std::cout << std::left << std::setw(16) << ("project " + c) << std::right << std::fixed << std::setprecision(2) << std::setw(8) << t("exact")
              << std::setw(10) << t("mpfr200") << std::setw(10) << t("mpfr53") << std::setw(10) << t("double") << std::setw(10) << t("newton16")
              << std::setprecision(1) << std::setw(15) << (t("double") > 0 ? t("exact") / t("double") : 0.0) << std::setw(16)
              << (t("double") > 0 ? t("mpfr200") / t("double") : 0.0) << "\n";
  }
  {
    const auto t = [&](const std::string& a) { return rep.ns["solve/contact/" + a + "/spheres"]; };
    std::cout << std::left << std::setw(16) << "contact spheres" << std::right << std::fixed << std::setprecision(2) << std::setw(8) << t("exact")
              << std::setw(10) << t("mpfr200") << std::setw(10) << "-" << std::setw(10) << t("double") << std::setw(10) << "-" << std::setprecision(1)
              << std::setw(15) << (t("double") > 0 ? t("exact") / t("double") : 0.0) << std::setw(16) << (t("double") > 0 ? t("mpfr200") / t("double") : 0.0)
              << "\n";
  }
  benchmark::Shutdown();
  return 0;
}
