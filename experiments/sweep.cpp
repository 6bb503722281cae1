#include "experiments/sweep.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <new>
#include <utility>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "base/errors.hpp"
#include "base/parallel.hpp"
#include "experiments/report.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/untrim_tolerance.hpp"
#include "io/output_path.hpp"
#include "proofs/suite.hpp"

namespace splinex {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kMaxSweepJobs = 1000000;  // lines of one jobs.jsonl, and jobs of one plan

std::string eps_text(double e) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", e);
  return b;
}

// A positive finite double from decimal text (the nearest double, as a literal in the source is).
double positive_double(const std::string& text, const std::string& field) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || !(v > 0))
    throw UsageError(field, "'" + text + "' is not a positive number", "give e.g. 1e-3");
  return v;
}

int int_in(const std::string& text, const std::string& field, int lo, int hi) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || v < lo || v > hi)
    throw UsageError(field, "'" + text + "' is not an integer in " + std::to_string(lo) + ".." + std::to_string(hi), "give one in that range");
  return static_cast<int>(v);
}

std::vector<std::string> split(const std::string& s, char c) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, c)) out.push_back(cur);
  if (!s.empty() && s.back() == c) out.push_back("");
  return out;
}

UntrimToleranceOptions untrim_options(const SweepPlanOptions& o) {
  UntrimToleranceOptions u = o.full ? full_untrim_tolerance_options("") : UntrimToleranceOptions{};
  if (!o.eps.empty()) {
    u.eps.clear();
    for (const auto& t : split(o.eps, ',')) u.eps.push_back(positive_double(t, "eps"));
    if (u.eps.size() > 100) throw UsageError("eps", "has more than 100 tolerances", "give fewer");
  }
  if (!o.runs.empty()) {
    u.runs.clear();
    for (const auto& t : split(o.runs, ',')) {
      const auto f = split(t, ':');
      if (f.size() != 3) throw UsageError("runs", "'" + t + "' is not bits:min_eps:max_m", "give e.g. 0:1e-6:4 (double) or 113:1e-5:1 (MPFR)");
      const int bits = int_in(f[0], "runs", 0, 4096);
      if (bits == 1) throw UsageError("runs", "1 bit is no MPFR precision", "give 0 (double) or 2..4096 bits");
      u.runs.push_back({bits, positive_double(f[1], "runs"), int_in(f[2], "runs", 1, 4)});
    }
    if (u.runs.size() > 20) throw UsageError("runs", "has more than 20 runs", "give fewer");
  }
  return u;
}

// The report sweep's sections: the named ones (comma-separated), or every section.
std::vector<std::string> report_sections(const SweepPlanOptions& o) {
  if (o.sections.empty()) return report_section_names();
  const auto names = split(o.sections, ',');
  report_tasks(names);  // unknown names and composition-orders alone are typed errors
  std::vector<std::string> ordered;  // in the report's order, each once
  for (const auto& n : report_section_names())
    if (std::find(names.begin(), names.end(), n) != names.end()) ordered.push_back(n);
  return ordered;
}

// The report's options for a sweep of it: sections alone, on one core (the engines run the jobs
// side by side).
ReportOptions report_options(const std::string& out_dir, bool full, std::vector<std::string> sections) {
  ReportOptions o;
  o.out_dir = out_dir;
  o.full = full;
  o.sections = std::move(sections);
  o.jobs = 1;
  return o;
}

// The folder a report task writes its files into, beside its result.
std::string report_task_dir(const SweepJob& job, const std::string& dir) {
  return (std::filesystem::path(dir) / "report" / job.id).string();
}

std::size_t proof_cases(const SweepPlanOptions& o) {
  const long n = o.cases.value_or(200);
  if (n < 1 || n > 100000) throw UsageError("cases", std::to_string(n) + " is outside [1, 100000]", "give --cases N with 1 <= N <= 100000");
  return static_cast<std::size_t>(n);
}

std::size_t proof_cases_per_job(const SweepPlanOptions& o) {
  const long k = o.cases_per_job.value_or(25);
  if (k < 1 || k > 100000)
    throw UsageError("cases-per-job", std::to_string(k) + " is outside [1, 100000]", "give --cases-per-job K with 1 <= K <= 100000");
  return static_cast<std::size_t>(k);
}

