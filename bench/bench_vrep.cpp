// V-rep (issue 17): constructing, gluing and certifying the primitives (cylinder, cone, torus of
// five cells, the sphere of seven), exact (GMP rationals) and double, in one run; prints exact/double per step.
#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.hpp"

#include <array>
#include <iomanip>
#include <iostream>
#include <map>
#include <type_traits>

#include "experiments/vrep_ssi.hpp"
#include "fixtures/teapot_vmodel.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/boolean/ssi.hpp"
#include "vrep/freeform/freeform.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_euler.hpp"
#include "vrep/topology/trimmed_glue.hpp"
#include "vrep/topology/trimmed_topology.hpp"

using namespace splinex;

namespace {

template <class T>
std::vector<BSpline<T>> build(const std::string& name) {
  if (name == "cylinder") return cylinder_cells<T>(T(2), T(3));
  if (name == "cone") return cone_cells<T>(T(2), T(1), T(3));
  if (name == "torus") return torus_cells<T>(T(3), T(1));
  return sphere_cells<T>(T(2));
}

template <class T>
void step(benchmark::State& st, const std::string& name, const std::string& what) {
  const auto cells = build<T>(name);
  const T eps = std::is_same_v<T, double> ? T(1e-12) : T(0);
  for (auto _ : st) {
    if (what == "construct") benchmark::DoNotOptimize(build<T>(name));
    else if (what == "glue") benchmark::DoNotOptimize(glue(cells, eps));
    else
      for (const auto& V : cells) benchmark::DoNotOptimize(certify_regularity(V));
  }
}


/// Booleans (issue 18): Figure 3's union of two boxes, and a 3 x 3 x 3 grid of boxes minus an
/// inner box (a cavity: 27 cells cut, T-junctions resolved).
template <class T>
std::pair<VModel<T>, VModel<T>> boolean_operands(const std::string& name) {
  auto box = [](int a0, int a1, int a2, int b0, int b1, int b2, int den) {
    return glue(box_cells<T>({T(a0) / T(den), T(a1) / T(den), T(a2) / T(den)}, {T(b0) / T(den), T(b1) / T(den), T(b2) / T(den)}));
  };
  if (name == "figure3") return {box(0, 0, 0, 2, 1, 1, 1), box(1, 0, 0, 2, 2, 1, 1)};
  std::vector<BSpline<T>> cells;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) cells.push_back(box_cells<T>({T(i), T(j), T(k)}, {T(i + 1), T(j + 1), T(k + 1)})[0]);
  return {glue(cells, std::is_same_v<T, double> ? T(1e-12) : T(0)), box(1, 1, 1, 5, 5, 5, 2)};
}

template <class T>
void boolean_step(benchmark::State& st, const std::string& name) {
  const auto [A, B] = boolean_operands<T>(name);
  const T eps = std::is_same_v<T, double> ? T(1e-12) : T(0);
  const BooleanOp op = name == "figure3" ? BooleanOp::unite : BooleanOp::subtract;
  std::size_t cells = 0;
  for (auto _ : st) cells = boolean_op(A, B, op, eps).cells.size();
  st.counters["cells"] = static_cast<double>(cells);
}

/// Trimmed Booleans: Figure 4, the cone r 1 to 1/2 (h 2) united with a cylinder r 1/3 along x at
/// z = 1; exact, and in double with eps 1e-12 on the rounded models.
void trimmed_step(benchmark::State& st, bool exact) {
  using R = Rational;
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-3, 2), R(0), R(1)});
  std::size_t cells = 0;
  if (exact)
    for (auto _ : st) cells = trimmed_boolean(cone, cyl, BooleanOp::unite).cells.size();
  else {
    const auto a = trimmed_to_double(cone), b = trimmed_to_double(cyl);
    for (auto _ : st) cells = trimmed_boolean(a, b, BooleanOp::unite, Blend::sum_clipped, {}, 1e-12).cells.size();
  }
  st.counters["cells"] = static_cast<double>(cells);
}

