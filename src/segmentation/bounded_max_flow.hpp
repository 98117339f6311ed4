// The maximum flow (and a minimum cut) of a sparse graph with integer capacities, within a cap
// on its work. Boykov and Kolmogorov's augmenting paths on two search trees ("An Experimental
// Comparison of Min-Cut/Max-Flow Algorithms for Energy Minimization in Vision", PAMI 2004): a tree
// grows from the source and one from the sink through arcs with residual capacity until they
// touch, the path through them is augmented, and the nodes its saturated arcs cut off are
// adopted by another parent of their tree or freed. The trees are kept from one path to the
// next, which makes it fast on the grid graphs of images, but its work has no useful bound: it
// stops after `max_visits` arc visits and says it gave up.
//
// The graph's arrays are kept from one call to the next: a graph no larger than one solved before
// allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

namespace projtrack {

class BoundedMaxFlow {
 public:
  using Capacity = std::int32_t;

  // An empty graph of `nodes` nodes: no arc, no link to the source or the sink.
  void reset(int nodes);
  // Adds capacity from the source to `node` and from `node` to the sink (each at least 0).
  void add_terminals(int node, Capacity from_source, Capacity to_sink);
  // An edge between nodes a and b: capacity `ab` from a to b and `ba` back (each at least 0).
  void add_edge(int a, int b, Capacity ab, Capacity ba);
  // Pushes the maximum flow from the source to the sink. False when that took more than
  // `max_visits` arc visits: it gave up, and the cut is not a minimum one. It stops within
  // 3 × nodes() visits past the cap (a path being augmented, or a walk to a root, is finished).
  bool solve(std::uint64_t max_visits);

  // Arc visits of the last solve(): arcs scanned as the trees grow and as orphans look for a
  // parent, and steps up a tree to its root.
  std::uint64_t visits() const { return visits_; }
  // The flow solve() pushed (with what reset() folded of a node linked to both terminals).
  std::int64_t flow() const { return flow_; }
  int nodes() const { return static_cast<int>(nodes_.size()); }
  int arcs() const { return static_cast<int>(arcs_.size()); }
  // After a solve() that finished: whether `node` lies on the source's side of a minimum cut
  // (the source still reaches it through arcs with residual capacity).
  bool source_side(int node) const { return nodes_[node].tree == Tree::Source; }

 private:
  enum class Tree : std::uint8_t { Free, Source, Sink };
  static constexpr int kNone = -1;      // no parent: a free node
  static constexpr int kTerminal = -2;  // the parent is the tree's terminal
  static constexpr int kOrphan = -3;    // the parent arc was saturated: looking for another

  struct Node {
    int first_arc = kNone;
    int parent = kNone;     // the arc from this node to its parent, or one of the above
    int stamp = 0;          // the augmentation at which `depth` was last known right
    int depth = 0;          // steps to the tree's terminal, as of `stamp`
    Capacity terminal = 0;  // residual capacity: from the source when > 0, to the sink when < 0
    Tree tree = Tree::Free;
    bool queued = false;  // in the active queue
  };
  struct Arc {
    int head = 0;      // the node it points to (its reverse is the arc index ^ 1)
    int next = kNone;  // the next arc out of the same node
    Capacity residual = 0;
  };

  // The residual capacity in the direction flow goes along a tree of `tree`, on the arc `a`
  // out of a node towards its neighbour: outwards for the source's tree, inwards for the sink's.
  Capacity along_tree(int a, Tree tree) const {
    return tree == Tree::Source ? arcs_[a].residual : arcs_[a ^ 1].residual;
  }
  void activate(int node);
  // Grows `node`'s tree through its arcs: the arc from the source's tree into the sink's when
  // the trees touch there, else kNone. False when the visits ran out.
  bool grow(int node, int& bridge);
  // Pushes the bottleneck of the path through `bridge` and makes orphans of the nodes whose
  // parent arc it saturated.
  void augment(int bridge);
  // The least capacity along `node`'s tree from its terminal (source tree) or to it (sink tree).
  Capacity bottleneck_to_root(int node, Capacity least);
  void push_to_root(int node, Capacity flow);
  // Finds each orphan a parent in its tree, or frees it. False when the visits ran out.
  bool adopt_orphans();
  bool adopt(int orphan);
  // The number of steps from `node` up to its tree's terminal, or -1 when its path ends at an
  // orphan; marks the path with this augmentation's stamp when it is sound.
  int depth_of(int node);
  void free_node(int orphan);
  bool spend_visits(std::uint64_t n) {
    visits_ += n;
    return visits_ <= max_visits_;
  }

  std::vector<Node> nodes_;
  std::vector<Arc> arcs_;
  std::vector<int> queue_;  // the active nodes, a ring of nodes_.size() slots
  std::size_t queue_head_ = 0, queue_size_ = 0;
  std::vector<int> orphans_;  // a stack (each node is an orphan at most once at a time)
  std::int64_t flow_ = 0;
  std::uint64_t visits_ = 0, max_visits_ = 0;
  int stamp_ = 0;
};

}  // namespace projtrack
