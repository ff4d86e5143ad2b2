// SPDX-License-Identifier: Zlib
#pragma once
// Disjoint sets over 0..n-1 with path halving: connected components of triangles or voxels.
#include <numeric>
#include <vector>

namespace btfracture {

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace btfracture
