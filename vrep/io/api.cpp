// The V-rep facade (vrep/io/api.hpp): reading models and operands, and the Boolean's choice of the
// planar or trimmed path - moved here from the command line (apps/cmd_vrep.cpp), unchanged.
#include "vrep/io/api.hpp"

#include <cmath>

#include "float/rounding.hpp"

namespace splinex::vrep {

VModelCells read_cells(const std::vector<std::string>& files, const Limits& limits, const ReadLimits& read_limits) {
  VModelCells all;
  for (std::size_t f = 0; f < files.size(); ++f)
    append_cells(all, vmodel_cells_from_json(read_json_file(files[f], read_limits), limits, files.size() == 1 ? "vmodel" : files[f]));
  return all;
}

LoadedModel model_of(const VModelCells& all, const Limits& limits, int levels) {
  auto M = glue(all.trivariates, Rational(0), all.names, limits);
  apply_attributes(M, all, limits);
  if (all.region) {
    const auto fails = check_region(M, *all.region, TrimOptions{}, limits);
    if (!fails.empty())
      throw ValidationError("vmodel.implicit",
                            "does not describe the cells: " + fails.front() +
                                (fails.size() > 1 ? " (and " + std::to_string(fails.size() - 1) + " more)" : ""),
                            "remove \"implicit\" or give the model's exact region");
  }
  ValidityOptions vo;
  vo.levels = levels;
  auto validity = validate_vmodel(M, "vmodel", vo, limits);
  return LoadedModel{std::move(M), all.region, std::move(validity)};
}

LoadedModel load_model(const std::vector<std::string>& files, const Limits& limits, const ReadLimits& read_limits, int levels) {
  return model_of(read_cells(files, limits, read_limits), limits, levels);
}

Operand load_operand(const std::string& file, const Limits& limits, const ReadLimits& read_limits) {
  Operand o;
  const Json doc = read_json_file(file, read_limits);
  if (doc.is_object() && doc.contains("type") && doc["type"] == "trimmed_vmodel") {
    o.trimmed = trimmed_from_json(doc, limits, file);
    o.validity = validate_trimmed(*o.trimmed, file, {}, limits);
    return o;
  }
  auto r = model_of(vmodel_cells_from_json(doc, limits, "vmodel"), limits, 6);
  if (!r.region) r.region = planar_region(r.model);
  if (r.region) o.trimmed = as_trimmed(r.model, *r.region);
  o.model = std::move(r.model);
  o.validity = std::move(r.validity);
  return o;
}

TrimMode parse_trim_mode(const std::string& name) {
  if (name == "auto") return TrimMode::automatic;
  if (name == "always") return TrimMode::always;
  if (name == "never") return TrimMode::never;
  throw UsageError("trim", "\"" + name + "\" is not a trim mode", "give auto, always or never");
}

namespace {

const char* region_fix =
    "curved cuts need both models' exact regions (\"implicit\"): vrep primitive writes one for box, cylinder, cone, "
    "torus and sphere (patch degree <= 4); glued or constructed models of curved cells have none: place such a model so "
    "that every cut is a parameter plane of its cells, or give its region";

/// The model's cells and attributes rounded to double (a value beyond double's range is a typed
/// error), glued with tolerance eps.
VModel<double> in_double(const VModel<Rational>& M, const std::string& field, double eps, const Limits& limits) {
  std::vector<BSpline<double>> d;
  std::vector<std::string> names;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    d.push_back(round_spline<double>(M.trivariates[M.cells[c].trivariates.front()], field + ".cells[" + std::to_string(c) + "]"));
    names.push_back(M.cells[c].name);
  }
  auto G = glue(d, eps, names, limits);
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const std::string w = field + ".cells[" + std::to_string(c) + "].attributes.";
    for (const auto& [n, v] : M.cells[c].attributes.constants)
      for (const auto& y : v) G.cells[c].attributes.constants[n].push_back(round_checked<double>(y, w + n));
    for (const auto& [n, F] : M.cells[c].attributes.fields) G.cells[c].attributes.fields.emplace(n, round_spline<double>(F, w + n));
  }
  return G;
}

}  // namespace