// The proofs a plan runs, in the registry's order: every one, or those named by --proofs (each
// known, none twice).
std::vector<const ProofEntry*> planned_proofs(const SweepPlanOptions& o) {
  std::vector<const ProofEntry*> out;
  if (o.proofs.empty()) {
    for (const auto& e : proof_registry()) out.push_back(&e);
    return out;
  }
  std::vector<std::string> names;
  std::stringstream ss(o.proofs);
  for (std::string n; std::getline(ss, n, ',');) {
    if (!find_proof(n)) throw UsageError("proofs", "'" + n + "' is not a proof", "give names that splinex prove --list prints, separated by commas");
    if (std::find(names.begin(), names.end(), n) != names.end()) throw UsageError("proofs", "'" + n + "' is named twice", "name each proof once");
    names.push_back(n);
  }
  for (const auto& e : proof_registry())
    if (std::find(names.begin(), names.end(), e.name) != names.end()) out.push_back(&e);
  return out;
}

const ProofEntry& proof_entry(const std::string& name) {
  if (const ProofEntry* e = find_proof(name)) return *e;
  throw UsageError("jobs", "'" + name + "' is not a proof of this splinex", "plan the sweep again with this splinex");
}

// The proofs' merged files: proofs.json (what `splinex prove --json --cases N` prints) and proofs.md;
// true when every verdict is as expected.
bool merge_proofs(const std::vector<Json>& rows, std::size_t cases, const std::string& out_dir) {
  bool ok = true;
  Json all = Json::array();
  std::ostringstream table;
  for (const auto& r : rows) {
    all.push_back(r);
    ok = ok && r.at("as_expected").get<bool>();
    table << "| " << r.at("name").get<std::string>() << " | " << r.at("verdict").get<std::string>() << (r.at("as_expected").get<bool>() ? "" : " (NOT AS EXPECTED)")
          << " | " << r.at("expected").get<std::string>() << " | " << r.at("cases").get<std::size_t>() << " | " << r.at("cells").get<std::size_t>() << " | "
          << r.at("points").get<std::size_t>() << " |\n";
  }
  write_file_atomically(out_dir + "/proofs.json", all.dump(2) + "\n");
  write_file_atomically(out_dir + "/proofs.md", ReportTemplate("sweep.proofs").set("cases", cases).set("rows", table.str()).render());
  return ok;
}

void no_report_options(const SweepPlanOptions& o, const std::string& name) {
  if (!o.sections.empty()) throw UsageError("sections", "is an option of report, not of " + name, "give it to sweep plan report");
}

void no_untrim_options(const SweepPlanOptions& o, const std::string& name) {
  no_report_options(o, name);
  if (o.full || !o.eps.empty() || !o.runs.empty())
    throw UsageError("sweep", "--full, --eps and --runs are options of untrim-tolerance, not of " + name, "give --cases for proofs");
}

void no_proof_options(const SweepPlanOptions& o, const std::string& name) {
  if (o.cases) throw UsageError("cases", "is an option of proofs, not of " + name, "give it to sweep plan proofs");
  if (o.cases_per_job) throw UsageError("cases-per-job", "is an option of proofs, not of " + name, "give it to sweep plan proofs");
  if (!o.proofs.empty()) throw UsageError("proofs", "is an option of proofs, not of " + name, "give it to sweep plan proofs");
}

