#include "experiments/vrep_figures.hpp"

#include "experiments/render.hpp"
#include "float/rounding.hpp"
#include "spline/evaluate.hpp"
#include "vrep/model/regularity.hpp"
#include <sstream>

namespace splinex {

std::string vmodel_svg(const VModel<Rational>& M, double explode, const std::string& title, bool mark_singular, int samples) {
  // Centroids of the control points (a figure's offset, not a claim).
  std::vector<std::array<double, 3>> centre(M.cells.size(), {0, 0, 0});
  std::array<double, 3> all{0, 0, 0};
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    for (std::size_t i = 0; i < V.size(); ++i)
      for (int k = 0; k < 3; ++k) centre[c][k] += to_double(V.points[i * V.q + k]) / static_cast<double>(V.size());
    for (int k = 0; k < 3; ++k) all[k] += centre[c][k] / static_cast<double>(M.cells.size());
  }
  std::vector<Triangle3> tris;
  std::vector<Marker3> marks;
  std::size_t zeros = 0;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    std::array<double, 3> off{};
    for (int k = 0; k < 3; ++k) off[k] = explode * (centre[c][k] - all[k]);
    // A cell's "colour" attribute (three values in [0, 1], Figure 5) if it has one.
    std::array<int, 3> rgb = svg::palette_rgb(c);
    const auto col = M.cells[c].attributes.constants.find("colour");
    if (col != M.cells[c].attributes.constants.end() && col->second.size() == 3)
      for (int k = 0; k < 3; ++k) {
        const double x = to_double(col->second[k]);
        rgb[k] = static_cast<int>(255.0 * (x < 0 ? 0 : x > 1 ? 1 : x) + 0.5);
      }
    add_trivariate_boundary(tris, V, rgb, samples, off);
    if (!mark_singular) continue;
    const auto J = jacobian_determinant(V);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s)
        for (int a = 0; a <= samples; ++a)
          for (int b = 0; b <= samples; ++b) {
            std::vector<Rational> x(3);
            const int da = d == 0 ? 1 : 0, db = d == 2 ? 1 : 2;
            x[d] = s ? V.domain_hi(d) : V.domain_lo(d);
            x[da] = V.domain_lo(da) + (V.domain_hi(da) - V.domain_lo(da)) * Rational(a, samples);
            x[db] = V.domain_lo(db) + (V.domain_hi(db) - V.domain_lo(db)) * Rational(b, samples);
            if (evaluate(J, x)[0] != 0) continue;
            const auto p = evaluate(V, x);
            marks.push_back({{to_double(p[0]) + off[0], to_double(p[1]) + off[1], to_double(p[2]) + off[2]}});
            ++zeros;
          }
  }
  RenderView view;
  view.title = title;
  view.note = mark_singular ? "red (drawn through the surface): " + std::to_string(zeros) + " sampled boundary points where det J = 0 exactly"
                            : "cells exploded by " + std::to_string(static_cast<int>(explode * 100)) + "% of their offset from the centre";
  return render_svg(tris, marks, view);
}

}  // namespace splinex