BooleanResult boolean(const Operand& A, const Operand& B, const BooleanRequest& rq, const Limits& limits) {
  TrimOptions topt;
  topt.max_boxes = rq.boxes;
  // Curved cuts need both models' exact regions.
  const auto need_regions = [&]() {
    if (!A.trimmed || !B.trimmed)
      throw DomainError(A.trimmed ? "second" : "first", "has curved cells and no exact region, and its cells are cut along curved surfaces",
                        region_fix);
  };
  // A planar cut that is not a parameter plane where an operand has no region.
  const auto no_region = [&](const NotPlanarError& e) {
    return DomainError(A.trimmed ? "second" : "first",
                       "has no exact region, and the Boolean cuts a cell along a surface that is not a parameter plane of its "
                       "trivariate (" + e.field() + ")",
                       region_fix);
  };
  const bool planar_possible = A.model && B.model && rq.trim != TrimMode::always;
  const auto check_never = [&]() {
    if (!planar_possible && rq.trim == TrimMode::never)
      throw DomainError("trim", "is never, but an operand is a trimmed V-model", "give --trim auto");
  };
  if (!rq.eps) {
    check_never();
    const auto trimmed = [&]() -> BooleanResult {
      need_regions();
      return trimmed_boolean(*A.trimmed, *B.trimmed, rq.op, rq.blend, topt, Rational(0), limits);
    };
    if (!planar_possible) return trimmed();
    try {
      return boolean_op(*A.model, *B.model, rq.op, Rational(0), rq.blend, limits);
    } catch (const NotPlanarError& e) {
      // A cut that is not a parameter plane: trimmed cells, where both regions are known.
      if (rq.trim == TrimMode::never) throw;
      if (!A.trimmed || !B.trimmed) throw no_region(e);
    }
    return trimmed();
  }
  const double eps = *rq.eps;
  if (!(eps > 0) || !std::isfinite(eps)) throw UsageError("eps", "must be a positive double", "give e.g. --eps 1e-9");
  check_never();
  // Trimmed cells in double: the models and regions rounded, coefficients within eps count as 0.
  const auto trimmed_in_double = [&]() -> BooleanResult {
    need_regions();
    return trimmed_boolean(trimmed_to_double(*A.trimmed), trimmed_to_double(*B.trimmed), rq.op, rq.blend, topt, eps, limits);
  };
  if (!planar_possible) return trimmed_in_double();
  try {
    return boolean_op(in_double(*A.model, "first", eps, limits), in_double(*B.model, "second", eps, limits), rq.op, eps, rq.blend, limits);
  } catch (const NotPlanarError& e) {
    if (rq.trim == TrimMode::never) throw;
    if (!A.trimmed || !B.trimmed) throw no_region(e);
  }
  return trimmed_in_double();
}

TrimmedModel<Rational> read_trimmed_model(const std::string& file, const Limits& limits, const ReadLimits& read_limits) {
  const Json doc = read_json_file(file, read_limits);
  if (!doc.is_object() || !doc.contains("type") || doc["type"] != "trimmed_vmodel")
    throw ValidationError(file, "is not a trimmed V-model document (type \"trimmed_vmodel\")",
                          "give the output of vrep boolean with trimmed cells; a V-model's own topology is in vrep info");
  return trimmed_from_json(doc, limits, file);
}

Json document(const BooleanResult& result) {
  return std::visit(
      [](const auto& M) -> Json {
        using M_t = std::decay_t<decltype(M)>;
        if constexpr (std::is_same_v<M_t, VModel<Rational>> || std::is_same_v<M_t, VModel<double>>) return vmodel_to_json(M);
        else return trimmed_to_json(M);
      },
      result);
}

}  // namespace splinex::vrep