// The options that give a plan (the inverse of sweep_plan on its plan documents): re-planning with
// them must give the same plan, which read_sweep_jobs checks.
SweepPlanOptions plan_options(const std::string& sweep, const Json& plan) {
  SweepPlanOptions o;
  const auto join = [](const std::vector<std::string>& v) {
    std::string t;
    for (const auto& x : v) t += (t.empty() ? "" : ",") + x;
    return t;
  };
  const auto exact = [](double v) {  // decimal text that strtod reads back as v
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  if (sweep == "proofs") {
    o.cases = plan.at("cases").get<long>();
    o.cases_per_job = plan.at("cases_per_job").get<long>();
    if (plan.contains("proofs")) {
      o.proofs = join(plan.at("proofs").get<std::vector<std::string>>());
      if (o.proofs.empty()) throw ParseError("proofs", "is empty", "plan the sweep again");
    }
  } else if (sweep == "report") {
    o.full = plan.at("full").get<bool>();
    o.sections = join(plan.at("sections").get<std::vector<std::string>>());
    if (o.sections.empty()) throw ParseError("sections", "is empty", "plan the sweep again");
  } else {
    const auto u = untrim_tolerance_options_from_json(plan);
    const auto full = full_untrim_tolerance_options("");
    o.full = u.max_control_points == full.max_control_points && u.max_boundary_samples == full.max_boundary_samples;
    std::vector<std::string> eps, runs;
    for (double e : u.eps) eps.push_back(exact(e));
    for (const auto& r : u.runs) runs.push_back(std::to_string(r.bits) + ":" + exact(r.min_eps) + ":" + std::to_string(r.max_m));
    o.eps = join(eps), o.runs = join(runs);
    if (o.eps.empty() || o.runs.empty()) throw ParseError("plan", "has no tolerances or no runs", "plan the sweep again");
  }
  return o;
}

// An existing output of `job`: its result, after checking that it is this job's under this plan
// (a folder reused for another plan must not be merged or skipped silently).
Json read_result(const SweepJob& job, const std::filesystem::path& p) {
  std::ifstream in(p);
  Json r;
  try {
    in >> r;
  } catch (const Json::parse_error&) {
    throw ParseError(job.output, "is not a job result (not JSON)", "delete it and run the job again (sweep run skips only finished jobs)");
  }
  if (!r.is_object() || r.value("id", std::string()) != job.id || !r.contains("result") || !r.contains("plan") || r["plan"] != job.plan ||
      r.value("params", Json()) != job.params)
    throw ParseError(job.output, "is not the result of job " + job.id + " under this plan", "give another --dir, or delete the folder's results of the other plan");
  return r;
}

}  // namespace

std::vector<std::string> sweep_names() { return {"untrim-tolerance", "proofs", "report"}; }

std::vector<SweepJob> sweep_plan(const std::string& name, const SweepPlanOptions& options) {
  const auto names = sweep_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw UsageError("sweep", "'" + name + "' is not a sweep that can be planned", "give one of " + list);
  }
  if (name == "proofs") {
    no_untrim_options(options, name);
    const std::size_t cases = proof_cases(options);
    const std::size_t per_job = proof_cases_per_job(options);
    const auto proofs = planned_proofs(options);
    std::size_t count = 0;  // the jobs, counted before they are made
    for (const ProofEntry* e : proofs) count += e->fixed_cases ? 1 : (cases + per_job - 1) / per_job;
    if (count > kMaxSweepJobs)
      throw SizeLimitError("cases-per-job", std::to_string(cases) + " cases in ranges of " + std::to_string(per_job) + " make " + std::to_string(count) +
                                                " jobs, more than " + std::to_string(kMaxSweepJobs),
                           "give a larger --cases-per-job");
    std::vector<SweepJob> jobs;
    Json plan = {{"cases", cases}, {"cases_per_job", per_job}};
    if (!options.proofs.empty()) {  // only when named, so that the plans of every proof stay as they were
      plan["proofs"] = Json::array();
      for (const ProofEntry* e : proofs) plan["proofs"].push_back(e->name);
    }
    for (const ProofEntry* ep : proofs) {
      const ProofEntry& e = *ep;
      // ranges [first, first + count) of the proof's cases; one job when they all fit (or the
      // proof's cases are its own)
      const std::size_t step = e.fixed_cases ? cases : per_job;
      for (std::size_t first = 0; first < cases; first += step) {
        const std::size_t count = std::min(step, cases - first);
        SweepJob j;
        j.sweep = name;
        j.id = count == cases ? e.name : e.name + ".cases" + std::to_string(first) + "-" + std::to_string(first + count - 1);
        j.params = {{"name", e.name}, {"first", first}, {"count", count}};
        j.plan = plan;
        j.output = name + "/" + j.id + ".json";
        jobs.push_back(std::move(j));
      }
    }
    return jobs;
  }
  if (name == "report") {
    if (options.cases || options.cases_per_job || !options.proofs.empty() || !options.eps.empty() || !options.runs.empty())
      throw UsageError("sweep", "--cases, --cases-per-job, --proofs, --eps and --runs are not options of report", "give --full and --sections");
    const auto sections = report_sections(options);
    std::vector<SweepJob> jobs;
    for (const auto& task : report_tasks(sections)) {
      SweepJob j;
      j.sweep = name;
      for (const auto& t : task) j.id += (j.id.empty() ? "" : "+") + t;
      j.params = {{"sections", task}};
      j.plan = {{"full", options.full}, {"sections", sections}};
      j.output = name + "/" + j.id + ".json";
      jobs.push_back(std::move(j));
    }
    return jobs;
  }
  no_report_options(options, name);
  no_proof_options(options, name);
  const auto u = untrim_options(options);
  const Json plan = untrim_tolerance_options_json(u);
  std::vector<SweepJob> jobs;
  for (const auto& c : untrim_tolerance_cases(u)) {
    SweepJob j;
    j.sweep = name;
    std::ostringstream id;  // e.g. m2-mpfr113-eps1e-05
    id << "m" << c.m << "-" << (c.bits == 0 ? std::string("double") : "mpfr" + std::to_string(c.bits)) << "-eps" << eps_text(c.eps);
    j.id = id.str();
    j.params = {{"m", c.m}, {"bits", c.bits}, {"eps", c.eps}};
    j.plan = plan;
    j.output = name + "/" + j.id + ".json";
    jobs.push_back(std::move(j));
  }
  return jobs;
}

