// The teapot's V-model (papers/002 Figure 14, Table 1's teapot row), built exactly from trivariates
// that have no implicit form (vrep/freeform/freeform.hpp on fixtures/teapot_vmodel.hpp's solids): the body
// shell, the solid handle and spout, and the cavity subtracted from them. One run per arithmetic
// (exact: certified; double: the same steps in floats), its figure and its ParaView file.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "io/json_io.hpp"
#include "vrep/freeform/freeform.hpp"

namespace splinex {

template <class T>
struct TeapotVModel {
  struct Row {
    std::string name, trivariate, conditions;
    FreeformCell<T> cell;
    FreeformEdges<T> edges;  // the cell's V-curves and V-points on its trivariate's edges
    double seconds = 0, seconds_edges = 0;
  };
  /// The model's cells: body - handle - spout, handle & body, handle - body - cavity, spout & body,
  /// spout - body - cavity (a cell with k components stands for k V-cells).
  std::vector<Row> cells;
  /// What the subtraction removes: handle & cavity, spout & cavity (for the volume balance).
  std::vector<Row> removed;
  std::map<std::string, BSpline<T>> trivariates;  // body, handle, spout, cavity
  double seconds_solids = 0;                      // boundaries and pieces of the four solids
  double seconds = 0;                             // everything
};

/// The V-model with `boxes` subdivision boxes per cell; progress lines (one per cell and the
/// solver's periodic ones) go to `progress`.
template <class T>
TeapotVModel<T> teapot_vmodel(std::size_t boxes, const std::function<void(const std::string&)>& progress = {});

/// The model as `splinex vrep teapot` prints it: per cell its edges, kind, components, volume
/// (certified enclosure in exact arithmetic), boxes and time; the cells removed by the subtraction.
template <class T>
Json teapot_document(const TeapotVModel<T>& M);

/// An exploded view (SVG): per cell the faces of its boxes on its trivariate's boundary (in-boxes
/// in the cell's colour, boxes near a trimming surface pale), cells moved apart along x.
std::string teapot_vmodel_svg(const TeapotVModel<Rational>& M);

/// The cells' boxes as hexahedra through their corner points (legacy VTK, cell data: cell index and
/// in = 2 / near a trimming surface = 1) for ParaView.
std::string teapot_vmodel_vtk(const TeapotVModel<Rational>& M);

}  // namespace splinex
