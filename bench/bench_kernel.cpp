// Kernel timings in double, MPFR(128) and exact arithmetic (Google Benchmark): "exact" is the
// fraction-free kernel (exact/ffnet.hpp), "gmp" and "flint" the naive exact engines (one mpq / fmpq
// per coefficient, the generic kernel); followed by a table of time ratios to double. Inputs: random clamped curves with dyadic knots and
// coordinates (k/1024), the case the target names; pass --decimal for k/1000 data.
//
//   build/bin/bench_kernel                      all operations, degrees 1,3,5,7, n = 10..10000
//   build/bin/bench_kernel --benchmark_filter=insert   (any Google Benchmark flag works)
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <type_traits>

#ifdef SPLINEX_HAVE_SISL
#define SISLNEEDPROTOTYPES
#include <sisl.h>
#endif
#ifdef SPLINEX_HAVE_OCCT
#include <Geom_BSplineCurve.hxx>
#include <GeomConvert_BSplineCurveToBezierCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Pnt.hxx>
#endif

#include "bench/memory_probe.hpp"
#include "bench/ratio_reporter.hpp"
#include <flint/fmpz_vec.h>

#include "exact/ffnet.hpp"
#include "exact/flint_rational.hpp"
#include "fixtures/random_spline.hpp"
#include "io/json_io.hpp"
#include "float/mpfr.hpp"
#include "spline/kernel.hpp"

using namespace splinex;