Json sweep_job_json(const SweepJob& j) {
  return {{"sweep", j.sweep}, {"id", j.id}, {"params", j.params}, {"plan", j.plan}, {"output", j.output},
          {"command", Json::array({"splinex", "sweep", "run", "--jobs", "JOBS.jsonl", "--only", j.id, "--dir", "DIR"})}};
}

std::string sweep_plan_lines(const std::vector<SweepJob>& jobs) {
  std::string out;
  for (const auto& j : jobs) out += sweep_job_json(j).dump() + "\n";
  return out;
}

Json sweep_run_document(const SweepRunStats& st, std::size_t shard, std::size_t shards, const std::string& dir) {
  return {{"shard", std::to_string(shard) + "/" + std::to_string(shards)}, {"jobs_in_shard", st.in_shard}, {"run", st.run}, {"skipped", st.skipped}, {"dir", dir}};
}

Json sweep_merge_document(std::size_t jobs, const std::string& merged_into, bool checks_passed) {
  return {{"jobs", jobs}, {"merged_into", merged_into}, {"checks", checks_passed ? "passed" : "FAILED"}};
}

Json sweep_single_document(const std::string& out, bool checks_passed) {
  return {{"out", out}, {"checks", checks_passed ? "passed" : "FAILED"}};
}

SweepJob sweep_job_from_json(const Json& j, const std::string& where) {
  if (!j.is_object()) throw ParseError(where, "is not a JSON object", "give one job per line, as sweep plan writes them");
  SweepJob s;
  for (const char* f : {"sweep", "id", "output"})
    if (!j.contains(f) || !j[f].is_string()) throw ParseError(where + "." + f, "is missing or not a string", "give the job as sweep plan writes it");
  for (const char* f : {"params", "plan"})
    if (!j.contains(f) || !j[f].is_object()) throw ParseError(where + "." + f, "is missing or not an object", "give the job as sweep plan writes it");
  s.sweep = j["sweep"].get<std::string>(), s.id = j["id"].get<std::string>(), s.output = j["output"].get<std::string>();
  s.params = j["params"], s.plan = j["plan"];
  const auto names = sweep_names();
  if (std::find(names.begin(), names.end(), s.sweep) == names.end()) throw ParseError(where + ".sweep", "'" + s.sweep + "' is not a sweep", "give a job of sweep plan");
  const std::filesystem::path out(s.output);
  if (s.output.empty() || out.is_absolute() || s.output.find("..") != std::string::npos)
    throw ParseError(where + ".output", "'" + s.output + "' is not a relative path inside the run's folder", "give the job as sweep plan writes it");
  return s;
}

