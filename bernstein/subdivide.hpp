// The certified subdivision engine: one loop for every budgeted examination of boxes (regularity
// of trivariates, cell shapes, the V-rep's trimming curves, regions, surface traces, Euler
// characteristic and glue witnesses, the subdivision solver, the cutting checks and separation
// certificates). Each use supplies what a box is, how it is examined and how it splits, as
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
// waiting box is left (Left::boxes): with depth first, the last one left is the one that would
// have been examined next. A goal of the whole, reached(), ends the walk before the next
// examination (Stop::reached; the waiting boxes are dropped). Depth-first pops the last child
// emitted first (emit the children in reverse to examine them in order, as a recursion would);
// breadth-first the first. The result is deterministic: it depends on the order, never on timing.
//
// The second form, refine(), refines a partition (adaptive quadrature, covers of a region): every
// box is examined once, when it is made, and stays in the partition until it is split; the budget
// counts the partition's boxes, and a goal of the whole (a width reached, both sides witnessed)
// can end it. Its uses: the V-rep's trimmed classification, the covers of trimmed topology, the
// enclosures of integrals over trimmed cells and of rational cells' volumes.
#pragma once
#include <algorithm>
#include <cstddef>
#include <deque>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace splinex {

/// What examining one box decided. (`replace`: refine() only, the box is no part of the partition
/// but is split at once, e.g. at a plane that decides both parts exactly.)
enum class Examined { settled, refuted, split, left, replace };

/// Why a box stays undecided.
enum class Left { depth, alive, boxes, examined };

/// The order boxes are examined in (subdivide) or split in (refine). Best first: refine() only, the
/// open box of the largest key first.
enum class Order { depth_first, breadth_first, best_first };

/// The limits of one subdivision; the one name for each budget.
struct Budget {
  std::size_t max_boxes = std::numeric_limits<std::size_t>::max();  // boxes examined (refine: in the partition)
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
  enum class Stop { complete, refuted, boxes, left, reached };  // reached: the goal of the whole
  Stop stop = Stop::complete;
  std::size_t examined = 0;    // boxes examined
  std::size_t boxes = 0;       // refine(): the partition's boxes at the end (open ones included)
  int deepest = 0;             // the largest depth examined
  std::size_t left = 0;        // boxes left undecided (all reasons)
  std::size_t left_depth = 0;  // ... of them at max_depth
  std::size_t left_alive = 0;  // ... for the memory budget
  /// Every box settled: nothing refuted, nothing left.
  bool decided() const { return stop == Stop::complete && left == 0; }
};

/// No goal of the whole: a subdivision runs until no box waits, a refutation, or the budget.
struct NoGoal {
  bool operator()() const { return false; }
};

