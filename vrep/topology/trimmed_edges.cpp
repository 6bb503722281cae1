// The edges of a trimmed cell's domain cut exactly at the leaves' roots (vrep/topology/trimmed_edges.hpp; a
// step of trimmed_topology), instantiated for Rational and double.
#include <utility>
#include <vector>

#include "bernstein/subdivide.hpp"
#include "solve/solver.hpp"
#include "spline/bezier.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_edges.hpp"
#include "vrep/topology/trimmed_topology.hpp"

namespace splinex::vrep_detail {

namespace {

/// The edge along `along` at sides (s1, s2) of the fixed directions.
template <class T>
typename TrimmedTopology<T>::Edge cut_edge(const BSpline<T>& V, const Region<T>& trim, const std::vector<LeafPiece<T>>& pieces, int along,
                                           int s1, int s2, const SolveOptions& so) {
  auto domain_at = [&](int d, int s) { return s ? V.domain_hi(d) : V.domain_lo(d); };
  auto truth_of = [&](const std::vector<Truth>& t) {
    std::size_t i = 0;
    return combine(trim, t, i);
  };
  typename TrimmedTopology<T>::Edge e;
  e.along = along;
  const int a = along == 0 ? 1 : 0, b = along == 2 ? 1 : 2;  // the fixed directions, a < b
  e.sides[a] = s1;
  e.sides[b] = s2;
  const BSpline<T> C = edge_curve(V, along, e.sides);
  if (vrep_detail::curve_collapsed(C)) {
    e.status = TrimmedTopology<T>::Edge::collapsed;
    return e;
  }
  // Per piece on the edge: the leaves as univariate polynomials along it.
  struct Segment {
    T lo, hi;
    std::vector<Bernstein<T>> g;
  };
  std::vector<Segment> segs;
  struct Event {
    T lo, hi;
  };
  std::vector<Event> events;
  for (const auto& p : pieces) {
    if (!((s1 ? p.hi[a] : p.lo[a]) == domain_at(a, s1)) || !((s2 ? p.hi[b] : p.lo[b]) == domain_at(b, s2))) continue;
    Segment sg{p.lo[along], p.hi[along], {}};
    for (const auto& G : p.G) sg.g.push_back(bern_face(bern_face(G, b, s2), a, s1));  // b > a: remove b first
    for (const auto& g : sg.g) {
      if (all_zero(g)) {
        e.status = TrimmedTopology<T>::Edge::on_trimming_surface;
        continue;
      }
      const SolveResult<T> r = solve_system(std::vector<Bernstein<T>>{g}, {sg.lo}, {sg.hi}, so);
      if (!r.undecided.empty()) e.status = Uncertain<typename TrimmedTopology<T>::Edge::Status>::undecided("a solver box left (tangency)");
      for (const auto& root : r.roots) events.push_back(root.exact ? Event{root.point[0], root.point[0]} : Event{root.lo[0], root.hi[0]});
    }
    segs.push_back(std::move(sg));
  }
  if (e.status != TrimmedTopology<T>::Edge::curve) return e;
  // The truth between consecutive events, at an exact point there.
  auto truth_at = [&](const T& t) {
    for (const auto& sg : segs) {
      if (t < sg.lo || sg.hi < t) continue;
      const std::vector<T> x{(t - sg.lo) / (sg.hi - sg.lo)};
      std::vector<Truth> tr;
      for (const auto& g : sg.g) tr.push_back(value_truth(bern_value(g, x), T(0)));
      return static_cast<int>(truth_of(tr));
    }
    return static_cast<int>(Truth::mixed);
  };
  std::vector<std::pair<T, T>> ev;
  for (const auto& x : events) ev.push_back({x.lo, x.hi});
  const auto runs = edge_runs(ev, V.domain_lo(along), V.domain_hi(along), truth_at);
  if (!runs.decided)
    e.status = Uncertain<typename TrimmedTopology<T>::Edge::Status>::undecided("the truth between the events is not decided");
  e.pieces = runs.pieces;
  e.points = runs.points;
  e.cuts = runs.cuts;
  return e;
}

}  // namespace

template <class T>
void cut_edges(const BSpline<T>& V, const Region<T>& trim, const std::vector<LeafPiece<T>>& pieces,
               std::vector<typename TrimmedTopology<T>::Edge>& edges) {
  SolveOptions so;
  so.recognize_rationals = true;
  for (int along = 0; along < 3; ++along)
    for (int s1 = 0; s1 < 2; ++s1)
      for (int s2 = 0; s2 < 2; ++s2) edges.push_back(cut_edge(V, trim, pieces, along, s1, s2, so));
}

template void cut_edges(const BSpline<Rational>&, const Region<Rational>&, const std::vector<LeafPiece<Rational>>&,
                        std::vector<TrimmedTopology<Rational>::Edge>&);
template void cut_edges(const BSpline<double>&, const Region<double>&, const std::vector<LeafPiece<double>>&,
                        std::vector<TrimmedTopology<double>::Edge>&);

}  // namespace splinex::vrep_detail