/// The Euler characteristic of Figure 4's union: every cell's (trimmed_euler) and the model's
/// (model_euler), exact or on the rounded model.
void euler_step(benchmark::State& st, bool exact) {
  using R = Rational;
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-3, 2), R(0), R(1)});
  const auto U = trimmed_boolean(cone, cyl, BooleanOp::unite);
  long chi = 0;
  auto run = [&](const auto& M) {
    chi = 0;
    for (const auto& c : M.cells) chi += trimmed_euler(M.trivariates[c.trivariate], c.trim).image_chi;
    chi += 1000 * model_euler(M).image_chi;
  };
  if (exact)
    for (auto _ : st) run(U);
  else {
    const auto D = trimmed_to_double(U);
    for (auto _ : st) run(D);
  }
  st.counters["sum_chi_cells_plus_1000_chi_model"] = static_cast<double>(chi);
}

/// The cube [0, 2]^3 trimmed to the lens of two balls (centres (4/5, 1, 1), (6/5, 1, 1), radius
/// 1/2) cut by the plane z = 11/10: its trivariate and region.
template <class T>
std::pair<BSpline<T>, Region<T>> lens_cut() {
  Poly3<T> plane;
  plane.terms[{0, 0, 1}] = T(1);
  plane.terms[{0, 0, 0}] = -(T(11) / T(10));
  return {box_cells<T>({T(0), T(0), T(0)}, {T(2), T(2), T(2)}).front(),
          region_and<T>({ball_region<T>({T(4) / T(5), T(1), T(1)}, T(1) / T(2)), ball_region<T>({T(6) / T(5), T(1), T(1)}, T(1) / T(2)),
                         region_leaf(plane, "plane")})};
}

/// The V-curves between trimming surfaces (trimmed_curves) of the lens cell: three arcs between
/// two V-points, exact or double.
template <class T>
void curves_step(benchmark::State& st) {
  const auto [V, R] = lens_cut<T>();
  std::size_t arcs = 0, decided = 0;
  for (auto _ : st) {
    const auto c = trimmed_curves(V, R);
    arcs = c.arcs;
    decided = 0;
    for (const auto& p : c.pairs) decided += p.decided;
  }
  st.counters["arcs"] = static_cast<double>(arcs);
  st.counters["decided_pairs"] = static_cast<double>(decided);
}

/// The half-V-surfaces (count_surface through trimmed_topology's parts) of the same cell: the
/// pieces of the three trimming surfaces' parts (1 each), exact or double.
template <class T>
void surfaces_step(benchmark::State& st) {
  const auto [V, R] = lens_cut<T>();
  std::size_t pieces = 0, decided = 0;
  for (auto _ : st) {
    const auto t = trimmed_topology(V, R, 1024);
    pieces = decided = 0;
    for (const auto& s : t.surfaces)
      if (s.leaf >= 0) {
        pieces += s.pieces;
        decided += s.decided;
      }
  }
  st.counters["trimming_pieces"] = static_cast<double>(pieces);
  st.counters["decided_surfaces"] = static_cast<double>(decided);
}

/// The gluing of a trimmed model into one V-model (trimmed_glue; Table 1's gluing time): the box
/// [0,2]x[0,1]^2 united with the cylinder r 1/3 along x through it (7 cells; 24 + 27 V-surfaces
/// exactly), exact or on the model rounded to double.
TrimmedModel<Rational> box_cylinder_union() {
  using R = Rational;
  const auto A = as_trimmed(glue(box_cells<R>({R(0), R(0), R(0)}, {R(2), R(1), R(1)})), box_region<R>({R(0), R(0), R(0)}, {R(2), R(1), R(1)}));
  const auto B = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-1, 2), R(1, 2), R(1, 2)});
  return trimmed_boolean(A, B, BooleanOp::unite);
}
template <class T>
void glue_step(benchmark::State& st) {
  static const auto U = box_cylinder_union();
  TrimmedModel<T> M;
  if constexpr (std::is_same_v<T, Rational>) M = U;
  else M = trimmed_to_double(U);
  TrimmedGlueOptions o;
  o.max_boxes = 2048;
  std::size_t v = 0, decided = 0;
  for (auto _ : st) {
    const auto G = trimmed_glue(M, o);
    v = G.boundary_v_surfaces + G.internal_v_surfaces;
    decided = G.decided;
  }
  st.counters["v_surfaces"] = static_cast<double>(v);
  st.counters["decided"] = static_cast<double>(decided);
}