std::vector<SweepJob> read_sweep_jobs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError("jobs", "cannot read '" + path + "'", "give the file sweep plan wrote");
  std::vector<SweepJob> jobs;
  std::vector<std::size_t> line_of;  // the line of every job, for the errors
  std::set<std::string> ids;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "jobs line " + std::to_string(n);
    Json j;
    try {
      j = Json::parse(line);
    } catch (const Json::parse_error& e) {
      throw ParseError(where, "is not JSON", "give one job per line, as sweep plan writes them");
    }
    auto s = sweep_job_from_json(j, where);
    if (!ids.insert(s.id).second) throw ParseError(where + ".id", "'" + s.id + "' appears twice", "give each job once");
    if (!jobs.empty() && (s.sweep != jobs.front().sweep || s.plan != jobs.front().plan))
      throw ParseError(where, "belongs to another sweep or plan than line 1", "give the lines of one sweep plan");
    jobs.push_back(std::move(s));
    line_of.push_back(n);
    if (jobs.size() > kMaxSweepJobs) throw SizeLimitError("jobs", "has more than " + std::to_string(kMaxSweepJobs) + " jobs", "split the plan");
  }
  if (jobs.empty()) throw ParseError("jobs", "'" + path + "' has no jobs", "give the file sweep plan wrote");
  // Every line must be a job that sweep plan writes for its plan, exactly: a hand-edited or foreign
  // line (an id naming a folder outside DIR, a range of 10^12 cases, a proof this splinex lacks) is
  // an error before any work, not a job that runs.
  std::vector<SweepJob> planned;
  try {
    planned = sweep_plan(jobs.front().sweep, plan_options(jobs.front().sweep, jobs.front().plan));
  } catch (const Error& e) {
    throw ParseError("jobs line 1.plan", std::string("is not a plan that this splinex writes: ") + e.what(), "plan the sweep again with this splinex");
  } catch (const Json::exception& e) {
    throw ParseError("jobs line 1.plan", std::string("is not a plan that this splinex writes: ") + e.what(), "plan the sweep again with this splinex");
  }
  if (planned.empty() || planned.front().plan != jobs.front().plan)
    throw ParseError("jobs line 1.plan", "is not a plan that this splinex writes", "plan the sweep again with this splinex");
  std::map<std::string, const SweepJob*> by_id;
  for (const auto& j : planned) by_id.emplace(j.id, &j);
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const auto it = by_id.find(jobs[k].id);
    if (it == by_id.end() || it->second->params != jobs[k].params || it->second->output != jobs[k].output)
      throw ParseError("jobs line " + std::to_string(line_of[k]), "'" + jobs[k].id + "' is not a job of its plan (sweep plan does not write it so)",
                       "give the lines sweep plan wrote, unedited, or plan the sweep again");
  }
  return jobs;
}

Json sweep_run_job(const SweepJob& job, const std::string& dir, const std::function<void(const std::string&)>& progress) {
  if (job.sweep == "report") {
    const auto o = report_options(report_task_dir(job, dir), job.plan.at("full").get<bool>(), job.plan.at("sections").get<std::vector<std::string>>());
    const auto task = job.params.at("sections").get<std::vector<std::string>>();
    std::filesystem::remove_all(o.out_dir);  // the files of an interrupted attempt
    const auto r = run_report_task(o, task, [&](const std::string& s) {
      if (progress) progress("[" + job.id + "] " + s);
    });
    return {{"sweep", job.sweep}, {"id", job.id}, {"params", job.params}, {"plan", job.plan}, {"result", r}};
  }
  if (job.sweep == "proofs") {
    const auto& e = proof_entry(job.params.at("name").get<std::string>());
    const auto r = e.run_range(job.params.at("first").get<std::size_t>(), job.params.at("count").get<std::size_t>());
    return {{"sweep", job.sweep}, {"id", job.id}, {"params", job.params}, {"plan", job.plan}, {"result", proof_range_json(r)}};
  }
  // untrim-tolerance
  const auto u = untrim_tolerance_options_from_json(job.plan);
  UntrimCase c;
  c.m = job.params.at("m").get<int>(), c.bits = job.params.at("bits").get<int>(), c.eps = job.params.at("eps").get<double>();
  return {{"sweep", job.sweep}, {"id", job.id}, {"params", job.params}, {"plan", job.plan}, {"result", untrim_tolerance_case(c, u)}};
}

