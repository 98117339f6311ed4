#include "segmentation/bounded_max_flow.hpp"

#include <algorithm>
#include <limits>

namespace projtrack {

void BoundedMaxFlow::reset(int nodes) {
  nodes_.assign(static_cast<std::size_t>(std::max(nodes, 0)), Node{});
  arcs_.clear();
  queue_.resize(nodes_.size());
  orphans_.clear();
  orphans_.reserve(nodes_.size());
  queue_head_ = queue_size_ = 0;
  flow_ = 0;
  visits_ = 0;
  stamp_ = 0;
}

void BoundedMaxFlow::add_terminals(int node, Capacity from_source, Capacity to_sink) {
  // Flow through the node straight from the source to the sink is flow already: only the
  // difference is left to route.
  Node& n = nodes_[node];
  const std::int64_t source =
      std::int64_t{std::max<Capacity>(from_source, 0)} + std::max<Capacity>(n.terminal, 0);
  const std::int64_t sink =
      std::int64_t{std::max<Capacity>(to_sink, 0)} + std::max<Capacity>(-n.terminal, 0);
  flow_ += std::min(source, sink);
  n.terminal = static_cast<Capacity>(source - sink);
}

void BoundedMaxFlow::add_edge(int a, int b, Capacity ab, Capacity ba) {
  const int i = static_cast<int>(arcs_.size());
  arcs_.push_back({b, nodes_[a].first_arc, std::max<Capacity>(ab, 0)});
  arcs_.push_back({a, nodes_[b].first_arc, std::max<Capacity>(ba, 0)});
  nodes_[a].first_arc = i;
  nodes_[b].first_arc = i + 1;
}

void BoundedMaxFlow::activate(int node) {
  Node& n = nodes_[node];
  if (n.queued) return;
  n.queued = true;
  queue_[(queue_head_ + queue_size_++) % queue_.size()] = node;
}

bool BoundedMaxFlow::solve(std::uint64_t max_visits) {
  max_visits_ = max_visits;
  visits_ = 0;
  for (int i = 0; i < nodes(); ++i) {
    Node& n = nodes_[i];
    if (n.terminal == 0) continue;
    n.tree = n.terminal > 0 ? Tree::Source : Tree::Sink;
    n.parent = kTerminal;
    n.depth = 1;
    activate(i);
  }
  while (queue_size_ > 0) {
    const int p = queue_[queue_head_];
    int bridge = kNone;
    if (nodes_[p].tree != Tree::Free && !grow(p, bridge)) return false;
    if (bridge != kNone) {  // p stays active: its other arcs may lead to more paths
      ++stamp_;
      augment(bridge);
      if (!adopt_orphans()) return false;
      continue;
    }
    nodes_[p].queued = false;
    queue_head_ = (queue_head_ + 1) % queue_.size();
    --queue_size_;
  }
  return true;
}

bool BoundedMaxFlow::grow(int p, int& bridge) {
  const Node& from = nodes_[p];
  for (int a = from.first_arc; a != kNone; a = arcs_[a].next) {
    if (!spend_visits(1)) return false;
    if (along_tree(a, from.tree) == 0) continue;
    const int q = arcs_[a].head;
    Node& to = nodes_[q];
    if (to.tree == Tree::Free) {
      to.tree = from.tree;
      to.parent = a ^ 1;
      to.stamp = from.stamp;
      to.depth = from.depth + 1;
      activate(q);
    } else if (to.tree != from.tree) {
      bridge = from.tree == Tree::Source ? a : a ^ 1;
      return true;
    } else if (to.stamp <= from.stamp && to.depth > from.depth) {
      // A shorter way to the terminal through p: shorter paths to augment, fewer orphans.
      to.parent = a ^ 1;
      to.stamp = from.stamp;
      to.depth = from.depth + 1;
    }
  }
  return true;
}

BoundedMaxFlow::Capacity BoundedMaxFlow::bottleneck_to_root(int node, Capacity least) {
  const Tree tree = nodes_[node].tree;
  int v = node;
  for (; nodes_[v].parent != kTerminal; v = arcs_[nodes_[v].parent].head) {
    // The parent arc runs from v up: the source's tree carries the flow down it, the sink's up.
    const int up = nodes_[v].parent;
    least = std::min(least, tree == Tree::Source ? arcs_[up ^ 1].residual : arcs_[up].residual);
    ++visits_;
  }
  return std::min(least, tree == Tree::Source ? nodes_[v].terminal : -nodes_[v].terminal);
}

void BoundedMaxFlow::push_to_root(int node, Capacity flow) {
  const Tree tree = nodes_[node].tree;
  int v = node;
  while (nodes_[v].parent != kTerminal) {
    const int up = nodes_[v].parent;
    const int along = tree == Tree::Source ? up ^ 1 : up;
    arcs_[along].residual -= flow;
    arcs_[along ^ 1].residual += flow;
    const int parent = arcs_[up].head;
    if (arcs_[along].residual == 0) {
      nodes_[v].parent = kOrphan;
      orphans_.push_back(v);
    }
    v = parent;
  }
  Node& root = nodes_[v];
  root.terminal += tree == Tree::Source ? -flow : flow;
  if (root.terminal == 0) {
    root.parent = kOrphan;
    orphans_.push_back(v);
  }
}

void BoundedMaxFlow::augment(int bridge) {
  const int s = arcs_[bridge ^ 1].head;  // the bridge's tail, in the source's tree
  const int t = arcs_[bridge].head;
  Capacity flow = bottleneck_to_root(s, arcs_[bridge].residual);
  flow = bottleneck_to_root(t, flow);
  arcs_[bridge].residual -= flow;
  arcs_[bridge ^ 1].residual += flow;
  push_to_root(s, flow);
  push_to_root(t, flow);
  flow_ += flow;
}

bool BoundedMaxFlow::adopt_orphans() {
  while (!orphans_.empty()) {
    const int orphan = orphans_.back();
    orphans_.pop_back();
    if (!adopt(orphan)) return false;
  }
  return true;
}

int BoundedMaxFlow::depth_of(int node) {
  int steps = 0, depth = 0;
  for (int v = node;; ++steps) {
    ++visits_;
    const Node& n = nodes_[v];
    if (n.stamp == stamp_) {
      depth = steps + n.depth;
      break;
    }
    if (n.parent == kTerminal) {
      depth = steps + 1;
      break;
    }
    if (n.parent < 0) return -1;  // the path ends at an orphan: no way to the terminal
    v = arcs_[n.parent].head;
  }
  // The path is sound: its nodes' depths hold for this augmentation, and later walks stop there.
  for (int v = node, d = depth; nodes_[v].stamp != stamp_; --d) {
    nodes_[v].stamp = stamp_;
    nodes_[v].depth = d;
    if (nodes_[v].parent == kTerminal) break;
    v = arcs_[nodes_[v].parent].head;
  }
  return depth;
}

bool BoundedMaxFlow::adopt(int orphan) {
  const Tree tree = nodes_[orphan].tree;
  int best_arc = kNone, best_depth = std::numeric_limits<int>::max();
  for (int a = nodes_[orphan].first_arc; a != kNone; a = arcs_[a].next) {
    if (!spend_visits(1)) return false;
    // A neighbour of the same tree that can pass flow to the orphan along the tree, on a path
    // that still reaches the terminal; the nearest to it.
    const int q = arcs_[a].head;
    if (nodes_[q].tree != tree || along_tree(a ^ 1, tree) == 0) continue;
    const int depth = depth_of(q);
    if (depth >= 0 && depth < best_depth) best_depth = depth, best_arc = a;
  }
  if (!spend_visits(0)) return false;
  if (best_arc != kNone) {
    Node& n = nodes_[orphan];
    n.parent = best_arc;
    n.stamp = stamp_;
    n.depth = best_depth + 1;
    return true;
  }
  free_node(orphan);
  return true;
}

void BoundedMaxFlow::free_node(int orphan) {
  const Tree tree = nodes_[orphan].tree;
  for (int a = nodes_[orphan].first_arc; a != kNone; a = arcs_[a].next) {
    ++visits_;
    const int q = arcs_[a].head;
    Node& n = nodes_[q];
    if (n.tree != tree) continue;
    // q may grow into the freed node again; q's own children lose their parent.
    if (along_tree(a ^ 1, tree) > 0) activate(q);
    if (n.parent >= 0 && arcs_[n.parent].head == orphan) {
      n.parent = kOrphan;
      orphans_.push_back(q);
    }
  }
  nodes_[orphan].tree = Tree::Free;
  nodes_[orphan].parent = kNone;
}

}  // namespace projtrack
