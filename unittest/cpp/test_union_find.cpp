// UnionFind and LabelUnion (union_find.h): the components of a known graph, each led by its
// smallest member, and of a random graph against a breadth-first search's components.
#include "union_find.h"

#include "gtest/gtest.h"

#include <queue>
#include <random>
#include <utility>
#include <vector>

using LAMMPS_NS::tagint;
using LAMMPS_NS::ClusterDyn::LabelUnion;
using LAMMPS_NS::ClusterDyn::UnionFind;

namespace {

using Edges = std::vector<std::pair<int, int>>;

// the smallest vertex of each vertex's component, by breadth-first search
std::vector<int> bfs_roots(int n, const Edges &edges)
{
  std::vector<std::vector<int>> adj(n);
  for (const auto &e : edges) {
    adj[e.first].push_back(e.second);
    adj[e.second].push_back(e.first);
  }
  std::vector<int> root(n, -1);
  for (int s = 0; s < n; s++) {    // in increasing order: s is its component's smallest
    if (root[s] >= 0) continue;
    std::queue<int> todo;
    todo.push(s);
    root[s] = s;
    while (!todo.empty()) {
      const int v = todo.front();
      todo.pop();
      for (int w : adj[v])
        if (root[w] < 0) {
          root[w] = s;
          todo.push(w);
        }
    }
  }
  return root;
}

}    // namespace

TEST(UnionFind, ComponentsOfAKnownGraph)
{
  // {0, 3, 7}, {2, 5, 8, 9}, {1}, {4}, {6}
  const Edges edges = {{7, 3}, {3, 0}, {9, 8}, {5, 2}, {8, 5}, {9, 2}};
  const int root[10] = {0, 1, 2, 0, 4, 2, 6, 0, 2, 2};
  UnionFind uf;
  uf.reset(10);
  for (const auto &e : edges) uf.join(e.first, e.second);
  for (int v = 0; v < 10; v++) EXPECT_EQ(uf.find(v), root[v]) << v;
  EXPECT_GE(uf.memory_usage(), 10.0 * sizeof(int));
  uf.reset(10);    // starts afresh
  for (int v = 0; v < 10; v++) EXPECT_EQ(uf.find(v), v);
}

TEST(UnionFind, RandomGraphMatchesBreadthFirstSearch)
{
  const int n = 2000;
  std::mt19937 rng(4711);
  std::uniform_int_distribution<int> vertex(0, n - 1);
  Edges edges;
  for (int k = 0; k < 1500; k++) edges.emplace_back(vertex(rng), vertex(rng));    // many parts
  const std::vector<int> want = bfs_roots(n, edges);
  UnionFind uf;
  uf.reset(n);
  for (const auto &e : edges) uf.join(e.first, e.second);
  int parts = 0;
  for (int v = 0; v < n; v++) {
    EXPECT_EQ(uf.find(v), want[v]) << v;
    parts += want[v] == v;
  }
  EXPECT_GT(parts, 1);    // the test sees several components
  EXPECT_LT(parts, n);
}

TEST(LabelUnion, GlobalLabelsLedByTheSmallest)
{
  LabelUnion lu;
  const tagint big = 2000000000;    // labels far apart: a map, not an array
  lu.join(big, 17);
  lu.join(5, big - 1);
  lu.join(big - 1, 17);
  lu.join(40, 41);
  for (tagint t : {tagint(5), tagint(17), big - 1, big}) EXPECT_EQ(lu.root(t), 5) << t;
  EXPECT_EQ(lu.root(41), 40);
  EXPECT_EQ(lu.root(40), 40);
  EXPECT_EQ(lu.root(3), 3);    // never joined: its own
}
