// The V-model document (JSON), read exactly.
//   {"type": "vmodel",
//    "cells": [{"name": "...", "trivariate": {spline document with three directions, q >= 3},
//               "inherited": [indices into inherited_trivariates] (the trivariates that contain the
//                            cell besides its own: the sources of a Boolean's cell, Section 4),
//               "attributes": {"NAME": [numbers] (a constant) | {spline document} (a field: an
//                              attribute trivariate on the cell's domain)}}, ...],
//    "inherited_trivariates": [{spline document}, ...],
//    "surface_attributes": [{"cell": i, "face": [direction, side], "attributes": {"NAME": [numbers]}}],
//    "curve_attributes":   [{"cell": i, "along": d, "sides": [s0, s1, s2], "attributes": {...}}],
//    "point_attributes":   [{"cell": i, "corner": [s0, s1, s2], "attributes": {...}}],
//    "implicit": region (io/trimmed_io.hpp; optional: the model's exact point set, checked by readers),
//    "topology": {...}}                     written for the reader's information; ignored on input
// Entity attributes are addressed by a cell's face, edge or corner and land on the V-surface,
// V-curve or V-point that is there after gluing.
// Reading glues the cells' trivariates exactly (vrep/model/vmodel.hpp), so the topology is always the one
// of the geometry; a "topology" given in the input is not trusted. Unknown fields are refused.
#pragma once
#include <string>
#include <vector>

#include "io/json_io.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The cells' trivariates and names of a V-model document, or of a plain trivariate document (one
/// cell).
struct VModelCells {
  std::vector<BSpline<Rational>> trivariates;
  std::vector<std::string> names;
  std::vector<std::pair<Json, std::size_t>> attribute_docs;  // (document, index of its first cell)
  std::vector<BSpline<Rational>> inherited;                  // inherited trivariates of all documents
  std::vector<std::vector<std::size_t>> inherits;            // per cell: indices into `inherited`
  std::optional<Region<Rational>> region;                     // "implicit": the point set (unchecked here)
};
VModelCells vmodel_cells_from_json(const Json& doc, const Limits& limits = {}, const std::string& where = "vmodel");
/// Appends the cells of another document (cell indices of its attributes shifted).
void append_cells(VModelCells& into, VModelCells more);

/// The attributes of the documents attached to the glued model (ValidationError naming the field
/// for a bad address or value), and the cells' inherited trivariates appended to its trivariates.
void apply_attributes(VModel<Rational>& M, const VModelCells& cells, const Limits& limits = {});

/// A list of names (e.g. a cell's `fields_not_carried`): ValidationError naming `where` for
/// anything but an array of strings.
std::vector<std::string> names_from_json(const Json& j, const std::string& where);

/// Named constant attributes as {"NAME": [numbers]}.
template <class T>
Json constants_to_json(const std::map<std::string, std::vector<T>>& m) {
  Json o = Json::object();
  for (const auto& [n, v] : m) {
    Json a = Json::array();
    for (const auto& x : v) a.push_back(ArithTraits<T>::to_json(x));
    o[n] = a;
  }
  return o;
}

/// The document: cells with their trivariates, and the topology (counts, Euler characteristic,
/// V-points, V-curves with ends and V-surfaces, half-V-surfaces with cell, face, twin and loop).
template <class T>
Json vmodel_to_json(const VModel<T>& M);

}  // namespace splinex
