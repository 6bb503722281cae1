// The certified subdivision engine: one loop for every budgeted examination of boxes (regularity
// of trivariates, cell shapes, the V-rep's trimming curves and regions, the subdivision solver,
// the cutting checks). Each use supplies what a box is, how it is examined and how it splits, as
// Arrangement_2 writes its sweep once against a traits class; the engine owns the order, the
// budget and the stop reason.
//
//   examine(box, depth) -> Examined::settled   decided on this box (a sign proved, excluded)
//                          Examined::refuted   the claim is false here: the subdivision stops
//                          Examined::split     undecided here: split it, if the budget allows
//                          Examined::left      undecided here, not to be split (a leaf)
//   split(std::move(box), depth, emit)         calls emit(child) for each child, in order
//   leave(std::move(box), Left why)            a box that stays undecided, and why
//
// A box at depth max_depth that asks to be split is left (Left::depth), as is one whose children
// would make more than max_alive boxes wait at once (Left::alive, the memory budget); the loop
// goes on with the others, or stops at the first box left when the walk says so (a claim that one
// undecided box already leaves undecided). After max_boxes examinations it stops, and every
// waiting box is left (Left::boxes). Depth-first pops the last child emitted first; breadth-first
// the first. The result is deterministic: it depends on the order, never on timing.
#pragma once
#include <algorithm>
#include <cstddef>
#include <deque>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace splinex {

/// What examining one box decided.
enum class Examined { settled, refuted, split, left };

/// Why a box stays undecided.
enum class Left { depth, alive, boxes, examined };

/// The order boxes are examined in.
enum class Order { depth_first, breadth_first };

/// The limits of one subdivision; the one name for each budget.
struct Budget {
  std::size_t max_boxes = std::numeric_limits<std::size_t>::max();  // boxes examined
  std::size_t max_alive = std::numeric_limits<std::size_t>::max();  // boxes waiting at once (memory)
  int max_depth = std::numeric_limits<int>::max();                   // splits from a root to a box
};

/// How the boxes are walked: the order, the most children one split emits (the memory budget is
/// checked before a split: waiting + fanout > max_alive leaves the box), and whether the first box
/// left ends the walk.
struct Walk {
  Order order = Order::breadth_first;
  std::size_t fanout = 2;
  bool stop_at_first_left = false;
};

/// What a subdivision did, and why it stopped.
struct Subdivision {
  enum class Stop { complete, refuted, boxes, left };
  Stop stop = Stop::complete;
  std::size_t examined = 0;    // boxes examined
  int deepest = 0;             // the largest depth examined
  std::size_t left = 0;        // boxes left undecided (all reasons)
  std::size_t left_depth = 0;  // ... of them at max_depth
  std::size_t left_alive = 0;  // ... for the memory budget
  /// Every box settled: nothing refuted, nothing left.
  bool decided() const { return stop == Stop::complete && left == 0; }
};

/// One subdivision from `roots` (depth 0).
template <class Box, class Examine, class Split, class Leave>
Subdivision subdivide(std::vector<Box> roots, const Walk& walk, const Budget& budget, Examine&& examine, Split&& split,
                      Leave&& leave) {
  struct Node {
    Box box;
    int depth;
  };
  std::deque<Node> waiting;
  for (auto& b : roots) waiting.push_back(Node{std::move(b), 0});
  Subdivision out;
  // A box left undecided; true when that ends the walk.
  auto left = [&](Box&& b, Left why) {
    ++out.left;
    out.left_depth += why == Left::depth ? 1 : 0;
    out.left_alive += why == Left::alive ? 1 : 0;
    leave(std::move(b), why);
    if (walk.stop_at_first_left && why != Left::boxes) out.stop = Subdivision::Stop::left;
    return out.stop == Subdivision::Stop::left;
  };
  while (!waiting.empty()) {
    if (out.examined >= budget.max_boxes) {
      out.stop = Subdivision::Stop::boxes;
      while (!waiting.empty()) {
        left(std::move(waiting.front().box), Left::boxes);
        waiting.pop_front();
      }
      break;
    }
    Node n = walk.order == Order::breadth_first ? std::move(waiting.front()) : std::move(waiting.back());
    if (walk.order == Order::breadth_first)
      waiting.pop_front();
    else
      waiting.pop_back();
    ++out.examined;
    out.deepest = std::max(out.deepest, n.depth);
    const Examined e = examine(n.box, n.depth);
    if (e == Examined::settled) continue;
    if (e == Examined::refuted) {
      out.stop = Subdivision::Stop::refuted;
      break;
    }
    if (e == Examined::left) {
      if (left(std::move(n.box), Left::examined)) break;
      continue;
    }
    if (n.depth >= budget.max_depth) {
      if (left(std::move(n.box), Left::depth)) break;
      continue;
    }
    if (walk.fanout > budget.max_alive || waiting.size() > budget.max_alive - walk.fanout) {  // no wrap-around
      if (left(std::move(n.box), Left::alive)) break;
      continue;
    }
    const int d = n.depth + 1;
    split(std::move(n.box), n.depth, [&](Box&& child) { waiting.push_back(Node{std::move(child), d}); });
  }
  return out;
}

}  // namespace splinex
