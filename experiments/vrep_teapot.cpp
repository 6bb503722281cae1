#include "experiments/vrep_teapot.hpp"

#include "exact/rational.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <iomanip>
#include <sstream>

#include "experiments/common.hpp"
#include "experiments/render.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "fixtures/teapot_vmodel.hpp"
#include "float/rounding.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/io/documents.hpp"

namespace splinex {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <class T>
BSpline<T> as_arith(const BSpline<Rational>& S) {
  if constexpr (std::is_same_v<T, Rational>) return S;
  else return round_spline<T>(S, "teapot trivariate");
}

/// The image of a box's corner (c bit d: hi in direction d), in double, moved by `offset`.
std::array<double, 3> corner_point(const BSpline<double>& V, const std::array<Rational, 3>& lo, const std::array<Rational, 3>& hi, int c,
                                   const std::array<double, 3>& offset) {
  std::vector<double> x(3);
  for (int d = 0; d < 3; ++d) x[d] = to_double((c >> d) & 1 ? hi[d] : lo[d]);
  const auto p = evaluate(V, x);
  return {p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]};
}

const std::array<double, 3> kOffsets[] = {{0, 0, 0}, {-0.6, 0, 0}, {-1.3, 0, 0}, {0.6, 0, 0}, {1.3, 0, 0}};

}  // namespace

template <class T>
TeapotVModel<T> teapot_vmodel(std::size_t boxes, const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  TeapotVModel<T> M;
  const TeapotSolids S = teapot_solids();
  M.trivariates = {{"body", as_arith<T>(S.body)}, {"handle", as_arith<T>(S.handle)}, {"spout", as_arith<T>(S.spout)},
                   {"cavity", as_arith<T>(S.cavity)}};
  std::map<std::string, FreeformSolid<T>> solid;
  for (const auto& [name, V] : M.trivariates) solid.emplace(name, freeform_solid<T>(name, {V}));
  M.seconds_solids = seconds_since(t0);
  FreeformOptions o;
  o.max_boxes = boxes;
  o.progress = progress;
  struct Spec {
    const char* name;
    const char* trivariate;
    std::vector<std::pair<const char*, bool>> conditions;
    bool removed;
  };
  const std::vector<Spec> specs = {
      {"body - handle - spout", "body", {{"handle", false}, {"spout", false}}, false},
      {"handle & body", "handle", {{"body", true}}, false},
      {"handle - body - cavity", "handle", {{"body", false}, {"cavity", false}}, false},
      {"spout & body", "spout", {{"body", true}}, false},
      {"spout - body - cavity", "spout", {{"body", false}, {"cavity", false}}, false},
      {"handle & cavity", "handle", {{"cavity", true}}, true},
      {"spout & cavity", "spout", {{"cavity", true}}, true},
  };
  for (const auto& s : specs) {
    if (progress) progress("teapot V-model: " + std::string(s.name));
    typename TeapotVModel<T>::Row row;
    row.name = s.name;
    row.trivariate = s.trivariate;
    std::vector<FreeformCondition<T>> c;
    for (const auto& [who, inside] : s.conditions) {
      c.push_back({&solid.at(who), inside});
      row.conditions += std::string(row.conditions.empty() ? "" : ", ") + (inside ? "in " : "out of ") + who;
    }
    const auto t = std::chrono::steady_clock::now();
    row.cell = freeform_cell(M.trivariates.at(s.trivariate), c, o);
    row.seconds = seconds_since(t);
    const auto te = std::chrono::steady_clock::now();
    row.edges = freeform_edges(M.trivariates.at(s.trivariate), c, o);
    row.seconds_edges = seconds_since(te);
    (s.removed ? M.removed : M.cells).push_back(std::move(row));
  }
  M.seconds = seconds_since(t0);
  return M;
}

