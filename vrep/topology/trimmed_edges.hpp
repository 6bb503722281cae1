// The edges of a trimmed cell's domain cut at the leaves' roots (vrep/topology/trimmed_edges.cpp): a step of
// trimmed_topology (vrep/topology/trimmed_topology.cpp), internal to vrep/topology/.
#pragma once
#include <vector>

#include "vrep/topology/trimmed_topology.hpp"

namespace splinex::vrep_detail {

template <class T>
struct LeafPiece;

/// Edges: exact cuts at the leaves' roots along each of the 12 edges of V's domain (along u, v, w;
/// per along, the sides of the two fixed directions), appended to `edges` in that order. `pieces`:
/// the leaves of `trim` on V's Bezier pieces.
template <class T>
void cut_edges(const BSpline<T>& V, const Region<T>& trim, const std::vector<LeafPiece<T>>& pieces,
               std::vector<typename TrimmedTopology<T>::Edge>& edges);

}  // namespace splinex::vrep_detail