/// The teapot's handle against its body (step 1/16): the float SSI, and the exact judgement of its
/// points (Krawczyk certificates).
void ssi_step(benchmark::State& st, bool judge) {
  const auto H = teapot_surface("handle"), B = teapot_surface("body");
  const auto h = round_spline<double>(H), b = round_spline<double>(B);
  const auto r = intersect_surfaces(h, b);
  std::size_t n = 0;
  for (auto _ : st) {
    if (!judge) {
      n = intersect_surfaces(h, b).branches.size();
      continue;
    }
    n = 0;
    for (const auto& br : r.branches)
      for (std::size_t i = 0; i + 1 < br.points.size(); ++i) {
        SsiParams d;
        for (int k = 0; k < 4; ++k) d[k] = br.points[i + 1][k] - br.points[i][k];
        n += judge_point(H, B, br.points[i], d).certified;
      }
  }
  st.counters[judge ? "certified" : "branches"] = static_cast<double>(n);
}

/// Trimming by a freeform solid: the teapot's handle inside its body (Figure 14's shared cells),
/// 1024 boxes, exact and double.
template <class T>
void freeform_step(benchmark::State& st) {
  const auto S = teapot_solids();
  BSpline<T> H, B;
  if constexpr (std::is_same_v<T, Rational>) {
    H = S.handle;
    B = S.body;
  } else {
    H = round_spline<double>(S.handle);
    B = round_spline<double>(S.body);
  }
  const auto body = freeform_solid<T>("body", {B});
  FreeformOptions o;
  o.max_boxes = 1024;
  std::size_t mixed = 0;
  for (auto _ : st) mixed = freeform_cell(H, {{&body, true}}, o).cls.mixed;
  st.counters["boxes_near_trimming"] = static_cast<double>(mixed);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("vrep/freeform/double/teapot-handle-in-body", [](benchmark::State& st) { freeform_step<double>(st); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/freeform/exact/teapot-handle-in-body", [](benchmark::State& st) { freeform_step<Rational>(st); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/trimmed/double/figure4", [](benchmark::State& st) { trimmed_step(st, false); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/trimmed/exact/figure4", [](benchmark::State& st) { trimmed_step(st, true); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/euler/double/figure4", [](benchmark::State& st) { euler_step(st, false); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/euler/exact/figure4", [](benchmark::State& st) { euler_step(st, true); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/curves/double/lens-cut", [](benchmark::State& st) { curves_step<double>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/curves/exact/lens-cut", [](benchmark::State& st) { curves_step<Rational>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/topology/double/lens-cut", [](benchmark::State& st) { surfaces_step<double>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/topology/exact/lens-cut", [](benchmark::State& st) { surfaces_step<Rational>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/trimmed-glue/double/box-cylinder", [](benchmark::State& st) { glue_step<double>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/trimmed-glue/exact/box-cylinder", [](benchmark::State& st) { glue_step<Rational>(st); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/ssi/double/teapot-handle-body", [](benchmark::State& st) { ssi_step(st, false); })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("vrep/ssi/judge/teapot-handle-body", [](benchmark::State& st) { ssi_step(st, true); })->Unit(benchmark::kMillisecond);
  const std::vector<std::string> booleans{"figure3", "grid-cavity"};
  for (const auto& b : booleans) {
    benchmark::RegisterBenchmark(("vrep/boolean/double/" + b).c_str(), [b](benchmark::State& st) { boolean_step<double>(st, b); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("vrep/boolean/exact/" + b).c_str(), [b](benchmark::State& st) { boolean_step<Rational>(st, b); })
        ->Unit(benchmark::kMillisecond);
  }
  const std::vector<std::string> prims{"cylinder", "cone", "torus", "sphere"}, steps{"construct", "glue", "certify"};
  for (const auto& p : prims)
    for (const auto& s : steps) {
      benchmark::RegisterBenchmark(("vrep/" + s + "/double/" + p).c_str(), [p, s](benchmark::State& st) { step<double>(st, p, s); })
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("vrep/" + s + "/exact/" + p).c_str(), [p, s](benchmark::State& st) { step<Rational>(st, p, s); })
          ->Unit(benchmark::kMillisecond);
    }
  benchmark::Initialize(&argc, argv);
  RatioReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::cout << "\nV-rep primitives: exact(GMP)/double\nprimitive   construct   glue   certify\n";
  for (const auto& p : prims) {
    std::cout << std::left << std::setw(12) << p << std::right;
    for (const auto& s : steps) {
      const double d = rep.ns["vrep/" + s + "/double/" + p], e = rep.ns["vrep/" + s + "/exact/" + p];
      std::cout << std::fixed << std::setprecision(1) << std::setw(9) << (d > 0 ? e / d : 0.0) << "  ";
    }
    std::cout << "\n";
  }
  std::cout << "\nV-rep Booleans (Table 1 for what is built): ms double, ms exact, exact/double\n";
  for (const auto& b : booleans) {
    const double d = rep.ns["vrep/boolean/double/" + b], e = rep.ns["vrep/boolean/exact/" + b];
    std::cout << std::left << std::setw(12) << b << std::right << std::fixed << std::setprecision(2) << std::setw(10) << d
              << std::setw(10) << e << std::setprecision(1) << std::setw(8) << (d > 0 ? e / d : 0.0) << "\n";
  }
  {
    const double d = rep.ns["vrep/trimmed/double/figure4"], e = rep.ns["vrep/trimmed/exact/figure4"];
    std::cout << std::left << std::setw(12) << "figure4" << std::right << std::fixed << std::setprecision(2) << std::setw(10) << d
              << std::setw(10) << e << std::setprecision(1) << std::setw(8) << (d > 0 ? e / d : 0.0) << "  (trimmed cells)\n";
    const double ed = rep.ns["vrep/euler/double/figure4"], ee = rep.ns["vrep/euler/exact/figure4"];
    std::cout << std::left << std::setw(12) << "euler" << std::right << std::fixed << std::setprecision(2) << std::setw(10) << ed << std::setw(10) << ee
              << std::setprecision(1) << std::setw(8) << (ed > 0 ? ee / ed : 0.0) << "  (Euler characteristic of Figure 4's 15 cells and model)\n";
    const double cd = rep.ns["vrep/curves/double/lens-cut"], ce = rep.ns["vrep/curves/exact/lens-cut"];
    std::cout << std::left << std::setw(12) << "curves" << std::right << std::fixed << std::setprecision(2) << std::setw(10) << cd << std::setw(10) << ce
              << std::setprecision(1) << std::setw(8) << (cd > 0 ? ce / cd : 0.0)
              << "  (V-curves between trimming surfaces: lens of two balls cut by a plane; see the decided_pairs counter)\n";
    const double td = rep.ns["vrep/topology/double/lens-cut"], te = rep.ns["vrep/topology/exact/lens-cut"];
    std::cout << std::left << std::setw(12) << "topology" << std::right << std::fixed << std::setprecision(2) << std::setw(10) << td << std::setw(10) << te
              << std::setprecision(1) << std::setw(8) << (td > 0 ? te / td : 0.0)
              << "  (trimmed_topology of the same cell, with the exact half-V-surfaces; see the decided_surfaces counter)\n";
    const double gd = rep.ns["vrep/trimmed-glue/double/box-cylinder"], ge = rep.ns["vrep/trimmed-glue/exact/box-cylinder"];
    std::cout << std::left << std::setw(12) << "glue" << std::right << std::fixed << std::setprecision(2) << std::setw(10) << gd << std::setw(10) << ge
              << std::setprecision(1) << std::setw(8) << (gd > 0 ? ge / gd : 0.0)
              << "  (trimmed_glue of box u cylinder, 7 cells; double's counts are wrong here: see the v_surfaces and decided counters)\n";
    const double f = rep.ns["vrep/ssi/double/teapot-handle-body"], j = rep.ns["vrep/ssi/judge/teapot-handle-body"];
    std::cout << "\nTeapot handle and body: float SSI " << std::setprecision(2) << f << " ms, its exact judgement " << j
              << " ms (judge/SSI " << std::setprecision(1) << (f > 0 ? j / f : 0.0) << ")\n";
    const double fd = rep.ns["vrep/freeform/double/teapot-handle-in-body"], fe = rep.ns["vrep/freeform/exact/teapot-handle-in-body"];
    std::cout << "Teapot handle in body (trimming by a freeform solid, 1024 boxes): ms double " << std::setprecision(2) << fd << ", exact " << fe
              << " (exact/double " << std::setprecision(1) << (fd > 0 ? fe / fd : 0.0) << ")\n";
  }
  benchmark::Shutdown();
  return 0;
}
