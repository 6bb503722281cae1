// What `splinex cut` reads and prints, written once here (issue 48: the commands build no JSON):
// the solid and cutting documents read by path, and each subcommand's result document - a guide,
// a cutting curve or surface run in exact arithmetic, in double, or both side by side, the
// validity of a given curve or surface, the parts of a split.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "cut/io/documents.hpp"
#include "io/cut_io.hpp"

namespace splinex::cut {

/// A solid document read by path ("-": standard input, read once): its dimension (2 for type
/// "solid2d", 3 otherwise), then the solid read exactly and validated, when the command asks.
class SolidDocument {
 public:
  SolidDocument(const std::string& path, const ReadLimits& read_limits);
  int dimension() const { return dimension_; }
  Solid2<Rational> solid2(const Limits& limits) const;
  Solid3<Rational> solid3(const Limits& limits) const;

 private:
  Json doc_;
  int dimension_ = 2;
};
CutData2<Rational> read_cut2(const std::string& path, const ReadLimits& read_limits);
CutData3 read_cut3(const std::string& path, const ReadLimits& read_limits);
CuttingSurfaceDoc read_cutting_surface(const std::string& path, const Limits& limits, const ReadLimits& read_limits);

/// `cut example NAME`: the example's solid document (with its description) and cutting data.
struct ExampleDocuments {
  Json solid, cut;
};
ExampleDocuments example_documents(const std::string& name);
/// What `cut example` wrote.
Json example_written_document(const std::string& solid_path, const std::string& cut_path);

/// A planar solid (a part of a split) as its document.
Json solid_document(const Solid2<Rational>& S);
/// A cutting surface document: the patch (solid's coordinates) over its domain polygon.
Json cutting_surface_document(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain);

/// One guide run: RDCP's result and, when it has a minimizer, the separation certificate.
template <class T>
struct GuideRun {
  GuideResult<T> result;
  std::optional<SeparationResult> separation;
};
template <class T>
struct GuideRun3 {
  GuideResult3<T> result;
  std::optional<SeparationResult3> separation;
};
/// `cut guide`: the exact run, the double run, or both side by side ({"exact", "double"}, the
/// double coefficients judged exactly against the exact minimizer). Null pointers: not run.
Json guide_runs_document(const GuideRun<Rational>* exact, const GuideRun<double>* dbl);
/// The same on a solid3d; `vtk`: what was written for ParaView (empty: nothing).
Json guide3_runs_document(const GuideRun3<Rational>* exact, const GuideRun3<double>* dbl, const std::string& vtk);

/// `cut facet` on a planar solid: the guide, the fitted cutting curve (solid's coordinates), the
/// march and fit, the curve's validity and, when `out` was given, the split's parts (written only
/// when the curve is valid).
struct CurveFacetRun {
  GuideRun<Rational> guide;
  BSpline<Rational> curve;
  std::size_t march_points = 0;
  double fit_max_deviation = 0;
  ValidityResult validity;
  bool out = false;
  std::optional<std::pair<Solid2<Rational>, Solid2<Rational>>> parts;
};
Json curve_facet_document(const CurveFacetRun& r);

/// `cut certify` on a planar solid: the curve's validity.
Json curve_validity_document(const ValidityResult& v);
/// `cut split` on a planar solid: the parts' files, facets and exact areas.
Json curve_split_document(const std::string& part1, const std::string& part2, const Solid2<Rational>& S1, const Solid2<Rational>& S2);

/// One cutting-surface run: the patch (Steps 1 and 2), its validity and, with --guided, the
/// refinement's steps (Eq. 6 at each weight tried; the last one is the result).
template <class T>
struct SurfaceRun {
  CuttingSurface<T> surface;
  SurfaceValidity validity;
  std::optional<std::vector<GuidedStep>> refined;
};
/// What the surface runs share: the solid's frame and the guide's settings and status.
struct SurfaceRunSettings {
  Frame3 frame;
  GuideOptions3 guide;
  std::string guide_status;  // "exact, optimal", ...
  bool weight_sweep = false; // --weight-guide auto
  bool guided = false;       // --guided was asked for
  bool guide_found = false;  // and RDCP had a minimizer
  bool vtk = false;          // solid.vtk and surface.vtk were written
  bool out = false;          // --out: surface.json written, and the split when valid
  std::optional<SurfaceSplit> split;
};
/// `cut facet` on a solid3d: the exact run, the double run or both side by side.
Json surface_facet_document(const SurfaceRun<Rational>* exact, const SurfaceRun<double>* dbl, const SurfaceRunSettings& s);
/// The final validity of a run: the refined patch's with --guided, else the initial patch's.
template <class T>
const SurfaceValidity& final_validity(const SurfaceRun<T>& r) {
  return r.refined ? r.refined->back().validity : r.validity;
}

/// The patch a run ends with (the refined one with --guided), in the solid's coordinates.
template <class T>
BSpline<Rational> final_patch(const SurfaceRun<T>& r, const Frame3& f) {
  return patch_from_frame(r.refined ? r.refined->back().result.patch : r.surface.patch, f);
}

/// `cut certify` on a solid3d: the surface's validity, its witness in the solid's coordinates.
Json surface_validity_document(const SurfaceValidity& v, const Frame3& f);
/// split.json: the two parts of a valid surface's split as facet lists.
Json surface_split_parts_document(const SurfaceSplit& sp);
/// `cut split` on a solid3d: where split.json is, the parts' sizes and the verdict.
Json surface_split_document(const std::string& split_path, const SurfaceSplit& sp, const Verdict& verdict);

}  // namespace splinex::cut