namespace splinex {

namespace {

/// Voxels of the trimmed cells: per cell the grid's points (double) and which voxels are kept.
struct Voxels {
  int n = 0;
  std::vector<std::vector<std::array<double, 3>>> points;  // per cell, (n+1)^3, u fastest
  std::vector<std::vector<char>> kept;                      // per cell, n^3
};


Voxels voxelize(const TrimmedModel<Rational>& M, int n) {
  Voxels v;
  v.n = n;
  for (const auto& c : M.cells) {
    const BSpline<double> V = round_spline<double>(M.trivariates[c.trivariate], c.name);
    const Region<double> trim = region_to_double(c.trim);
    std::vector<std::array<double, 3>> pts;
    auto at = [&](double a, double b, double d) {
      std::vector<double> x{V.domain_lo(0) + (V.domain_hi(0) - V.domain_lo(0)) * a, V.domain_lo(1) + (V.domain_hi(1) - V.domain_lo(1)) * b,
                            V.domain_lo(2) + (V.domain_hi(2) - V.domain_lo(2)) * d};
      const auto p = evaluate(V, x);
      return std::array<double, 3>{p[0], p[1], p[2]};
    };
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) pts.push_back(at(double(i) / n, double(j) / n, double(k) / n));
    std::vector<char> kept(static_cast<std::size_t>(n) * n * n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const auto p = at((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
          kept[(static_cast<std::size_t>(k) * n + j) * n + i] = classify_point(trim, std::vector<double>{p[0], p[1], p[2]}) != Truth::out;
        }
    v.points.push_back(std::move(pts));
    v.kept.push_back(std::move(kept));
  }
  return v;
}

std::array<int, 3> category_rgb(const std::string& category, std::size_t c) {
  if (category == "A") return {150, 90, 200};
  if (category == "both") return {60, 200, 220};
  if (category == "B") return {90, 190, 90};
  return svg::palette_rgb(c);
}

}  // namespace

std::string trimmed_svg(const TrimmedModel<Rational>& M, double explode, const std::string& title, int n) {
  const Voxels v = voxelize(M, n);
  const auto N = static_cast<std::size_t>(n);
  auto pid = [N](std::size_t i, std::size_t j, std::size_t k) { return (k * (N + 1) + j) * (N + 1) + i; };
  // Centroids of the kept voxels' corners (for the explosion).
  std::vector<std::array<double, 3>> centre(M.cells.size(), {0, 0, 0});
  std::array<double, 3> all{0, 0, 0};
  std::size_t cells_with = 0;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    std::size_t cnt = 0;
    for (std::size_t k = 0; k < N; ++k)
      for (std::size_t j = 0; j < N; ++j)
        for (std::size_t i = 0; i < N; ++i)
          if (v.kept[c][(k * N + j) * N + i]) {
            const auto& p = v.points[c][pid(i, j, k)];
            for (int a = 0; a < 3; ++a) centre[c][a] += p[a];
            ++cnt;
          }
    if (cnt == 0) continue;
    for (int a = 0; a < 3; ++a) centre[c][a] /= static_cast<double>(cnt);
    for (int a = 0; a < 3; ++a) all[a] += centre[c][a];
    ++cells_with;
  }
  for (int a = 0; a < 3; ++a) all[a] /= static_cast<double>(std::max<std::size_t>(cells_with, 1));
  std::vector<Triangle3> tris;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    std::array<double, 3> off{};
    for (int a = 0; a < 3; ++a) off[a] = explode * (centre[c][a] - all[a]);
    const auto rgb = category_rgb(M.cells[c].category, c);
    auto kept = [&](long i, long j, long k) {
      if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n) return false;
      return v.kept[c][(static_cast<std::size_t>(k) * N + j) * N + i] != 0;
    };
    auto P = [&](std::size_t i, std::size_t j, std::size_t k) {
      auto p = v.points[c][pid(i, j, k)];
      for (int a = 0; a < 3; ++a) p[a] += off[a];
      return p;
    };
    for (long k = 0; k < n; ++k)
      for (long j = 0; j < n; ++j)
        for (long i = 0; i < n; ++i) {
          if (!kept(i, j, k)) continue;
          const long d[3] = {i, j, k};
          for (int ax = 0; ax < 3; ++ax)
            for (int s = 0; s < 2; ++s) {
              long e[3] = {i, j, k};
              e[ax] += s ? 1 : -1;
              if (kept(e[0], e[1], e[2])) continue;
              // The voxel face at d[ax] + s across axis ax: its four corners.
              std::array<std::array<double, 3>, 4> q;
              const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
              for (int t = 0; t < 4; ++t) {
                std::size_t g[3];
                g[ax] = static_cast<std::size_t>(d[ax] + s);
                g[a1] = static_cast<std::size_t>(d[a1] + (t == 1 || t == 2));
                g[a2] = static_cast<std::size_t>(d[a2] + (t >= 2));
                q[t] = P(g[0], g[1], g[2]);
              }
              tris.push_back({{q[0], q[1], q[2]}, rgb});
              tris.push_back({{q[0], q[2], q[3]}, rgb});
            }
        }
  }
  RenderView view;
  view.title = title;
  view.note = std::to_string(n) + "^3 parameter voxels per cell (stair-stepped); purple: only A, cyan: both, green: only B";
  return render_svg(tris, {}, view);
}

std::string trimmed_vtu(const TrimmedModel<Rational>& M, int n) {
  const Voxels v = voxelize(M, n);
  const auto N = static_cast<std::size_t>(n);
  std::ostringstream pts, conn, offs, types, cell, cat;
  pts.precision(17);
  std::size_t npts = 0, ncells = 0, base = 0;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    for (const auto& p : v.points[c]) pts << p[0] << " " << p[1] << " " << p[2] << "\n";
    npts += v.points[c].size();
    auto pid = [&](std::size_t i, std::size_t j, std::size_t k) { return base + (k * (N + 1) + j) * (N + 1) + i; };
    const std::string& g = M.cells[c].category;
    const int category = g == "A" ? 1 : g == "both" ? 2 : g == "B" ? 3 : 0;
    for (std::size_t k = 0; k < N; ++k)
      for (std::size_t j = 0; j < N; ++j)
        for (std::size_t i = 0; i < N; ++i) {
          if (!v.kept[c][(k * N + j) * N + i]) continue;
          conn << pid(i, j, k) << " " << pid(i + 1, j, k) << " " << pid(i + 1, j + 1, k) << " " << pid(i, j + 1, k) << " " << pid(i, j, k + 1) << " "
               << pid(i + 1, j, k + 1) << " " << pid(i + 1, j + 1, k + 1) << " " << pid(i, j + 1, k + 1) << "\n";
          ++ncells;
          offs << 8 * ncells << "\n";
          types << "12\n";
          cell << c << "\n";
          cat << category << "\n";
        }
    base += v.points[c].size();
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << npts << "\" NumberOfCells=\"" << ncells << "\">\n"
      << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n" << pts.str() << "</DataArray></Points>\n"
      << "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n" << conn.str() << "</DataArray>\n"
      << "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n" << offs.str() << "</DataArray>\n"
      << "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n" << types.str() << "</DataArray></Cells>\n"
      << "<CellData Scalars=\"category\"><DataArray type=\"Int32\" Name=\"cell\" format=\"ascii\">\n" << cell.str() << "</DataArray>\n"
      << "<DataArray type=\"Int32\" Name=\"category\" format=\"ascii\">\n" << cat.str() << "</DataArray></CellData>\n"
      << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return out.str();
}

}  // namespace splinex