namespace {

bool g_dyadic = true;

struct Case {
  BSpline<Rational> exact;
  Rational knot;                 // one knot to insert (dyadic)
  std::vector<Rational> refine;  // n/10 knots to insert at once
  std::vector<Rational> at;      // evaluation parameters
};

const Case& get_case(int p, std::size_t n) {
  static std::map<std::pair<int, std::size_t>, Case> cache;
  auto key = std::make_pair(p, n);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  std::mt19937_64 rng(1000 * p + n);
  RandomSplineSpec spec;
  spec.degrees = {p};
  spec.counts = {n};
  spec.q = 3;
  spec.dyadic = g_dyadic;
  spec.max_interior_multiplicity = 1;
  Case c;
  c.exact = random_spline(spec, rng);
  c.knot = random_inside(0, 1, rng, g_dyadic);
  // Refinement knots on a grid fine enough (2^-20 or 10^-6) that n/10 of them rarely repeat;
  // repeats beyond the degree are skipped so the input is always valid.
  const long fine = g_dyadic ? (1L << 20) : 1000000L;
  std::map<long, int> used;
  for (std::size_t i = 0; i < std::max<std::size_t>(1, n / 10); ++i) {
    const long k = std::uniform_int_distribution<long>(1, fine - 1)(rng);
    if (++used[k] > p) continue;
    c.refine.emplace_back(k, fine);
  }
  for (int i = 0; i < 16; ++i) c.at.push_back(random_inside(0, 1, rng, g_dyadic));
  return cache.emplace(key, std::move(c)).first->second;
}

template <class T>
T conv(const Rational& x) {
  return ArithTraits<T>::from_rational(x);
}

template <class T>
struct Input {
  BSpline<T> S;
  T knot;
  std::vector<T> refine, at;
  Input(int p, std::size_t n) {
    const Case& c = get_case(p, n);
    S = convert<T>(c.exact, conv<T>);
    knot = conv<T>(c.knot);
    for (const auto& x : c.refine) refine.push_back(conv<T>(x));
    for (const auto& x : c.at) at.push_back(conv<T>(x));
  }
};

/// The memory counters of one more run of the case's operation (after the timing, which runs
/// with counting off): heap allocations per operation (per point for eval), the peak of the live
/// heap above its level before the operation, and the process's peak RSS during it.
template <class F>
void report_memory(benchmark::State& st, F&& once, long items) {
  if (!memprobe::available()) return;
  const memprobe::Usage u = memprobe::measure(once);
  st.counters["allocs"] = static_cast<double>(u.allocations);
  st.counters["allocs_per_item"] = static_cast<double>(u.allocations) / static_cast<double>(items);
  st.counters["heap_peak_kib"] = static_cast<double>(u.peak_heap) / 1024.0;
  if (u.peak_rss_kib >= 0) st.counters["rss_peak_mib"] = static_cast<double>(u.peak_rss_kib) / 1024.0;
}

/// Bytes one stored value takes: its own size plus what it holds on the heap (no allocator
/// overhead), counted as ff::heap_bytes counts the fraction-free net's, so the columns compare.
std::size_t value_bytes(const double&) { return sizeof(double); }
std::size_t value_bytes(const Rational& x) {
  const auto* q = x.backend().data();
  return sizeof(Rational) + static_cast<std::size_t>(mpq_numref(q)->_mp_alloc + mpq_denref(q)->_mp_alloc) * sizeof(mp_limb_t);
}
// FlintRational is one fmpq_t and standard-layout, so its address is the fmpq's.
static_assert(std::is_standard_layout_v<FlintRational> && sizeof(FlintRational) == sizeof(fmpq));
std::size_t value_bytes(const FlintRational& x) {
  const fmpq* v = reinterpret_cast<const fmpq*>(&x);
  std::size_t b = sizeof(fmpq);
  for (const fmpz* z : {fmpq_numref(v), fmpq_denref(v)})
    if (COEFF_IS_MPZ(*z)) b += sizeof(__mpz_struct) + static_cast<std::size_t>(COEFF_TO_PTR(*z)->_mp_alloc) * sizeof(mp_limb_t);
  return b;
}
template <class T>
constexpr bool kCountsBytes = std::is_same_v<T, double> || std::is_same_v<T, Rational> || std::is_same_v<T, FlintRational>;

/// The result's bytes per stored value (coordinates, weights and knots), as run_ff's counter.
template <class T>
double bytes_per_value(const BSpline<T>& R) {
  std::size_t bytes = 0, values = 0;
  auto add = [&](const std::vector<T>& v) {
    for (const auto& x : v) bytes += value_bytes(x);
    values += v.size();
  };
  add(R.points);
  add(R.weights);
  for (const auto& K : R.knots) add(K);
  return static_cast<double>(bytes) / static_cast<double>(values);
}

template <class T>
void run_op(benchmark::State& st, const std::string& op, int p, std::size_t n, long bits) {
  std::unique_ptr<Mpfr::Precision> scope;
  if (bits) scope = std::make_unique<Mpfr::Precision>(bits);
  Input<T> in(p, n);
  auto once = [&] {
    if (op == "insert") benchmark::DoNotOptimize(insert_knot(in.S, 0, in.knot, 1));
    else if (op == "refine") benchmark::DoNotOptimize(refine_knots(in.S, 0, in.refine));
    else if (op == "elevate") benchmark::DoNotOptimize(elevate_degree(in.S, 0, 1));
    else if (op == "extract") benchmark::DoNotOptimize(bezier_form(in.S));
    else if (op == "pieces") benchmark::DoNotOptimize(extract_bezier(in.S));
    else if (op == "eval") benchmark::DoNotOptimize(evaluate_points(in.S, in.at));
  };
  for (auto _ : st) once();
  const long items = static_cast<long>(op == "eval" ? in.at.size() : 1);
  st.SetItemsProcessed(st.iterations() * items);
  report_memory(st, once, items);
  if constexpr (kCountsBytes<T>)
    if (op == "insert" || op == "refine" || op == "elevate" || op == "extract")
      st.counters["bytes_per_coef"] = bytes_per_value(op == "insert"    ? insert_knot(in.S, 0, in.knot, 1)
                                                      : op == "refine"  ? refine_knots(in.S, 0, in.refine)
                                                      : op == "elevate" ? elevate_degree(in.S, 0, 1)
                                                                        : bezier_form(in.S).spline);
}

/// "exact": the fraction-free net (exact/ffnet.hpp, issue 49), converted from the exact case outside the
/// timed loop, as the double input is; `bytes_per_coef` is the
/// result's heap bytes per stored rational value (coordinates, weights and knots).
void run_ff(benchmark::State& st, const std::string& op, int p, std::size_t n) {
  const Case& c = get_case(p, n);
  const ff::FFNet F = ff::from_bspline(c.exact);
  auto once = [&] {
    if (op == "insert") benchmark::DoNotOptimize(ff::insert_knot(F, 0, c.knot, 1));
    else if (op == "refine") benchmark::DoNotOptimize(ff::refine_knots(F, 0, c.refine));
    else if (op == "elevate") benchmark::DoNotOptimize(ff::elevate_degree(F, 0, 1));
    else if (op == "extract") benchmark::DoNotOptimize(ff::bezier_form(F));
    else if (op == "pieces") benchmark::DoNotOptimize(ff::extract_bezier(F));
    else benchmark::DoNotOptimize(ff::evaluate_points(F, c.at));
  };
  for (auto _ : st) once();
  const long items = static_cast<long>(op == "eval" ? c.at.size() : 1);
  st.SetItemsProcessed(st.iterations() * items);
  report_memory(st, once, items);
  ff::promotions() = 0;
  once();
  st.counters["promotions"] = static_cast<double>(ff::promotions());  // small products that overflowed, one run
  if (op == "insert" || op == "refine" || op == "elevate" || op == "extract") {
    const ff::FFNet R = op == "insert"    ? ff::insert_knot(F, 0, c.knot, 1)
                        : op == "refine"  ? ff::refine_knots(F, 0, c.refine)
                        : op == "elevate" ? ff::elevate_degree(F, 0, 1)
                                          : ff::bezier_form(F).spline;
    const double values = static_cast<double>(R.size() * (R.q + (R.rational ? 1 : 0)) + R.knots[0].size());
    st.counters["bytes_per_coef"] = static_cast<double>(ff::heap_bytes(R)) / values;
    // The longest integer of the result (bits): past 62 the words hold FLINT's big integers.
    st.counters["max_bits"] = static_cast<double>(std::abs(_fmpz_vec_max_bits(R.words.data(), static_cast<slong>(R.words.size()))));
  }
}

#ifdef SPLINEX_HAVE_SISL
// SISL 4.6 (SINTEF): the same curve as a polynomial B-spline of order p+1 (kind 1), the same
// operations by s1017 (one knot), s1018 (several), s1750 (order + 1), s1730 (to Bezier form) and
// s1227 (value from the left). Each result is freed inside the timed loop, as splinex's is.
void run_sisl(benchmark::State& st, const std::string& op, int p, std::size_t n) {
  Input<double> in(p, n);
  SISLCurve* c = newCurve(static_cast<int>(n), p + 1, in.S.knots[0].data(), in.S.points.data(), 1, 3, 1);
  int stat = 0;
  std::vector<double> value(3);
  auto once = [&] {
    SISLCurve* r = nullptr;
    if (op == "insert") s1017(c, &r, in.knot, &stat);
    else if (op == "refine") s1018(c, in.refine.data(), static_cast<int>(in.refine.size()), &r, &stat);
    else if (op == "elevate") s1750(c, p + 2, &r, &stat);
    else if (op == "extract") s1730(c, &r, &stat);
    else if (op == "eval")
      for (const double x : in.at) {
        int left = 0;
        s1227(c, 0, x, &left, value.data(), &stat);
        benchmark::DoNotOptimize(value.data());
      }
    if (r) freeCurve(r);
  };
  for (auto _ : st) {
    once();
    if (stat < 0) {
      st.SkipWithError("SISL reported an error");
      break;
    }
  }
  const long items = static_cast<long>(op == "eval" ? in.at.size() : 1);
  st.SetItemsProcessed(st.iterations() * items);
  report_memory(st, once, items);
  freeCurve(c);
}
#endif

#ifdef SPLINEX_HAVE_OCCT
// OpenCASCADE 7.6: Geom_BSplineCurve has only in-place modifiers, so insert, refine and elevate
// copy the curve (Geom_Geometry::Copy) and modify the copy; extraction is
// GeomConvert_BSplineCurveToBezierCurve with every arc fetched; evaluation is D0.
void run_occt(benchmark::State& st, const std::string& op, int p, std::size_t n) {
  Input<double> in(p, n);
  const auto& U = in.S.knots[0];
  std::vector<double> kv;
  std::vector<int> mv;
  for (double u : U)
    if (!kv.empty() && kv.back() == u) ++mv.back();
    else { kv.push_back(u); mv.push_back(1); }
  TColgp_Array1OfPnt poles(1, static_cast<int>(n));
  for (std::size_t i = 0; i < n; ++i) poles(static_cast<int>(i) + 1) = gp_Pnt(in.S.points[3 * i], in.S.points[3 * i + 1], in.S.points[3 * i + 2]);
  TColStd_Array1OfReal knots(1, static_cast<int>(kv.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(kv.size()));
  for (std::size_t i = 0; i < kv.size(); ++i) { knots(static_cast<int>(i) + 1) = kv[i]; mults(static_cast<int>(i) + 1) = mv[i]; }
  Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, knots, mults, p);
  std::vector<double> rk = in.refine;
  std::sort(rk.begin(), rk.end());
  TColStd_Array1OfReal ins(1, static_cast<int>(rk.size()));
  TColStd_Array1OfInteger insm(1, static_cast<int>(rk.size()));
  for (std::size_t i = 0; i < rk.size(); ++i) { ins(static_cast<int>(i) + 1) = rk[i]; insm(static_cast<int>(i) + 1) = 1; }
  auto once = [&] {
    if (op == "insert" || op == "refine" || op == "elevate") {
      Handle(Geom_BSplineCurve) r = Handle(Geom_BSplineCurve)::DownCast(c->Copy());
      if (op == "insert") r->InsertKnot(in.knot, 1, 0.0);
      else if (op == "refine") r->InsertKnots(ins, insm, 0.0, Standard_True);
      else r->IncreaseDegree(p + 1);
      benchmark::DoNotOptimize(r.get());
    } else if (op == "extract") {
      GeomConvert_BSplineCurveToBezierCurve conv(c);
      for (int i = 1; i <= conv.NbArcs(); ++i) benchmark::DoNotOptimize(conv.Arc(i).get());
    } else {
      for (const double x : in.at) {
        gp_Pnt v;
        c->D0(x, v);
        benchmark::DoNotOptimize(v);
      }
    }
  };
  for (auto _ : st) once();
  const long items = static_cast<long>(op == "eval" ? in.at.size() : 1);
  st.SetItemsProcessed(st.iterations() * items);
  report_memory(st, once, items);
}
#endif

}  // namespace

