#include "cut/io/commands.hpp"

#include "cut/examples.hpp"

namespace splinex::cut {

SolidDocument::SolidDocument(const std::string& path, const ReadLimits& read_limits)
    : doc_(read_json_file(path, read_limits)), dimension_(solid_document_type(doc_) == "solid3d" ? 3 : 2) {}

Solid2<Rational> SolidDocument::solid2(const Limits& limits) const { return solid2_from_json(doc_, limits); }

Solid3<Rational> SolidDocument::solid3(const Limits& limits) const { return solid3_from_json(doc_, limits); }

CutData2<Rational> read_cut2(const std::string& path, const ReadLimits& read_limits) { return cut2_from_json(read_json_file(path, read_limits)); }

CutData3 read_cut3(const std::string& path, const ReadLimits& read_limits) { return cut3_from_json(read_json_file(path, read_limits)); }

CuttingSurfaceDoc read_cutting_surface(const std::string& path, const Limits& limits, const ReadLimits& read_limits) {
  return cutting_surface_from_json(read_json_file(path, read_limits), limits);
}

ExampleDocuments example_documents(const std::string& name) {
  ExampleDocuments d;
  const auto names3 = cut_example3_names();
  if (std::find(names3.begin(), names3.end(), name) != names3.end()) {
    const auto e = cut_example3(name);
    d.solid = solid3_to_json(e.solid), d.cut = cut3_to_json(e.cut);
    d.solid["description"] = e.description;
  } else {
    const auto e = cut_example(name);
    d.solid = solid2_to_json(e.solid), d.cut = cut2_to_json(e.cut);
    d.solid["description"] = e.description;
  }
  return d;
}

Json example_written_document(const std::string& solid_path, const std::string& cut_path) { return Json{{"solid", solid_path}, {"cut", cut_path}}; }

Json solid_document(const Solid2<Rational>& S) { return solid2_to_json(S); }

Json cutting_surface_document(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain) {
  return cutting_surface_to_json(patch, domain);
}

namespace {

// One run's document, or both side by side with the double coefficients judged against the exact.
template <class Run, class Doc>
Json runs_document(const Run* exact, const auto* dbl, const Doc& doc) {
  if (exact && dbl) {
    Json d = doc(*dbl);
    const auto &R = exact->result, &D = dbl->result;
    if (D.status == QPStatus::optimal && R.status == QPStatus::optimal && D.coefficients.size() == R.coefficients.size())
      d["judged_against_exact"] = judged_against_exact(R.coefficients, D.f_exact.points);
    return Json{{"exact", doc(*exact)}, {"double", d}};
  }
  return exact ? doc(*exact) : doc(*dbl);
}

}  // namespace

Json guide_runs_document(const GuideRun<Rational>* exact, const GuideRun<double>* dbl) {
  return runs_document(exact, dbl, [](const auto& r) { return guide_json(r.result, r.separation); });
}

Json guide3_runs_document(const GuideRun3<Rational>* exact, const GuideRun3<double>* dbl, const std::string& vtk) {
  Json out = runs_document(exact, dbl, [](const auto& r) { return guide3_json(r.result, r.separation); });
  if (!vtk.empty()) out["vtk"] = vtk;
  return out;
}

namespace {

// The two parts of a planar split: their facets and exact areas, which add up to the solid's.
Json parts_document(const Solid2<Rational>& S1, const Solid2<Rational>& S2) {
  return Json{{"part1_facets", S1.facets.size()}, {"part2_facets", S2.facets.size()},
              {"areas", Json::array({q_json(signed_area(S1)), q_json(signed_area(S2))})},
              {"area_check", "area(part1) + area(part2) = area(solid), exactly"}};
}

}  // namespace

Json curve_facet_document(const CurveFacetRun& r) {
  Json out{{"guide", guide_json(r.guide.result, r.guide.separation)},
           {"curve", spline_to_json(r.curve)},
           {"march_points", r.march_points},
           {"fit_max_deviation_normalized", r.fit_max_deviation},
           {"validity", validity_json(r.validity)}};
  out["guide"].erase("guide");
  if (r.out) {
    out["split"] = r.parts ? parts_document(r.parts->first, r.parts->second) : Json("not written: the curve is not certified valid");
  }
  return out;
}

Json curve_validity_document(const ValidityResult& v) { return validity_json(v); }

Json curve_split_document(const std::string& part1, const std::string& part2, const Solid2<Rational>& S1, const Solid2<Rational>& S2) {
  Json out = parts_document(S1, S2);
  out["part1"] = part1;
  out["part2"] = part2;
  return out;
}

namespace {

// One surface run: the initial patch's program and validity and, with --guided, the refined
// patch's validity, run and surface as the result.
template <class T>
Json surface_run_document(const SurfaceRun<T>& r, const SurfaceRunSettings& s) {
  Json j = surface_json(r.surface, s.frame);
  j["validity"] = surface_validity_json(r.validity, s.frame);
  if (r.refined) {
    const GuidedStep& last = r.refined->back();
    j["initial_validity"] = j["validity"];
    j["validity"] = surface_validity_json(last.validity, s.frame);
    j["guided"] = guided_json(last.result, last.weight, s.guide, s.guide_status);
    if (s.weight_sweep) {
      Json sweep = Json::array();
      for (const auto& st : *r.refined)
        sweep.push_back(Json{{"weight", st.weight}, {"max_abs_f_after", st.result.max_abs_f_after}, {"verdict", validity_word(st.validity.verdict)}});
      j["guided"]["weight_sweep"] = sweep;
      j["guided"]["weight_meaning"] = "--weight-guide auto: Eq. 6's weight 10, 10^2, ..., 10^6 in turn, each from the initial patch, until the refined patch is "
                                      "certified valid; the last one run is the result";
    }
    j["surface"] = cutting_surface_to_json(patch_from_frame(last.result.patch, s.frame), r.surface.domain.vertices);
  }
  return j;
}

}  // namespace

Json surface_facet_document(const SurfaceRun<Rational>* exact, const SurfaceRun<double>* dbl, const SurfaceRunSettings& s) {
  Json out;
  bool valid = false;
  if (exact) {
    out = surface_run_document(*exact, s);
    valid = final_validity(*exact).verdict.is_proved();
    if (dbl) {
      Json d = surface_run_document(*dbl, s);
      d["judged_against_exact"] = judged_against_exact(exact->surface.coefficients, dbl->surface.coefficients);
      d["judged_against_exact"]["meaning"] = "the double initial patch's control points against the exact minimizer, measured exactly (normalized coordinates)";
      out = Json{{"exact", out}, {"double", d}};
    }
  } else {
    out = surface_run_document(*dbl, s);
    valid = final_validity(*dbl).verdict.is_proved();
  }
  if (s.guided && !s.guide_found)
    out["guided"] = Json{{"guide", s.guide_status},
                         {"meaning", "no refinement: RDCP has no minimizer at these settings (raise --max-inner-knots, lower --delta or widen --strip); "
                                     "the surface and validity above are the initial patch's"}};
  if (s.vtk) out["vtk"] = "solid.vtk and surface.vtk written";
  if (s.out) {
    if (valid && s.split)
      out["split"] = Json{{"part1_facets", s.split->part1.size()}, {"part2_facets", s.split->part2.size()}, {"file", "split.json"}};
    else
      out["split"] = "not written: the surface is not certified valid";
  }
  return out;
}

Json surface_validity_document(const SurfaceValidity& v, const Frame3& f) { return surface_validity_json(v, f); }

Json surface_split_parts_document(const SurfaceSplit& sp) {
  return Json{{"part1", Json{{"facets", sp.part1}, {"cutting_surface", "surface.json"}, {"meaning", "the facets of b and the cutting surface"}}},
              {"part2", Json{{"facets", sp.part2}, {"cutting_surface", "surface.json, reversed"}, {"meaning", "the facets of b-bar and the cutting surface"}}}};
}

Json surface_split_document(const std::string& split_path, const SurfaceSplit& sp, const Verdict& verdict) {
  return Json{{"split", split_path}, {"part1_facets", sp.part1.size()}, {"part2_facets", sp.part2.size()},
              {"verdict", validity_word(verdict)},
              {"meaning", "the surface certified valid (cut certify), the parts as facet lists with the trimmed patch (not solids: the patch is trimmed)"}};
}

}  // namespace splinex::cut
