// bench_document: Google Benchmark of one kernel operation on your own spline document, in every
// arithmetic (exact = fraction-free, gmp, flint, double, MPFR), and the CPU-time ratio of each to double -
// the measure of docs/speed.md, on your input instead of its generated cases.
//
//   build/bin/bench_document elevate --by 1 tests/data/curve.json
//   build/bin/bench_document insert-knots --knots 0.25,0.5 my.json --arith exact,double
//   build/bin/bench_document split --at 1/3 my.json --benchmark_min_time=0.5   (any Google Benchmark flag)
//
// The input is read exactly and rounded once into each arithmetic (outside the timing); the
// operation's options are those of `splinex OPERATION` (numbers read exactly).
#include <benchmark/benchmark.h>

#include <CLI/CLI.hpp>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "bench/ratio_reporter.hpp"
#include "crosscheck/operations.hpp"
#include "crosscheck/operations_ff.hpp"
#include "float/arith_spec.hpp"
#include "float/rounding.hpp"
#include "io/json_io.hpp"

using namespace splinex;

int main(int argc, char** argv) {
  CLI::App app{"bench_document: one kernel operation on your spline document in every arithmetic, CPU-time ratios to double"};
  std::string kind, file, ariths = "exact,gmp,flint,double,mpfr:53";
  OpOptions op;
  app.add_option("operation", kind, "insert-knots, elevate, extract-bezier, split, reparametrize, reverse, derivative")
      ->required()
      ->check(CLI::IsMember({"insert-knots", "elevate", "extract-bezier", "split", "reparametrize", "reverse", "derivative"}));
  app.add_option("file", file, "the spline document")->required();
  app.add_option("--arith", ariths, "comma-separated arithmetics (exact, gmp, flint, double, mpfr:BITS)")->capture_default_str();
  app.add_option("--dir", op.dir, "parametric direction");
  app.add_option("--knots", op.knots, "insert-knots: comma-separated knots");
  app.add_option("--method", op.insert_method, "insert-knots: a54|boehm; elevate: auto|a59|blossom")
      ->check(CLI::IsMember({"a54", "boehm", "auto", "a59", "blossom"}));
  app.allow_extras();  // the --benchmark_* flags, handed to Google Benchmark below
  app.footer("Any Google Benchmark flag may follow (--benchmark_min_time=0.5, --benchmark_repetitions=5, ...).");
  app.add_option("--by", op.by, "elevate: amount; derivative: order");
  app.add_option("--at", op.at, "split: parameter");
  app.add_option("--interval", op.interval, "reparametrize: \"lo,hi\"");
  CLI11_PARSE(app, argc, argv);
  std::vector<std::string> extras{argv[0]};
  for (const auto& x : app.remaining()) {
    if (x.rfind("--benchmark_", 0) != 0) {
      std::cerr << "bench_document: error: " << x << ": not an option of bench_document or Google Benchmark (see --help)\n";
      return 2;
    }
    extras.push_back(x);
  }
  std::vector<char*> bargv;
  for (auto& x : extras) bargv.push_back(x.data());
  int bargc = static_cast<int>(bargv.size());
  benchmark::Initialize(&bargc, bargv.data());
  std::vector<std::string> names;
  try {
    const std::string& m = op.insert_method;  // --method serves both operations; here each only its own methods
    if (kind == "insert-knots" && m != "a54" && m != "boehm") throw UsageError("method", "insert-knots takes a54 or boehm", "give --method a54|boehm");
    if (kind == "elevate" && m == "boehm") throw UsageError("method", "elevate takes auto, a59 or blossom", "give --method auto|a59|blossom");
    use_one_method(kind, op, kind);
    const Operation o = make_op(kind, op);
    const auto S = spline_from_json(read_json_file(file), Limits{}, "input");
    std::string rest = ariths;
    while (!rest.empty()) {
      const auto comma = rest.find(',');
      const std::string a = rest.substr(0, comma);
      rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
      const ArithSpec spec = ArithSpec::parse(a);
      with_arith<KernelArithmetics>(spec, "bench_document", [&](auto tag) {
        using T = typename decltype(tag)::type;
        if constexpr (std::is_same_v<T, ExactFF>) {
          // The fraction-free net, converted once as the float inputs are; the operations it
          // lacks run on GMP (run_operation_exact), timed as such.
          auto in = std::make_shared<ff::FFNet>(ff::from_bspline(S));
          auto gin = std::make_shared<BSpline<Rational>>(S);
          run_operation_exact(o, S, Limits{});
          const std::string name = kind + "/" + spec.name();
          names.push_back(name);
          benchmark::RegisterBenchmark(name.c_str(), [o, in, gin](benchmark::State& st) {
            for (auto _ : st)
              if (runs_fraction_free(o)) benchmark::DoNotOptimize(run_operation_ff(o, *in, Limits{}));
              else benchmark::DoNotOptimize(run_operation<Rational>(o, *gin, Limits{}));
          });
          return;
        } else {
        auto in = std::make_shared<BSpline<T>>(round_spline<T>(S, "input"));
        run_operation<T>(o, *in, Limits{});  // a bad operation is an error here, not inside the timing
        const long bits = spec.bits;
        const std::string name = kind + "/" + spec.name();
        names.push_back(name);
        benchmark::RegisterBenchmark(name.c_str(), [o, in, bits](benchmark::State& st) {
          std::optional<Mpfr::Precision> scope;
          if constexpr (std::is_same_v<T, Mpfr>) scope.emplace(bits);
          for (auto _ : st) benchmark::DoNotOptimize(run_operation<T>(o, *in, Limits{}));
        });
        }
      });
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_document: error: " << e.what() << "\n";
    return 2;
  }
  RatioReporter rep;  // CPU time: a busy machine changes it less than wall time
  benchmark::RunSpecifiedBenchmarks(&rep);
  const std::string base = kind + "/double";
  if (!rep.cpu.count(base) || rep.cpu[base] <= 0) {
    std::cout << "no double run: no ratios (give --arith with double)\n";
    return 0;
  }
  std::cout << "\nCPU time relative to double (" << kind << " on " << file << "):\n";
  for (const auto& n : names)
    if (rep.cpu.count(n)) std::cout << "  " << std::left << std::setw(28) << n << std::fixed << std::setprecision(2) << rep.cpu[n] / rep.cpu[base] << "x\n";
  return 0;
}
