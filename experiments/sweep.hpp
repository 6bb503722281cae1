// Sweeps as independent jobs (issue 21): a sweep's plan is a list of jobs, one JSON line each
// (jobs.jsonl), that any engine can run in any order and on any machine: `splinex sweep run` (a
// shard I of N, in one process), GNU parallel or xargs over the shards, a Slurm array. Every job
// writes one JSON file (atomically, so an interrupted run resumes by skipping the files that are
// there); `splinex sweep merge` checks that all are there, reads them in the plan's order and
// produces the same CSV, figures and Markdown as the single-process run (the report's section),
// timings aside, whatever the sharding.
//
// Built: untrim-tolerance (the untrimming tolerance sweep: multiplicity x arithmetic x eps),
// proofs (every named proof of `splinex prove` on N cases, in ranges of K cases per job: every
// case draws from a stream of its own, so a range runs alone; teapot-merge, whose cases are its
// four surfaces, is one job) and report (the
// report's sections as jobs: the crosscheck suite, the teapot stars, the composition tolerance
// study and every other section; crosscheck with composition-orders is one job, as they share a
// seeded stream; the merge writes the folder `splinex report` writes).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace splinex {

struct SweepJob {
  std::string sweep;       // the sweep's name
  std::string id;          // unique within the plan
  nlohmann::json params;   // what the job computes
  nlohmann::json plan;     // the plan's options (the same on every line; the merge reads them)
  std::string output;      // relative to the run's folder
};

/// The names of the sweeps that can be planned.
std::vector<std::string> sweep_names();

/// The options a plan takes, as given on the command line.
struct SweepPlanOptions {
  bool full = false;        // the long sweep (the report's --full)
  std::string eps;          // comma-separated tolerances, replacing the default list
  std::string runs;         // comma-separated bits:min_eps:max_m (bits 0: double), replacing the default runs
  std::optional<long> cases;          // proofs: random exact cases per proof (unset: 200, the long label's)
  std::optional<long> cases_per_job;  // proofs: cases of one proof per job (unset: 25); ranges of one proof merge exactly
  std::string proofs;       // proofs: comma-separated proof names (empty: every proof of the registry)
  std::string sections;     // report: comma-separated sections (empty: all)
};

std::vector<SweepJob> sweep_plan(const std::string& name, const SweepPlanOptions& options);

/// One line of jobs.jsonl and back (typed errors naming the field).
nlohmann::json sweep_job_json(const SweepJob& job);
SweepJob sweep_job_from_json(const nlohmann::json& j, const std::string& where);
/// Reads a jobs.jsonl file: every line a job, ids unique, one sweep and one plan for all, and every
/// line a job that sweep_plan writes for that plan (same id, params and output), checked by
/// planning again: an edited or foreign line is a ParseError naming it, before any work.
std::vector<SweepJob> read_sweep_jobs(const std::string& path);

/// Runs one job: its result document (the merge's input). Jobs that write files (report) write
/// them under dir/report/ID. progress (may be empty) receives the job's own progress lines.
nlohmann::json sweep_run_job(const SweepJob& job, const std::string& dir,
                             const std::function<void(const std::string&)>& progress = {});

/// Runs the jobs of shard `shard` of `shards` (job k when k % shards == shard) into dir, skipping
/// jobs whose output exists (resumption), on `threads` threads of this process (each job is
/// deterministic and MPFR's precision is per thread, so the outputs do not depend on the threads);
/// progress on stderr. Returns the counts. A job that throws is reported on stderr at once and
/// leaves no output; the others go on, and the run then throws DomainError naming the failed jobs
/// (a rerun retries only them).
struct SweepRunStats {
  std::size_t run = 0, skipped = 0, in_shard = 0;
  std::vector<std::pair<std::string, std::string>> failed;  // job id, why
};
SweepRunStats sweep_run(const std::vector<SweepJob>& jobs, const std::string& dir, std::size_t shard, std::size_t shards, bool progress = true,
                        std::size_t threads = 1);

/// The merge: every job's output read from dir (a missing one is a typed error naming the jobs),
/// then the sweep's files written into out_dir. Returns false when the sweep's own checks fail (as
/// in the report: a proof not as expected, gaps in untrimming), true otherwise.
bool sweep_merge(const std::vector<SweepJob>& jobs, const std::string& dir, const std::string& out_dir);

/// What `splinex sweep` prints: the plan as JSON lines (one job each), and one line after a run
/// (the shard and its counts), a merge or a single run (whether the sweep's checks passed).
std::string sweep_plan_lines(const std::vector<SweepJob>& jobs);
nlohmann::json sweep_run_document(const SweepRunStats& st, std::size_t shard, std::size_t shards, const std::string& dir);
nlohmann::json sweep_merge_document(std::size_t jobs, const std::string& merged_into, bool checks_passed);
nlohmann::json sweep_single_document(const std::string& out, bool checks_passed);

/// The single-process run of a plan (what the report does), into out_dir; returns as sweep_merge.
bool sweep_single(const std::string& name, const SweepPlanOptions& options, const std::string& out_dir,
                  const std::function<void(const std::string&)>& progress);

}  // namespace splinex