// --write-cases DIR: the inputs of the insert and eval cases with splinex's exact results, one JSON
// document per (p, n), for the Python Fraction peer (scripts/bench_python.py), which checks its
// results against them before it times anything.
int write_cases(const std::string& dir, const std::vector<int>& degrees, const std::vector<std::size_t>& sizes) {
  for (int p : degrees)
    for (std::size_t n : sizes) {
      if (n < static_cast<std::size_t>(p) + 1) continue;
      const Case& c = get_case(p, n);
      Json at = Json::array(), values = Json::array();
      for (const auto& x : c.at) at.push_back(ArithTraits<Rational>::to_json(x));
      const auto all = evaluate_points(c.exact, c.at);
      for (const auto& v : all) values.push_back(ArithTraits<Rational>::to_json(v));
      const Json doc{{"p", p}, {"n", n}, {"spline", spline_to_json(c.exact)}, {"knot", ArithTraits<Rational>::to_json(c.knot)},
                     {"inserted", spline_to_json(insert_knot(c.exact, 0, c.knot, 1))}, {"at", at}, {"values", values}};
      std::ofstream(dir + "/case_p" + std::to_string(p) + "_n" + std::to_string(n) + ".json") << doc.dump() << "\n";
    }
  return 0;
}

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--decimal") == 0) g_dyadic = false;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--write-cases") == 0) return write_cases(argv[i + 1], {1, 3, 5, 7}, {10, 100, 1000, 10000});
  // extract: the Bezier form in one object (bezier_form; SISL's s1730 returns the same, OCCT's
  // converter one arc per piece); pieces: one BSpline per piece (extract_bezier), splinex only.
  const std::vector<std::string> ops{"insert", "refine", "elevate", "extract", "pieces", "eval"};
  const std::vector<int> degrees{1, 3, 5, 7};
  const std::vector<std::size_t> sizes{10, 100, 1000, 10000};
  std::vector<std::pair<std::string, long>> ariths{{"double", 0}, {"mpfr128", 128}, {"gmp", 0}, {"flint", 0}, {"exact", 0}};
