#include "experiments/vrep_figures.hpp"

#include "experiments/render.hpp"
#include "spline/evaluate.hpp"
#include "vrep/regularity.hpp"

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
    std::array<int, 3> rgb = palette_rgb(c);
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