template <class T>
Json teapot_document(const TeapotVModel<T>& M) {
  static_assert(std::is_same_v<T, std::decay_t<decltype(M.cells.front().cell.volume.lower)>>);
  auto row = [](const auto& r) {
    Json v;
    if constexpr (std::is_same_v<T, Rational>) vrep::put_enclosure(v, "exact", r.cell.volume.lower, r.cell.volume.upper, true);
    else v = {{"lower", r.cell.volume.lower}, {"upper", r.cell.volume.upper}};
    std::size_t pieces = 0, points = 0, undecided = 0, collapsed = 0;
    for (const auto& e : r.edges.edges) {
      pieces += e.pieces;
      points += e.points;
      undecided += !e.status.is_certain();
      collapsed += e.status == std::decay_t<decltype(e)>::collapsed;
    }
    return Json{{"name", r.name},
                {"edges", {{"corners", r.edges.corners}, {"corners_undecided", r.edges.corners_undecided}, {"v_curves", pieces}, {"v_points", points},
                           {"undecided", undecided}, {"collapsed", collapsed}}},
                {"trivariate", r.trivariate},
                {"conditions", r.conditions},
                {"kind", to_string<T>(r.cell.cls.kind)},
                {"components_at_least", r.cell.components},
                {"cover_components", r.cell.cover_components},
                {"volume", v},
                {"boxes", r.cell.cls.boxes},
                {"boxes_near_trimming", r.cell.cls.mixed},
                {"point_queries", r.cell.queries},
                {"seconds", r.seconds}};
  };
  Json cells = Json::array(), removed = Json::array();
  std::size_t vcells = 0;
  for (const auto& r : M.cells) {
    cells.push_back(row(r));
    vcells += r.cell.components;
  }
  for (const auto& r : M.removed) removed.push_back(row(r));
  return Json{{"cells", cells},
              {"removed_by_subtraction", removed},
              {"v_cells_at_least", vcells},
              {"seconds", M.seconds},
              {"certified", std::is_same_v<T, Rational>},
              {"note", std::is_same_v<T, Rational>
                           ? "kinds, volume enclosures and the lower bounds on components are certified; (body + handle + spout) - cavity"
                           : "double: the same steps in floats, nothing certified; (body + handle + spout) - cavity"}};
}

template Json teapot_document(const TeapotVModel<Rational>&);
template Json teapot_document(const TeapotVModel<double>&);
template TeapotVModel<Rational> teapot_vmodel(std::size_t, const std::function<void(const std::string&)>&);
template TeapotVModel<double> teapot_vmodel(std::size_t, const std::function<void(const std::string&)>&);

std::string teapot_vmodel_svg(const TeapotVModel<Rational>& M) {
  std::vector<Triangle3> tri;
  for (std::size_t k = 0; k < M.cells.size(); ++k) {
    const auto& row = M.cells[k];
    const auto& V = M.trivariates.at(row.trivariate);
    const BSpline<double> Vd = round_spline<double>(V, "teapot trivariate");
    const auto rgb = svg::palette_rgb(k);
    const std::array<int, 3> pale{(rgb[0] + 2 * 255) / 3, (rgb[1] + 2 * 255) / 3, (rgb[2] + 2 * 255) / 3};
    for (const auto& b : row.cell.boxes)
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s) {
          if (!((s ? b.hi[d] : b.lo[d]) == (s ? V.domain_hi(d) : V.domain_lo(d)))) continue;
          // The face as a grid of quads: fine where the box is large in the domain (the clear
          // boxes far from a trimming surface), one quad where it is small.
          const int a = d == 0 ? 1 : 0, c = d == 2 ? 1 : 2;
          auto steps = [&](int e) {
            const double span = to_double(V.domain_hi(e) - V.domain_lo(e)), w = to_double(b.hi[e] - b.lo[e]);
            return std::clamp(static_cast<int>(std::lround(16 * w / span)), 1, 8);
          };
          const int na = steps(a), nb = steps(c);
          auto at = [&](int i, int j) {
            std::vector<double> x(3);
            x[d] = to_double(s ? b.hi[d] : b.lo[d]);
            x[a] = to_double(b.lo[a]) + (to_double(b.hi[a]) - to_double(b.lo[a])) * i / na;
            x[c] = to_double(b.lo[c]) + (to_double(b.hi[c]) - to_double(b.lo[c])) * j / nb;
            const auto p = evaluate(Vd, x);
            const auto& o = kOffsets[k % 5];
            return std::array<double, 3>{p[0] + o[0], p[1] + o[1], p[2] + o[2]};
          };
          const auto& col = b.truth == Truth::in ? rgb : pale;
          for (int i = 0; i < na; ++i)
            for (int j = 0; j < nb; ++j) {
              const auto p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
              tri.push_back({{p00, p10, p11}, col});
              tri.push_back({{p00, p11, p01}, col});
            }
        }
  }
  RenderView view;
  view.azimuth_deg = -90;
  view.elevation_deg = 20;
  view.width = 900;
  view.height = 420;
  view.title = "The teapot's V-model, exploded (papers/002 Figure 14): body, handle & body, handle, spout & body, spout";
  view.note = "faces of the subdivision boxes on each trivariate's boundary; pale: boxes the trimming surface may cross";
  return render_svg(tri, {}, view);
}