#ifdef SPLINEX_HAVE_SISL
  ariths.emplace_back("sisl", 0);
#endif
#ifdef SPLINEX_HAVE_OCCT
  ariths.emplace_back("occt", 0);
#endif
  for (const auto& op : ops)
    for (int p : degrees)
      for (std::size_t n : sizes) {
        if (n < static_cast<std::size_t>(p) + 1) continue;
        for (const auto& [a, bits] : ariths) {
          if (op == "pieces" && (a == "sisl" || a == "occt")) continue;
          const std::string name = op + "/" + a + "/p" + std::to_string(p) + "/n" + std::to_string(n);
          const long b = bits;
          benchmark::RegisterBenchmark(name.c_str(), [op, p, n, a, b](benchmark::State& st) {
            if (a == "double") run_op<double>(st, op, p, n, 0);
            else if (a == "gmp") run_op<Rational>(st, op, p, n, 0);
            else if (a == "flint") run_op<FlintRational>(st, op, p, n, 0);
            else if (a == "exact") run_ff(st, op, p, n);
#ifdef SPLINEX_HAVE_SISL
            else if (a == "sisl") run_sisl(st, op, p, n);
#endif
#ifdef SPLINEX_HAVE_OCCT
            else if (a == "occt") run_occt(st, op, p, n);
#endif
            else run_op<Mpfr>(st, op, p, n, b);
          })->Unit(benchmark::kMicrosecond);
        }
      }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nTime ratios (" << (g_dyadic ? "dyadic" : "decimal") << " data) against double:\n";
  std::cout << std::left << std::setw(10) << "op" << std::setw(5) << "p" << std::setw(8) << "n" << std::setw(16) << "gmp/double"
            << std::setw(18) << " flint/double" << std::setw(16) << "exact/double" << "mpfr128/double\n";
  for (const auto& op : ops)
    for (int p : degrees)
      for (std::size_t n : sizes) {
        const std::string tail = "/p" + std::to_string(p) + "/n" + std::to_string(n);
        auto d = rep.ns.find(op + "/double" + tail), e = rep.ns.find(op + "/gmp" + tail), m = rep.ns.find(op + "/mpfr128" + tail),
             f = rep.ns.find(op + "/flint" + tail), ffr = rep.ns.find(op + "/exact" + tail);
        if (d == rep.ns.end()) continue;
        auto ratio = [&](decltype(d) it) { return it == rep.ns.end() ? std::string("-") : std::to_string(it->second / d->second).substr(0, 6); };
        std::cout << std::setw(10) << op << std::setw(5) << p << std::setw(8) << n << std::setw(18) << ratio(e) << std::setw(18) << ratio(f)
                  << std::setw(16) << ratio(ffr) << ratio(m);
        std::cout << "\n";
      }
  benchmark::Shutdown();
  return 0;
}