SweepRunStats sweep_run(const std::vector<SweepJob>& jobs, const std::string& dir, std::size_t shard, std::size_t shards, bool progress,
                        std::size_t threads) {
  if (shards == 0 || shard >= shards) throw UsageError("shard", std::to_string(shard) + "/" + std::to_string(shards) + " is no shard", "give I/N with 0 <= I < N");
  if (threads == 0 || threads > 1024) throw UsageError("threads", std::to_string(threads) + " is outside 1..1024", "give e.g. the number of cores");
  prepare_output_folder(dir, "dir");
  std::vector<std::size_t> mine;
  for (std::size_t k = 0; k < jobs.size(); ++k)
    if (k % shards == shard) mine.push_back(k);
  SweepRunStats st;
  st.in_shard = mine.size();
  const auto t0 = std::chrono::steady_clock::now();
  std::mutex lock;  // st and the progress lines
  std::size_t done = 0;
  const std::function<void(const std::string&)> job_progress = [&](const std::string& line) {
    if (!progress) return;
    std::lock_guard<std::mutex> g(lock);
    std::cerr << line << "\n";
  };
  parallel_for(mine.size(), threads, [&](std::size_t slot) {
    const auto& job = jobs[mine[slot]];
    const std::filesystem::path out = std::filesystem::path(dir) / job.output;
    if (std::filesystem::exists(out)) {
      read_result(job, out);  // a result of another plan is an error, not a finished job
      std::lock_guard<std::mutex> g(lock);
      ++st.skipped, ++done;
      if (progress) std::cerr << "[sweep] " << done << "/" << st.in_shard << " " << job.id << ": done before, skipped\n";
      return;
    }
    try {
      const Json r = sweep_run_job(job, dir, job_progress);  // deterministic: the same result on any thread, process or machine
      std::filesystem::create_directories(out.parent_path());
      write_file_atomically(out.string(), r.dump() + "\n");
    } catch (const std::exception& e) {
      // One job's failure (memory, a limit, its output not writable, a bug) does not cost the
      // others their hours: it is reported now, leaves no output (a rerun retries it) and fails
      // the run at the end.
      const std::string why = dynamic_cast<const std::bad_alloc*>(&e) ? std::string("out of memory") : std::string(e.what());
      std::lock_guard<std::mutex> g(lock);
      ++done;
      st.failed.emplace_back(job.id, why);
      if (progress) std::cerr << "[sweep] " << done << "/" << st.in_shard << " " << job.id << ": FAILED: " << why << "\n";
      return;
    }
    std::lock_guard<std::mutex> g(lock);
    ++st.run, ++done;
    if (progress) {
      const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double left = el / static_cast<double>(st.run) * static_cast<double>(st.in_shard - done);
      std::cerr << "[sweep] " << done << "/" << st.in_shard << " " << job.id << " (shard " << shard << "/" << shards << "): elapsed "
                << eps_text(el) << " s, about " << eps_text(left) << " s left\n";
    }
  });
  if (!st.failed.empty()) {
    std::sort(st.failed.begin(), st.failed.end());
    std::string list;
    for (std::size_t k = 0; k < st.failed.size() && k < 5; ++k) list += (k ? "; " : "") + st.failed[k].first + " (" + st.failed[k].second + ")";
    if (st.failed.size() > 5) list += " and " + std::to_string(st.failed.size() - 5) + " more";
    throw DomainError("jobs", std::to_string(st.failed.size()) + " of " + std::to_string(st.in_shard) + " jobs of shard " +
                                  std::to_string(shard) + "/" + std::to_string(shards) + " failed (the others finished): " + list,
                      "mend the cause (e.g. fewer --threads for memory) and run sweep run again: finished jobs are skipped");
  }
  return st;
}