std::string teapot_vmodel_vtk(const TeapotVModel<Rational>& M) {
  std::ostringstream pts, cells, kind, which;
  std::size_t np = 0, nc = 0;
  pts << std::setprecision(7);  // a figure's file: single precision is plenty
  for (std::size_t k = 0; k < M.cells.size(); ++k) {
    const auto& row = M.cells[k];
    const BSpline<double> Vd = round_spline<double>(M.trivariates.at(row.trivariate), "teapot trivariate");
    for (const auto& b : row.cell.boxes) {
      // VTK_HEXAHEDRON's corner order: the bottom face counter-clockwise, then the top.
      const int order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
      cells << 8;
      for (int c : order) {
        const auto p = corner_point(Vd, b.lo, b.hi, c, {0, 0, 0});
        pts << p[0] << " " << p[1] << " " << p[2] << "\n";
        cells << " " << np++;
      }
      cells << "\n";
      kind << (b.truth == Truth::in ? 2 : 1) << "\n";
      which << k << "\n";
      ++nc;
    }
  }
  std::ostringstream out;
  out << "# vtk DataFile Version 3.0\nsplinex: the teapot's V-cells as subdivision boxes (cell: index of the V-model's cell; in: 2 inside, 1 "
         "near a trimming surface)\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "
      << np << " double\n"
      << pts.str() << "CELLS " << nc << " " << 9 * nc << "\n"
      << cells.str() << "CELL_TYPES " << nc << "\n";
  for (std::size_t i = 0; i < nc; ++i) out << "12\n";
  out << "CELL_DATA " << nc << "\nSCALARS cell int 1\nLOOKUP_TABLE default\n" << which.str() << "SCALARS in int 1\nLOOKUP_TABLE default\n" << kind.str();
  return out.str();
}

}  // namespace splinex

