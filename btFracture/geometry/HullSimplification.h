// SPDX-License-Identifier: Zlib
#pragma once
// Vertex-budgeted convex hulls: the collision hull of a fragment keeps at most a given number of
// its corners. Bullet's convex-convex narrowphase (GJK/EPA support mapping) scans every hull
// vertex per query, so a chip cut from a fine collision mesh with hundreds of hull corners costs
// that much per contact pair and step; a few dozen corners carry its shape.
#include <Eigen/Core>

#include <vector>

namespace btfracture {

// A subset of `points` (at most maxVertices of them, in their input order) whose hull stays inside
// the hull of `points`: the points farthest (from the centroid) along maxVertices directions
// spread evenly over the sphere (Fibonacci lattice), then along the directions of a lattice four
// times as dense, in a scrambled order, until the budget is full; duplicates count once. A subset's hull lies
// inside the full hull, so sibling fragments that did not overlap still do not. All points when there are no
// more than maxVertices or when maxVertices <= 0. Deterministic.
std::vector<Eigen::Vector3d> budgetHullPoints(const std::vector<Eigen::Vector3d>& points, int maxVertices);

}  // namespace btfracture