/// One subdivision from `roots` (depth 0). reached(), checked before each examination, is a goal of
/// the whole (enough witnesses found): when it holds the walk stops (Stop::reached) and the boxes
/// still waiting are dropped, neither examined nor left.
template <class Box, class Examine, class Split, class Leave, class Reached = NoGoal>
Subdivision subdivide(std::vector<Box> roots, const Walk& walk, const Budget& budget, Examine&& examine, Split&& split,
                      Leave&& leave, Reached&& reached = Reached{}) {
  struct Node {
    Box box;
    int depth;
  };
  if (walk.order == Order::best_first) throw std::invalid_argument("subdivide: a best-first walk is refine()'s");
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
    if (reached()) {
      out.stop = Subdivision::Stop::reached;
      break;
    }
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
    if (e == Examined::replace) throw std::invalid_argument("subdivide: a replaced box is refine()'s");
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

/// The key of a breadth-first refinement (no priority).
struct NoKey {
  template <class Box>
  int operator()(const Box&) const {
    return 0;
  }
};

/// One refinement of a partition whose first boxes roots(emit) makes: emit(box) examines each at
/// once, before the next is made (so a root decided at once holds no more than it keeps).
///   examine(box) -> settled   closed: part of the partition, nothing to gain by splitting it
///                   split     open: to be split while the budget allows
///                   left      open, not to be split (kept as it is)
///                   replace   not part of the partition: split at once, its parts examined in its place
///                   refuted   the claim is false here: the refinement stops
///   split(std::move(box), depth, emit)   an open (or replaced) box's children, emit(child) in order
///   reached()                            the goal of the whole partition (checked before each split)
///   close(std::move(box), open)          each box of the final partition: a settled one (open false)
///                                        and one kept open (left, or at max_depth) as soon as it is
///                                        examined; the open ones still waiting at the end, in the
///                                        order they would have been split next
///   key(box)                             best first: the open box of the largest key is split first;
///                                        equal keys: the one in the higher slot of the pool, a slot
///                                        freed by a split taken again by the last freed first
/// Every root is examined whatever the budget; then, while an open box waits, the partition holds
/// fewer than budget.max_boxes boxes and the goal is not reached, the next open box (first made
/// first, or best first) is replaced by its children. An open box at budget.max_depth is kept open
/// (Left::depth), not split; budget.max_alive is not used (the partition's size bounds the memory).
/// A refutation stops at once: the refuted box is closed, boxes not yet examined (later roots, the
/// rest of a split) are dropped, neither examined nor closed, and the waiting ones are closed open.
/// Deterministic: the result depends on the order, never on timing.
template <class Box, class Roots, class Examine, class Split, class Reached, class Close, class Key = NoKey>
Subdivision refine_from(Roots&& roots, Order order, const Budget& budget, Examine&& examine, Split&& split, Reached&& reached,
                        Close&& close, Key&& key = Key{}) {
  if (order == Order::depth_first) throw std::invalid_argument("refine: splits breadth first or best first");
  using K = std::decay_t<decltype(key(std::declval<const Box&>()))>;
  struct Node {
    Box box;
    int depth;
  };
  Subdivision out;
  std::deque<Node> fifo;                          // breadth first
  std::vector<Node> pool;                         // best first: the open boxes by slot
  std::vector<std::size_t> free_slots;            // ... slots freed by splits
  std::priority_queue<std::pair<K, std::size_t>> best;  // ... (key, slot)
  bool refuted = false;
  auto wait = [&](Node&& n) {
    if (order == Order::breadth_first) {
      fifo.push_back(std::move(n));
      return;
    }
    std::size_t slot;
    if (!free_slots.empty()) {
      slot = free_slots.back();
      free_slots.pop_back();
      pool[slot] = std::move(n);
    } else {
      slot = pool.size();
      pool.push_back(std::move(n));
    }
    best.push({key(pool[slot].box), slot});
  };
  // Examine a new box and what replaces it, in order (a replaced box's parts before the next box).
  auto make = [&](Node&& first) {
    std::vector<Node> stack;
    stack.push_back(std::move(first));
    while (!stack.empty() && !refuted) {
      Node n = std::move(stack.back());
      stack.pop_back();
      ++out.examined;
      out.deepest = std::max(out.deepest, n.depth);
      const Examined e = examine(n.box);
      if (e == Examined::replace) {
        std::vector<Node> parts;
        split(std::move(n.box), n.depth, [&](Box&& child) { parts.push_back(Node{std::move(child), n.depth + 1}); });
        for (auto it = parts.rbegin(); it != parts.rend(); ++it) stack.push_back(std::move(*it));
        continue;
      }
      ++out.boxes;
      if (e == Examined::settled || e == Examined::refuted) {
        refuted = e == Examined::refuted;
        close(std::move(n.box), false);
      } else if (e == Examined::left || n.depth >= budget.max_depth) {
        ++out.left;
        out.left_depth += e == Examined::left ? 0 : 1;
        close(std::move(n.box), true);
      } else
        wait(std::move(n));
    }
  };
  roots([&](Box&& b) { make(Node{std::move(b), 0}); });
  auto waiting = [&]() { return order == Order::breadth_first ? !fifo.empty() : !best.empty(); };
  while (!refuted && waiting() && out.boxes < budget.max_boxes && !reached()) {
    Node n = [&]() {
      if (order == Order::breadth_first) {
        Node f = std::move(fifo.front());
        fifo.pop_front();
        return f;
      }
      const std::size_t slot = best.top().second;
      best.pop();
      free_slots.push_back(slot);
      return std::move(pool[slot]);
    }();
    --out.boxes;
    std::vector<Node> children;
    split(std::move(n.box), n.depth, [&](Box&& child) { children.push_back(Node{std::move(child), n.depth + 1}); });
    for (auto& c : children) make(std::move(c));
  }
  out.stop = refuted ? Subdivision::Stop::refuted
             : !waiting() ? Subdivision::Stop::complete
             : out.boxes >= budget.max_boxes ? Subdivision::Stop::boxes
                                              : Subdivision::Stop::reached;
  // The open boxes, in the order they would have been split next.
  while (!fifo.empty()) {
    ++out.left;
    close(std::move(fifo.front().box), true);
    fifo.pop_front();
  }
  while (!best.empty()) {
    ++out.left;
    close(std::move(pool[best.top().second].box), true);
    best.pop();
  }
  return out;
}

/// refine_from with the roots in a vector.
template <class Box, class Examine, class Split, class Reached, class Close, class Key = NoKey>
Subdivision refine(std::vector<Box> roots, Order order, const Budget& budget, Examine&& examine, Split&& split, Reached&& reached,
                   Close&& close, Key&& key = Key{}) {
  return refine_from<Box>(
      [&](auto&& emit) {
        for (auto& b : roots) emit(std::move(b));
        roots.clear();
      },
      order, budget, examine, split, reached, close, key);
}

}  // namespace splinex
