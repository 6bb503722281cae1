// The console reporter the benchmarks print their ratio tables from: real time (`ns`) and CPU time
// (`cpu`) per benchmark function name (without "/iterations:N"), as Google Benchmark reports them
// (in the benchmark's time unit: the ratios are what the tables print).
#pragma once
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace splinex {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns, cpu;
  void ReportRuns(const std::vector<Run>& runs) override {
    // With --benchmark_repetitions the mean is kept, not the last repetition or another aggregate.
    for (const auto& r : runs)
      if (!r.error_occurred && (r.run_type == Run::RT_Iteration || r.aggregate_name == "mean")) {
        ns[r.run_name.function_name] = r.GetAdjustedRealTime();
        cpu[r.run_name.function_name] = r.GetAdjustedCPUTime();
      }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace splinex
