// The V-rep package's facade (issue 48): what every caller of V-rep does with documents - the CLI,
// the report's studies, Python, the sweeps - written once: read a model (glued, attributes applied,
// its exact region checked against the cells, validated), read a Boolean operand, and run a Boolean
// that takes the planar path (cells cut along parameter planes) where it suffices and the trimmed
// path (cells trimmed by exact regions) otherwise, exactly or in double with a tolerance.
//
// It lives in vrep/io/, above io/: it reads and writes documents. The algorithms stay in vrep/.
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "io/json_io.hpp"
#include "io/trimmed_io.hpp"
#include "io/vmodel_io.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/validate.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex::vrep {

/// An exact V-model read from documents: the cells glued exactly, their attributes, the region the
/// documents give ("implicit": checked against the cells, refused when it does not describe them),
/// and the validity report (a proved defect is a ValidationError naming the cells).
struct LoadedModel {
  VModel<Rational> model;
  std::optional<Region<Rational>> region;
  ValidityReport validity;
};

/// The cells of one or more V-model or trivariate documents, appended (the names of several files
/// are the files' paths).
VModelCells read_cells(const std::vector<std::string>& files, const Limits& limits, const ReadLimits& read_limits);
/// The model of those cells; `levels`: subdivision levels of the validity's regularity test.
LoadedModel model_of(const VModelCells& cells, const Limits& limits, int levels = 6);
LoadedModel load_model(const std::vector<std::string>& files, const Limits& limits, const ReadLimits& read_limits, int levels = 6);

/// A Boolean operand: a trimmed V-model document as it is; or a V-model with its region ("implicit",
/// or the half-spaces of convex planar cells), as a model and as trimmed cells; or the V-model alone
/// (no region known: planar cuts only).
struct Operand {
  std::optional<VModel<Rational>> model;
  std::optional<TrimmedModel<Rational>> trimmed;
  ValidityReport validity;
};
Operand load_operand(const std::string& file, const Limits& limits, const ReadLimits& read_limits);

/// How a Boolean may cut: automatic (planar cuts where they suffice, else trimmed cells), always
/// trimmed, never trimmed (a cut that is not a parameter plane is then an error).
enum class TrimMode { automatic, always, never };
TrimMode parse_trim_mode(const std::string& name);  // "auto", "always", "never"; UsageError otherwise

struct BooleanRequest {
  BooleanOp op = BooleanOp::intersect;
  Blend blend = Blend::sum_clipped;
  TrimMode trim = TrimMode::automatic;
  std::size_t boxes = 4096;   // trimmed cells: the subdivision budget per cell
  std::optional<double> eps;  // absent: exact; else the models rounded to double, IRIT-style tolerance
};

/// The result: a V-model (planar cuts) or trimmed cells, exact or in double.
using BooleanResult = std::variant<VModel<Rational>, VModel<double>, TrimmedModel<Rational>, TrimmedModel<double>>;
BooleanResult boolean(const Operand& first, const Operand& second, const BooleanRequest& request, const Limits& limits = {});
/// The result's document (vmodel_to_json or trimmed_to_json).
Json document(const BooleanResult& result);

/// A trimmed V-model document (type "trimmed_vmodel", the output of a Boolean with trimmed cells)
/// read exactly; another document is a ValidationError naming the file.
TrimmedModel<Rational> read_trimmed_model(const std::string& file, const Limits& limits, const ReadLimits& read_limits);

}  // namespace splinex::vrep