namespace splinex {

namespace {

std::string bounds_text(double lo, double hi) {
  std::ostringstream s;
  s << std::setprecision(4) << "[" << lo << ", " << hi << "]";
  return s.str();
}

}  // namespace

void vrep_teapot_section(ReportContext& ctx) {
  const std::size_t boxes = ctx.options.full ? 16384 : 4096;  // 16384: within the default limits for the body's boxes
  std::ostringstream cell_rows, edge_rows, volume_rows, csv;
  auto progress = [&](const std::string& line) { ctx.progress(line); };
  const auto E = teapot_vmodel<Rational>(boxes, progress);
  const auto D = teapot_vmodel<double>(boxes);
  csv << "cell,trivariate,conditions,arith,kind,components,cover_components,volume_lower,volume_upper,boxes,mixed,queries,systems,seconds\n";
  std::size_t vcells = 0, cover = 0;
  double exact_s = 0, double_s = 0;
  auto put_csv = [&](const auto& row, const char* arith) {
    csv << "\"" << row.name << "\"," << row.trivariate << ",\"" << row.conditions << "\"," << arith << "," << to_string<Rational>(row.cell.cls.kind)
        << "," << row.cell.components << "," << row.cell.cover_components << "," << std::setprecision(17) << to_double(row.cell.volume.lower) << ","
        << to_double(row.cell.volume.upper) << "," << row.cell.cls.boxes << "," << row.cell.cls.mixed << "," << row.cell.queries << ","
        << row.cell.systems << "," << row.seconds << "\n";
  };
  std::string differing;
  std::size_t n_differing = 0;
  for (std::size_t k = 0; k < E.cells.size(); ++k) {
    const auto& e = E.cells[k];
    const auto& d = D.cells[k];
    if (!same_boxes(e.cell, d.cell)) {
      differing += (differing.empty() ? "" : ", ") + e.name;
      ++n_differing;
    }
    vcells += e.cell.components;
    cover += e.cell.cover_components;
    exact_s += e.seconds;
    double_s += d.seconds;
    cell_rows << "| " << e.name << " | " << e.trivariate << " | " << e.conditions << " | " << to_string<Rational>(e.cell.cls.kind) << " | "
       << e.cell.components << " / " << e.cell.cover_components << " | " << bounds_text(to_double(e.cell.volume.lower), to_double(e.cell.volume.upper))
       << " | " << e.cell.cls.mixed << " of " << e.cell.cls.boxes << " | " << fmt(e.seconds) << " | "
       << bounds_text(d.cell.volume.lower, d.cell.volume.upper) << " | "
       << fmt(to_double(abs(exact_from_double(d.cell.volume.lower) - e.cell.volume.lower)), 2) << ", "
       << fmt(to_double(abs(exact_from_double(d.cell.volume.upper) - e.cell.volume.upper)), 2) << " | " << fmt(d.seconds) << " |\n";
    put_csv(e, "exact");
    csv << "\"" << d.name << "\"," << d.trivariate << ",\"" << d.conditions << "\",double," << to_string<double>(d.cell.cls.kind) << "," << d.cell.components
        << "," << d.cell.cover_components << "," << std::setprecision(17) << d.cell.volume.lower << "," << d.cell.volume.upper << "," << d.cell.cls.boxes
        << "," << d.cell.cls.mixed << "," << d.cell.queries << "," << d.cell.systems << "," << d.seconds << "\n";
  }
  for (const auto& e : E.removed) put_csv(e, "exact");
  for (const auto& e : E.cells) {
    std::size_t pieces = 0, points = 0, undecided = 0, collapsed = 0;
    for (const auto& x : e.edges.edges) {
      pieces += x.pieces;
      points += x.points;
      undecided += !x.status.is_certain();
      collapsed += x.status == FreeformEdges<Rational>::Edge::collapsed;
    }
    edge_rows << "| " << e.name << " | " << e.edges.corners << " (" << e.edges.corners_undecided << ") | " << pieces << " | " << points << " | " << undecided
       << " | " << collapsed << " | " << fmt(e.seconds_edges) << " |\n";
  }
  // The volume balance: each trivariate's exact volume against the sum of its cells' enclosures.
  auto whole = [&](const char* name) { return volume_enclosure(E.trivariates.at(name)).lower; };
  auto find = [&](const std::string& name) -> const FreeformCell<Rational>& {
    for (const auto* list : {&E.cells, &E.removed})
      for (const auto& r : *list)
        if (r.name == name) return r.cell;
    throw std::logic_error("no cell " + name);
  };
  bool balance = true;
  for (const auto& [tv, parts] : std::vector<std::pair<const char*, std::vector<std::string>>>{
           {"handle", {"handle & body", "handle - body - cavity", "handle & cavity"}},
           {"spout", {"spout & body", "spout - body - cavity", "spout & cavity"}}}) {
    Rational lo(0), hi(0);
    std::string names;
    for (const auto& p : parts) {
      lo += find(p).volume.lower;
      hi += find(p).volume.upper;
      names += (names.empty() ? "" : " + ") + p;
    }
    const Rational v = whole(tv);
    const bool holds = lo <= v && v <= hi;
    balance = balance && holds;
    volume_rows << "| " << tv << " | " << to_fraction_string(v) << " = " << fmt(to_double(v), 6) << " | " << names << " | " << bounds_text(to_double(lo), to_double(hi))
       << (holds ? " holds it" : " **misses it**") << " |\n";
  }
  ctx.ok = ctx.ok && balance;
  // How the enclosure narrows with the budget (handle & body, exact).
  std::string budgets;
  for (std::size_t b : {std::size_t(1024), std::size_t(2048), boxes}) {
    const auto T = teapot_solids();
    const auto body = freeform_solid<Rational>("body", {T.body});
    FreeformOptions o;
    o.max_boxes = b;
    const auto c = freeform_cell(T.handle, {{&body, true}}, o);
    budgets += (budgets.empty() ? "" : ", ") + ReportTemplate("vrep-teapot.budget")
                                                   .set("boxes", b)
                                                   .set("bounds", bounds_text(to_double(c.volume.lower), to_double(c.volume.upper)))
                                                   .set("components", c.components)
                                                   .render();
  }
  std::ostringstream trivariates;
  for (const char* name : {"body", "handle", "spout", "cavity"}) {
    const auto& V = E.trivariates.at(name);
    trivariates << name << " " << V.count(0) << "x" << V.count(1) << "x" << V.count(2) << " (" << V.degrees[0] << "," << V.degrees[1] << "," << V.degrees[2] << ") ";
  }
  write_file_atomically(ctx.options.out_dir + "/vrep_teapot.csv", csv.str());
  write_file_atomically(ctx.options.out_dir + "/vrep_teapot.svg", teapot_vmodel_svg(E));
  write_file_atomically(ctx.options.out_dir + "/vrep_teapot.vtk", teapot_vmodel_vtk(E));
  ctx.markdown["vrep-teapot"] = ReportTemplate("vrep-teapot")
                                    .set("boxes", boxes)
                                    .set("cell_rows", cell_rows.str())
                                    .set("edge_rows", edge_rows.str())
                                    .set("volume_rows", volume_rows.str())
                                    .set("budgets", budgets)
                                    .set("vcells", vcells)
                                    .set("cover", cover)
                                    .set("trivariates", trivariates.str())
                                    .set("exact_s", fmt(exact_s + E.seconds_solids))
                                    .set("double_s", fmt(double_s + D.seconds_solids))
                                    .set("exact_over_double", fmt((exact_s + E.seconds_solids) / std::max(1e-9, double_s + D.seconds_solids), 3))
                                    .when("same_partition", n_differing == 0)
                                    .set("differing", n_differing == 0 ? std::string("") : std::to_string(n_differing) + " of " + std::to_string(E.cells.size()) + " cells (" + differing + ")")
                                    .render();
}

}  // namespace splinex
