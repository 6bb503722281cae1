// The V-model document (JSON), read exactly.
//   {"type": "vmodel",
//    "cells": [{"name": "...", "trivariate": {spline document with three directions, q >= 3}}, ...],
//    "topology": {...}}                     written for the reader's information; ignored on input
// Reading glues the cells' trivariates exactly (vrep/vmodel.hpp), so the topology is always the one
// of the geometry; a "topology" given in the input is not trusted. Unknown fields are refused.
#pragma once
#include <string>
#include <vector>

#include "io/json_io.hpp"
#include "vrep/vmodel.hpp"

namespace splinex {

/// The cells' trivariates and names of a V-model document, or of a plain trivariate document (one
/// cell).
struct VModelCells {
  std::vector<BSpline<Rational>> trivariates;
  std::vector<std::string> names;
};
VModelCells vmodel_cells_from_json(const Json& doc, const Limits& limits = {}, const std::string& where = "vmodel");

/// The document: cells with their trivariates, and the topology (counts, Euler characteristic,
/// V-points, V-curves with ends and V-surfaces, half-V-surfaces with cell, face, twin and loop).
template <class T>
Json vmodel_to_json(const VModel<T>& M);

}  // namespace splinex