bool sweep_merge(const std::vector<SweepJob>& jobs, const std::string& dir, const std::string& out_dir) {
  prepare_output_folder(out_dir, "out");
  std::vector<Json> rows;
  std::vector<std::string> missing;
  for (const auto& job : jobs) {
    const std::filesystem::path p = std::filesystem::path(dir) / job.output;
    if (!std::filesystem::exists(p)) {
      missing.push_back(job.id);
      continue;
    }
    rows.push_back(read_result(job, p)["result"]);
  }
  if (!missing.empty()) {
    std::string list;
    for (std::size_t k = 0; k < missing.size() && k < 10; ++k) list += (k ? ", " : "") + missing[k];
    if (missing.size() > 10) list += " and " + std::to_string(missing.size() - 10) + " more";
    throw DomainError("jobs", std::to_string(missing.size()) + " of " + std::to_string(jobs.size()) + " jobs have no output in '" + dir + "': " + list,
                      "run sweep run for their shards (finished jobs are skipped)");
  }
  std::filesystem::create_directories(out_dir);
  if (jobs.front().sweep == "report") {
    auto o = report_options(out_dir, jobs.front().plan.at("full").get<bool>(), jobs.front().plan.at("sections").get<std::vector<std::string>>());
    o.command = "splinex sweep merge --dir " + dir + " --out " + out_dir + " (the jobs of sweep plan report)";
    std::vector<std::string> dirs;
    for (const auto& job : jobs) dirs.push_back(report_task_dir(job, dir));
    return merge_report_tasks(o, rows, dirs, [](const std::string& s) { std::cerr << "[sweep merge] " << s << "\n"; }) == 0;
  }
  if (jobs.front().sweep == "proofs") {
    // every proof's ranges in case order, merged into its report; the proofs in the registry's
    // order (as prove --json lists them), whatever the order of the lines in jobs.jsonl
    std::map<std::string, std::vector<std::pair<std::size_t, ProofReport>>> ranges;
    for (std::size_t k = 0; k < jobs.size(); ++k) {
      const auto& e = proof_entry(jobs[k].params.at("name").get<std::string>());
      ranges[e.name].emplace_back(jobs[k].params.at("first").get<std::size_t>(), proof_range_from_json(e, rows[k]));
    }
    std::vector<Json> reports;
    for (const auto& e : proof_registry()) {
      auto it = ranges.find(e.name);
      if (it == ranges.end()) continue;
      std::sort(it->second.begin(), it->second.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      try {
        reports.push_back(proof_report_json(merge_proof_ranges(e, it->second)));
      } catch (const std::logic_error& x) {
        throw DomainError("jobs", x.what(), "plan the sweep again with sweep plan proofs");
      }
    }
    return merge_proofs(reports, jobs.front().plan.at("cases").get<std::size_t>(), out_dir);
  }
  auto u = untrim_tolerance_options_from_json(jobs.front().plan);
  u.out_dir = out_dir;
  bool ok = true;
  untrim_tolerance_merge(rows, u, ok);
  return ok;
}

bool sweep_single(const std::string& name, const SweepPlanOptions& options, const std::string& out_dir,
                  const std::function<void(const std::string&)>& progress) {
  sweep_plan(name, options);  // the name's and the options' errors
  prepare_output_folder(out_dir, "out");  // before the work, not after it
  if (name == "report") {
    auto o = report_options(out_dir, options.full, report_sections(options));
    o.command = "splinex sweep single report --out " + out_dir + (options.full ? " --full" : "");
    return run_report(o) == 0;
  }
  if (name == "proofs") {
    const std::size_t cases = proof_cases(options);
    std::vector<Json> rows;
    for (const ProofEntry* e : planned_proofs(options)) {
      progress("proof " + e->name);
      rows.push_back(proof_report_json(e->run(cases)));
    }
    std::filesystem::create_directories(out_dir);
    return merge_proofs(rows, cases, out_dir);
  }
  auto u = untrim_options(options);
  u.out_dir = out_dir;
  std::filesystem::create_directories(out_dir);
  bool ok = true;
  run_untrim_tolerance(u, progress, ok);
  return ok;
}

}  // namespace splinex
