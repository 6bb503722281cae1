// A small projection renderer for figures (SVG): triangles in 3D, an orthographic camera given by
// azimuth and elevation, flat Lambert shading, painter's algorithm (far to near by centroid
// depth), and marker points drawn on top. Written once and used for the V-rep figures (exploded
// primitives, Figure 8's singular sets) and the teapot star pattern on the 3D teapot. Figures only:
// doubles, no claim is made from them.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "experiments/svg.hpp"  // svg::palette_rgb: a distinct colour per index (cells, stars)
#include "spline/bspline.hpp"

namespace splinex {

struct Triangle3 {
  std::array<std::array<double, 3>, 3> p;
  std::array<int, 3> rgb{120, 160, 220};
};

struct Marker3 {
  std::array<double, 3> at;
  std::array<int, 3> rgb{220, 30, 30};
  double radius = 2.5;
};

struct RenderView {
  double azimuth_deg = 35, elevation_deg = 25;
  int width = 640, height = 480;
  std::string title, note;
};

std::string render_svg(const std::vector<Triangle3>& triangles, const std::vector<Marker3>& markers, const RenderView& view);

/// The six boundary faces of a trivariate (its first three coordinates), each sampled on an n x n
/// grid (exactly, then rounded), as triangles, shifted by `offset`.
template <class T>
void add_trivariate_boundary(std::vector<Triangle3>& out, const BSpline<T>& V, const std::array<int, 3>& rgb, int n,
                             const std::array<double, 3>& offset = {0, 0, 0});

/// A surface (first three coordinates) sampled on an n x n grid as triangles.
template <class T>
void add_surface(std::vector<Triangle3>& out, const BSpline<T>& S, const std::array<int, 3>& rgb, int n,
                 const std::array<double, 3>& offset = {0, 0, 0});

}  // namespace splinex
