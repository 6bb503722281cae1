// splinex sweep plan|run|merge|single: long sweeps as independent jobs (experiments/sweep.hpp).
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "base/errors.hpp"
#include "experiments/sweep.hpp"

namespace splinex::app {

namespace {

std::pair<std::size_t, std::size_t> parse_shard(const std::string& s) {
  const auto slash = s.find('/');
  auto num = [&](const std::string& t) -> long {
    // digits only: no sign, no blanks (strtol would skip leading ones and not trailing ones)
    if (t.empty() || t.size() > 7 || t.find_first_not_of("0123456789") != std::string::npos) return -1;
    const long v = std::stol(t);
    return v > 1000000 ? -1 : v;
  };
  const long i = slash == std::string::npos ? -1 : num(s.substr(0, slash)), n = slash == std::string::npos ? -1 : num(s.substr(slash + 1));
  if (i < 0 || n < 1 || i >= n) throw UsageError("shard", "'" + s + "' is not I/N with 0 <= I < N", "give e.g. 0/4 (the first of four shards)");
  return {static_cast<std::size_t>(i), static_cast<std::size_t>(n)};
}

}  // namespace

Commands add_sweep(CLI::App& app) {
  auto* sw = app.add_subcommand("sweep", "long sweeps as independent jobs: plan them, run shards anywhere (GNU parallel, Slurm arrays), merge");
  sw->require_subcommand(1);

  auto po = std::make_shared<SweepPlanOptions>();
  auto pname = std::make_shared<std::string>();
  auto* pl = sw->add_subcommand("plan", "write the sweep's jobs, one JSON line each (the command and the output file), to stdout");
  pl->add_option("name", *pname, "the sweep: untrim-tolerance, proofs or report")->required();
  pl->add_option("--cases", po->cases, "proofs: random exact cases per proof (default 200)");
  pl->add_option("--cases-per-job", po->cases_per_job, "proofs: cases of one proof per job (default 25)");
  pl->add_option("--proofs", po->proofs, "proofs: comma-separated proof names (default: every proof; splinex prove --list)");
  pl->add_flag("--full", po->full, "the long sweep (report --full's options)");
  pl->add_option("--sections", po->sections, "report: comma-separated sections (default: all), one job each");
  pl->add_option("--eps", po->eps, "untrim-tolerance: comma-separated tolerances instead of the defaults");
  pl->add_option("--runs", po->runs, "untrim-tolerance: comma-separated bits:min_eps:max_m (bits 0: double) instead of the defaults");

  struct RunOptions {
    std::string jobs, dir = "sweep", shard = "0/1", only;
    bool quiet = false;
    int threads = 1;
  };
  auto ro = std::make_shared<RunOptions>();
  auto* rn = sw->add_subcommand("run", "run shard I of N of a plan's jobs (job k when k mod N = I); finished jobs are skipped, so a run resumes");
  rn->add_option("--jobs", ro->jobs, "the plan (jobs.jsonl)")->required();
  rn->add_option("--dir", ro->dir, "folder of the jobs' outputs")->check(output_folder())->capture_default_str();
  rn->add_option("--shard", ro->shard, "I/N")->capture_default_str();
  rn->add_option("--only", ro->only, "run only the job with this id");
  rn->add_flag("--quiet", ro->quiet, "no progress on stderr");
  rn->add_option("--threads", ro->threads, "jobs run at once in this process (the outputs do not depend on it)")->check(CLI::Range(1, 1024))->capture_default_str();

  struct MergeOptions {
    std::string jobs, dir, out;
  };
  auto mo = std::make_shared<MergeOptions>();
  auto* mg = sw->add_subcommand("merge", "check that every job finished, merge the outputs, refit and redraw (the single run's files)");
  mg->add_option("--jobs", mo->jobs, "the plan (jobs.jsonl)")->required();
  mg->add_option("dir", mo->dir, "folder of the jobs' outputs")->required();
  mg->add_option("--out", mo->out, "folder for the merged files (default: DIR)")->check(output_folder());

  auto so = std::make_shared<SweepPlanOptions>();
  auto sname = std::make_shared<std::string>();
  auto sout = std::make_shared<std::string>();
  auto* sg = sw->add_subcommand("single", "the sweep in one process, as the report runs it (the reference for the merge)");
  sg->add_option("name", *sname, "the sweep: untrim-tolerance, proofs or report")->required();
  sg->add_option("--cases", so->cases, "as for plan");
  sg->add_option("--cases-per-job", so->cases_per_job, "as for plan (the single run does not split)");
  sg->add_option("--proofs", so->proofs, "as for plan");
  sg->add_flag("--full", so->full, "the long sweep");
  sg->add_option("--eps", so->eps, "as for plan");
  sg->add_option("--runs", so->runs, "as for plan");
  sg->add_option("--sections", so->sections, "as for plan");
  sg->add_option("--out", *sout, "folder for the files")->check(output_folder())->required();

  return {{pl, [po, pname](const Context&) {
             std::cout << sweep_plan_lines(sweep_plan(*pname, *po));
             return 0;
           }},
          {rn, [ro](const Context&) {
             auto jobs = read_sweep_jobs(ro->jobs);
             auto [i, n] = parse_shard(ro->shard);
             if (!ro->only.empty()) {
               std::vector<SweepJob> one;
               for (const auto& j : jobs)
                 if (j.id == ro->only) one.push_back(j);
               if (one.empty()) throw UsageError("only", "'" + ro->only + "' is no job of the plan", "give an id from the jobs file");
               jobs = one, i = 0, n = 1;
             }
             const auto st = sweep_run(jobs, ro->dir, i, n, !ro->quiet, static_cast<std::size_t>(ro->threads));
             print_document(sweep_run_document(st, i, n, ro->dir));
             return 0;
           }},
          {mg, [mo](const Context&) {
             const auto jobs = read_sweep_jobs(mo->jobs);
             const bool ok = sweep_merge(jobs, mo->dir, mo->out.empty() ? mo->dir : mo->out);
             print_document(sweep_merge_document(jobs.size(), mo->out.empty() ? mo->dir : mo->out, ok));
             return ok ? 0 : 1;
           }},
          {sg, [so, sname, sout](const Context&) {
             const bool ok = sweep_single(*sname, *so, *sout, [](const std::string& s) { std::cerr << "[sweep single] " << s << "\n"; });
             print_document(sweep_single_document(*sout, ok));
             return ok ? 0 : 1;
           }}};
}

}  // namespace splinex::app
