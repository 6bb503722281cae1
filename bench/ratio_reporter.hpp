// The console reporter the benchmarks print their ratio tables from: real time per benchmark
// function name (without "/iterations:N"), as Google Benchmark reports it (in the benchmark's
// time unit: the ratios are what the tables print).
#pragma once
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace splinex {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (!r.error_occurred) ns[r.run_name.function_name] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace splinex
