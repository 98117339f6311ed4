// The starts' max-flow: the minimum cut of small graphs against every cut (brute force), the
// flow of image-like grids against OpenCV's GrabCut graph (cv::detail::GCGraph, read here only),
// and the cap on its work.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc/detail/gcgraph.hpp>
#include <vector>

#include "segmentation/bounded_max_flow.hpp"

namespace projtrack {
namespace {

struct Edge {
  int a, b, ab, ba;
};
struct Graph {
  int nodes = 0;
  std::vector<int> source, sink;  // per node
  std::vector<Edge> edges;
};

Graph random_graph(cv::RNG& rng, int nodes, int edges, int most) {
  Graph g;
  g.nodes = nodes;
  for (int i = 0; i < nodes; ++i) {
    // About a third linked to neither terminal, some to both.
    g.source.push_back(rng.uniform(0, 3) == 0 ? rng.uniform(0, most) : 0);
    g.sink.push_back(rng.uniform(0, 3) == 0 ? rng.uniform(0, most) : 0);
  }
  for (int k = 0; k < edges; ++k) {
    const int a = rng.uniform(0, nodes), b = rng.uniform(0, nodes);
    if (a == b) continue;
    g.edges.push_back({a, b, rng.uniform(0, most), rng.uniform(0, 2) ? rng.uniform(0, most) : 0});
  }
  return g;
}

void build(const Graph& g, BoundedMaxFlow& f) {
  f.reset(g.nodes);
  for (int i = 0; i < g.nodes; ++i) f.add_terminals(i, g.source[i], g.sink[i]);
  for (const Edge& e : g.edges) f.add_edge(e.a, e.b, e.ab, e.ba);
}

// The capacity of the cut that puts the nodes of `source_side` (bit i: node i) with the source.
std::int64_t cut_capacity(const Graph& g, std::uint32_t source_side) {
  std::int64_t c = 0;
  const auto with_source = [&](int i) { return (source_side >> i) & 1U; };
  for (int i = 0; i < g.nodes; ++i) c += with_source(i) ? g.sink[i] : g.source[i];
  for (const Edge& e : g.edges) {
    if (with_source(e.a) && !with_source(e.b)) c += e.ab;
    if (with_source(e.b) && !with_source(e.a)) c += e.ba;
  }
  return c;
}

std::int64_t least_cut(const Graph& g) {
  std::int64_t least = std::numeric_limits<std::int64_t>::max();
  for (std::uint32_t s = 0; s < (1U << g.nodes); ++s) least = std::min(least, cut_capacity(g, s));
  return least;
}

constexpr std::uint64_t kNoCap = std::numeric_limits<std::uint64_t>::max();

TEST(BoundedMaxFlow, SmallGraphsTheirMinimumCut) {
  cv::RNG rng(7);
  BoundedMaxFlow f;  // one for all: its arrays are reused
  for (int trial = 0; trial < 400; ++trial) {
    const int nodes = rng.uniform(1, 11);
    const Graph g = random_graph(rng, nodes, rng.uniform(0, 3 * nodes), trial % 2 ? 5 : 1000);
    build(g, f);
    ASSERT_TRUE(f.solve(kNoCap));
    const std::int64_t least = least_cut(g);
    EXPECT_EQ(f.flow(), least) << "trial " << trial;
    std::uint32_t side = 0;
    for (int i = 0; i < nodes; ++i) side |= f.source_side(i) ? 1U << i : 0U;
    EXPECT_EQ(cut_capacity(g, side), least) << "trial " << trial << ": its cut is a minimum one";
  }
}

TEST(BoundedMaxFlow, NodesLinkedToBothTerminalsAndNoEdges) {
  BoundedMaxFlow f;
  f.reset(3);
  f.add_terminals(0, 5, 3);
  f.add_terminals(0, 0, 4);  // adds up: 5 from the source, 7 to the sink
  f.add_terminals(1, 2, 0);
  ASSERT_TRUE(f.solve(kNoCap));
  EXPECT_EQ(f.flow(), 5);
  EXPECT_FALSE(f.source_side(0));
  EXPECT_TRUE(f.source_side(1));
  EXPECT_FALSE(f.source_side(2)) << "a node nothing reaches lies with the sink";
  f.reset(0);
  EXPECT_TRUE(f.solve(0));
  EXPECT_EQ(f.flow(), 0);
}

// An 8-connected grid as the starts build it: colour evidence either way at each pixel,
// contrast-weighted smoothness between neighbours.
Graph grid(cv::RNG& rng, int w, int h) {
  Graph g;
  g.nodes = w * h;
  for (int i = 0; i < g.nodes; ++i) {
    const int u = rng.uniform(-300, 300);
    g.source.push_back(std::max(u, 0));
    g.sink.push_back(std::max(-u, 0));
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {-1, 1}}) {
        if (x + dx < 0 || x + dx >= w || y + dy >= h) continue;
        const int c = rng.uniform(0, 200);
        g.edges.push_back({y * w + x, (y + dy) * w + x + dx, c, c});
      }
  return g;
}

TEST(BoundedMaxFlow, GridsTheFlowOfOpenCVsGraph) {
  cv::RNG rng(11);
  BoundedMaxFlow f;
  for (const auto& [w, h] : {std::pair{5, 4}, {40, 30}, {90, 60}, {17, 120}}) {
    const Graph g = grid(rng, w, h);
    build(g, f);
    ASSERT_TRUE(f.solve(kNoCap));
    cv::detail::GCGraph<int> reference(g.nodes, 2 * static_cast<int>(g.edges.size()));
    for (int i = 0; i < g.nodes; ++i) {
      reference.addVtx();
      reference.addTermWeights(i, g.source[i], g.sink[i]);
    }
    for (const Edge& e : g.edges) reference.addEdges(e.a, e.b, e.ab, e.ba);
    EXPECT_EQ(f.flow(), reference.maxFlow()) << w << "x" << h;
    // Cuts of equal capacity may differ; ours must have the flow's.
    std::int64_t cut = 0;
    for (int i = 0; i < g.nodes; ++i) cut += f.source_side(i) ? g.sink[i] : g.source[i];
    for (const Edge& e : g.edges) {
      if (f.source_side(e.a) && !f.source_side(e.b)) cut += e.ab;
      if (f.source_side(e.b) && !f.source_side(e.a)) cut += e.ba;
    }
    EXPECT_EQ(cut, f.flow()) << w << "x" << h;
  }
}

TEST(BoundedMaxFlow, GivesUpPastItsVisitsAndTheSameGraphSolvesTheSame) {
  cv::RNG rng(3);
  const Graph g = grid(rng, 60, 40);
  BoundedMaxFlow f;
  build(g, f);
  ASSERT_TRUE(f.solve(kNoCap));
  const std::uint64_t needed = f.visits();
  const std::int64_t flow = f.flow();
  ASSERT_GT(needed, 1000U);
  build(g, f);
  EXPECT_FALSE(f.solve(needed / 2)) << "half the visits it needs";
  EXPECT_LE(f.visits(), needed / 2 + 3 * static_cast<std::uint64_t>(g.nodes))
      << "stops within 3 × its nodes of its cap";
  build(g, f);
  EXPECT_TRUE(f.solve(needed)) << "exactly the visits it needs";
  EXPECT_EQ(f.visits(), needed) << "deterministic";
  EXPECT_EQ(f.flow(), flow);
}

}  // namespace
}  // namespace projtrack
