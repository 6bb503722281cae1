// The float surface-surface intersection judged exactly (vrep/boolean/ssi.hpp): one run's numbers, its
// figure, and the report section on the teapot's handle and body (papers/002 Figures 10 and 14).
#pragma once
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "io/json_io.hpp"
#include "spline/bspline.hpp"
#include "vrep/boolean/ssi.hpp"

namespace splinex {

struct SsiStudy {
  SsiResult result;
  double seconds_float = 0, seconds_judge = 0;
  // The computed points (vertices) and the midpoints of the polylines' segments in the parameter
  // planes (the trimming curves between the vertices): how many, how many certified, the largest
  // exact gap |S1 - S2| and the largest certified distance bound from the true intersection.
  std::size_t vertices = 0, vertices_certified = 0, midpoints = 0, midpoints_certified = 0;
  double max_vertex_gap = 0, max_vertex_distance = 0, max_mid_gap = 0, max_mid_distance = 0;  // rounded up
  std::vector<std::string> uncertified;  // why, per reason, with counts
};

/// Runs intersect_surfaces on the surfaces rounded to double and, with `judge`, judges every
/// vertex and segment midpoint against the exact surfaces (judge_point). `progress` gets a line
/// per branch judged.
SsiStudy ssi_study(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiOptions& options, bool judge,
                   void (*progress)(const std::string&) = nullptr);

/// The loops in space: chains of branches whose end points (on S1, in double) meet within `tol`
/// all around, closed branches included.
std::size_t loops_in_space(const BSpline<Rational>& S1, const SsiResult& r, double tol);

/// `splinex vrep ssi`'s result: the branches as (u, v, s, t) points, the counts, the loops in
/// space (ends meeting within a quarter step), a warning for tangential stops and, with `judge`,
/// the exact judgement of the points.
Json ssi_document(const BSpline<Rational>& S1, const SsiStudy& st, const SsiOptions& options, bool judge);

/// The branches in the two parameter planes, side by side (SVG).
std::string ssi_svg(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiResult& r, const std::string& name1,
                    const std::string& name2, const std::string& title);

/// The branches as 3D polylines (Wavefront OBJ, `l` elements) for ParaView.
std::string ssi_obj(const BSpline<Rational>& S1, const SsiResult& r);

/// A teapot surface by name (body, handle, spout, lid) from data/teapot.bpt, exactly.
BSpline<Rational> teapot_surface(const std::string& name);

}  // namespace splinex
