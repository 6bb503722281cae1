// The tolerance study of untrimming (issue 4, papers/000 Algorithm 2): what trimming polylines
// within eps cost once the trimmed pieces are untrimmed into tensor-product tiles, measured
// exactly, against eps, the continuity of T at the crossed knot, and the float precision.
//
// Case: S of degrees (1, 2) whose trimming curve s_u = 1/2 is a parabola, T of degrees (3, 1) in
// R^2 with the knot u0 = 1/2 of multiplicity m = 1..4 (T is C^(3-m) there). For each eps and each
// arithmetic (double, MPFR at the given precisions) Algorithm 2 (compose_tensor with polylines) is
// run in that arithmetic; its output is then judged exactly:
//  - deviation: max |R(x, l) - T(S(Q(x, l)))| with R's local control points and Q's vertices taken
//    exactly, at the midpoints and vertices of every tile's bottom and top chains (where the sliver
//    between polyline and true curve is) and on a 4 x 4 interior grid; predicted ~ eps^(p-m+1);
//  - gaps and overlaps: the exact area of the union of the tiles (CGAL Boolean operations on the
//    exact tile polygons) against the domain's area and against the sum of the tile areas;
//  - tiles, their degrees, chain vertices, control points, time.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace splinex {

/// One arithmetic of the sweep: bits 0 is double, else MPFR at that precision; run for the
/// tolerances >= min_eps and the multiplicities 1..max_m (MPFR costs ~25x double here).
struct UntrimRun {
  int bits = 0;
  double min_eps = 1e-6;
  int max_m = 4;
};

struct UntrimToleranceOptions {
  std::string out_dir;
  std::vector<double> eps{1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<UntrimRun> runs{{0, 1e-6, 4}, {113, 1e-5, 1}};
  std::size_t max_boundary_samples = 400;  // per tile chain (every k-th vertex/midpoint beyond it)
  std::size_t max_control_points = 20'000'000;  // summed over a case's tiles (checked before composing); larger cases are recorded as skipped
};

UntrimToleranceOptions full_untrim_tolerance_options(const std::string& out_dir);

/// One unit of the sweep: multiplicity m, arithmetic (bits 0: double, else MPFR), tolerance.
struct UntrimCase {
  int m = 1, bits = 0;
  double eps = 1e-2;
};

/// The sweep's cases in the order of its table: m = 1..4, then the runs, then eps.
std::vector<UntrimCase> untrim_tolerance_cases(const UntrimToleranceOptions& options);

/// One case measured (Algorithm 2 in that arithmetic, judged exactly): its row as JSON, the exact
/// numbers as fractions and the doubles at 17 digits, so that a row written by one process and read
/// by another (sweep run / sweep merge) is the same row.
nlohmann::json untrim_tolerance_case(const UntrimCase& c, const UntrimToleranceOptions& options);

/// The rows (in the order of untrim_tolerance_cases) turned into untrim_tolerance.csv, .svg,
/// _cost.svg and .md in options.out_dir, the slopes fitted; returns the Markdown section. ok as below.
std::string untrim_tolerance_merge(const std::vector<nlohmann::json>& rows, const UntrimToleranceOptions& options, bool& ok);

/// The options as JSON and back (the sweep's plan carries them to every job and to the merge).
nlohmann::json untrim_tolerance_options_json(const UntrimToleranceOptions& options);
UntrimToleranceOptions untrim_tolerance_options_from_json(const nlohmann::json& j);

/// Writes untrim_tolerance.csv, untrim_tolerance.svg, untrim_tolerance_cost.svg and
/// untrim_tolerance.md into out_dir; returns the Markdown section. ok is false when the slope fitted
/// at the highest precision misses p - m + 1 (0 for m = p + 1) by more than 0.3, or a gap or
/// overlap of positive area appears.
/// The cases run on `threads` threads (0: every core); the files do not depend on it (times aside).
std::string run_untrim_tolerance(const UntrimToleranceOptions& options,
                                 const std::function<void(const std::string&)>& progress, bool& ok,
                                 std::size_t threads = 1);

}  // namespace splinex
