// Implicit regions and trimmed V-models as JSON (vrep/trimmed/trimmed.hpp), read exactly.
//   region:  {"leaf": [[c, a, b, e], ...], "label": "..."}   g = sum c x^a y^b z^e, the set g >= 0
//                                                            (c a number: integer, decimal or p/q text)
//          | {"all": [region, ...]} | {"any": [region, ...]} | {"not": region}
//   A V-model document may carry "implicit": region, its point set (vrep primitive writes it); it is
//   checked when read (check_region: every cell whole inside it, every boundary face on a surface).
//   {"type": "trimmed_vmodel",
//    "region": region,                            the model's point set
//    "cells": [{"name": ..., "category": "A" | "both" | "B" | "", "status": "whole" | "cut",
//               "trivariate": {spline document}, "trim": region (the cell is T restricted to it),
//               "inherited": [indices into inherited_trivariates], "constants": {"NAME": [numbers]}}],
//    "inherited_trivariates": [{spline document}, ...]}
// Nesting is limited to 64 levels and a region to 4096 leaves of degree <= 8 (SizeLimitError).
// A trimmed document's "region" and "trim"s are taken as written (vrep boolean writes them
// consistently; a status given is recomputed, not trusted). Unlike a V-model's "implicit", they are
// not checked against the cells: a hand-edited region that does not match the cells makes later
// Booleans and point classification wrong, so edit trimmed documents through vrep boolean only.
#pragma once
#include <string>

#include "io/json_io.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

Region<Rational> region_from_json(const Json& j, const std::string& where = "region");
template <class T>
Json region_to_json(const Region<T>& R);

TrimmedModel<Rational> trimmed_from_json(const Json& doc, const Limits& limits = {}, const std::string& where = "trimmed_vmodel");
template <class T>
Json trimmed_to_json(const TrimmedModel<T>& M);

}  // namespace splinex
