// V-models as VTK unstructured grids (.vtu, XML, ASCII) of Bezier hexahedra (cell type 79,
// VTK_BEZIER_HEXAHEDRON, VTK >= 9), so ParaView shows the exact geometry of every Bezier piece of
// every cell's trivariate, not a tessellation:
//  - the points of each piece in VTK's order for higher-order hexahedra (vtk_hex_index: corners,
//    edges, faces, interior; vtkHigherOrderHexahedron::PointIndexFromIJK);
//  - cell data HigherOrderDegrees (p, q, r) per piece, and "vcell" (the V-cell of the piece);
//  - point data RationalWeights (all 1 for polynomial cells) and one array per attribute coordinate
//    (point coordinates beyond the third).
// Numbers are written with 17 significant digits: each reads back as the double nearest to the
// exact value (docs/vrep/model.md; tests/vrep/test_vtk.py reads the file with VTK and compares).
#pragma once
#include <array>
#include <string>

#include "vrep/model/vmodel.hpp"

namespace splinex {

/// The position of control point (i, j, k) of a Bezier hexahedron of degrees `order` in VTK's
/// point order.
std::size_t vtk_hex_index(int i, int j, int k, const std::array<int, 3>& order);

template <class T>
std::string vmodel_to_vtu(const VModel<T>& M);

}  // namespace splinex
