// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/CrackFront.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/fracture/SurfaceSlide.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace btfracture {
namespace {

// Slab half-thickness of a crack in the level set (LevelSetBody.h: 0.85 voxel): a marker that
// comes this close to another sheet's swept surface has entered that crack.
constexpr double kSlabHalfWidth = 0.85;
// Spacing limits ([0.5, 2] voxels): shorter edges collapse, longer than kSplit split.
constexpr double kCollapse = 0.5, kSplit = 1.5;
// A sub-step moves a marker at most this many spacings (< kSlabHalfWidth: no marker can jump
// over a slab it approaches).
constexpr double kSubstep = 0.5;
// A marker that leaves the body stops this many spacings past the surface, so that the cut's
// slab reaches through the surface's narrow band.
constexpr double kPastSurface = 0.75;
constexpr int kMaxSubsteps = 1000;

using Steps = std::vector<Eigen::Vector3d>;

// Nearest point on segment a-b: parameter t in [0, 1].
double segmentParameter(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 <= 0.0) return 0.0;
    return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

std::int64_t cellKey(long x, long y, long z) {
    // 21 bits per axis (cells of 2 voxels: +-2^20 cells is far beyond kMaxVoxelsAcross).
    const auto u = [](long v) { return static_cast<std::int64_t>(v & 0x1FFFFF); };
    return (u(x) << 42) | (u(y) << 21) | u(z);
}

FrontMarker between(const FrontMarker& a, const FrontMarker& b, double t) {
    FrontMarker m;
    m.position = (1.0 - t) * a.position + t * b.position;
    m.direction = t < 0.5 ? a.direction : b.direction;
    m.arrested = a.arrested && b.arrested;
    m.free = a.free && b.free;
    m.home = t < 0.5 ? a.home : b.home;
    m.coarseNode = t < 0.5 ? a.coarseNode : b.coarseNode;
    m.coarseTangent = t < 0.5 ? a.coarseTangent : b.coarseTangent;
    return m;
}

}  // namespace

CrackFronts::CrackFronts(double spacing) : spacing_(spacing) {
    if (!(std::isfinite(spacing) && spacing > 0.0))
        throw Error("CrackFronts: marker spacing must be finite and > 0, got " + std::to_string(spacing));
}

const std::vector<MarkerChain>& CrackFronts::chains(int sheet) const {
    const auto it = sheets_.find(sheet);
    if (it == sheets_.end()) throw Error("CrackFronts: no markers for crack sheet " + std::to_string(sheet));
    return it->second;
}

std::vector<int> CrackFronts::sheets() const {
    std::vector<int> out;
    for (const auto& [sheet, chains] : sheets_) out.push_back(sheet);
    return out;
}

void CrackFronts::addSheet(int sheet, const CoarseFront& front, const FrontQueries& queries) {
    if (hasSheet(sheet))
        throw Error("CrackFronts: crack sheet " + std::to_string(sheet) + " already has markers");
    for (const auto& [a, b] : front.edges)
        if (!front.position.count(a) || !front.position.count(b))
            throw Error("CrackFronts: front edge " + std::to_string(a) + "-" + std::to_string(b) +
                        " of sheet " + std::to_string(sheet) + " has a node without position");
    // Walk the edges into loops (first unused edge first: deterministic).
    std::multimap<int, std::size_t> outgoing;
    for (std::size_t e = 0; e < front.edges.size(); ++e) outgoing.emplace(front.edges[e].first, e);
    std::vector<char> used(front.edges.size(), 0);
    std::vector<MarkerChain> chains;
    for (std::size_t first = 0; first < front.edges.size(); ++first) {
        if (used[first]) continue;
        std::vector<int> nodes{front.edges[first].first};
        std::size_t e = first;
        bool closed = false;
        while (true) {
            used[e] = 1;
            const int next = front.edges[e].second;
            if (next == nodes.front()) {
                closed = true;
                break;
            }
            nodes.push_back(next);
            std::size_t found = front.edges.size();
            for (auto [it, end] = outgoing.equal_range(next); it != end; ++it)
                if (!used[it->second]) {
                    found = it->second;
                    break;
                }
            if (found == front.edges.size()) break;  // dead end: an open chain
            e = found;
        }
        MarkerChain chain;
        chain.closed = closed;
        const std::size_t segments = closed ? nodes.size() : nodes.size() - 1;
        for (std::size_t i = 0; i < segments; ++i) {
            const int a = nodes[i], b = nodes[(i + 1) % nodes.size()];
            const Eigen::Vector3d pa = front.position.at(a), pb = front.position.at(b);
            const int pieces = std::max(1, static_cast<int>(std::ceil((pb - pa).norm() / spacing_ - 1e-9)));
            for (int k = 0; k < pieces; ++k) {
                const double t = static_cast<double>(k) / pieces;
                FrontMarker m;
                m.position = (1.0 - t) * pa + t * pb;
                m.coarseNode = t < 0.5 ? a : b;
                m.coarseTangent = pb - pa;
                chain.markers.push_back(m);
            }
        }
        if (!closed) {
            FrontMarker m;
            m.position = front.position.at(nodes.back());
            m.coarseNode = nodes.back();
            if (nodes.size() > 1) m.coarseTangent = m.position - front.position.at(nodes[nodes.size() - 2]);
            chain.markers.push_back(m);
        }
        for (FrontMarker& m : chain.markers) {
            m.home = queries.crackAt(m.position);
            m.free = !queries.insideBody(m.position);
        }
        chains.push_back(std::move(chain));
    }
    sheets_[sheet] = std::move(chains);
    movedCoarseNodes_.erase(sheet);
}

void CrackFronts::addSurface(int sheet, const TriangleMesh& triangles) {
    for (const auto& t : triangles.triangles) {
        for (int k = 0; k < 3; ++k)
            if (t[k] < 0 || t[k] >= static_cast<int>(triangles.vertices.size()))
                throw Error("CrackFronts: surface " + triangles.name + " has a vertex index out of range");
        addTriangle(swept_, cells_, sheet, triangles.vertices[t[0]], triangles.vertices[t[1]],
                    triangles.vertices[t[2]]);
    }
}

void CrackFronts::addTriangle(std::map<int, TriangleMesh>& store, Cells& cells, int sheet,
                              const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    if ((b - a).cross(c - a).norm() <= 1e-12 * spacing_ * spacing_) return;  // degenerate
    TriangleMesh& m = store[sheet];
    const int base = static_cast<int>(m.vertices.size());
    m.vertices.push_back(a);
    m.vertices.push_back(b);
    m.vertices.push_back(c);
    m.triangles.push_back({base, base + 1, base + 2});
    const int index = static_cast<int>(m.triangles.size()) - 1;
    const double cell = 2.0 * spacing_, pad = kSlabHalfWidth * spacing_;
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - pad,
                          hi = a.cwiseMax(b).cwiseMax(c).array() + pad;
    const auto lower = [&](int k) { return static_cast<long>(std::floor(lo[k] / cell)); };
    const auto upper = [&](int k) { return static_cast<long>(std::floor(hi[k] / cell)); };
    for (long x = lower(0); x <= upper(0); ++x)
        for (long y = lower(1); y <= upper(1); ++y)
            for (long z = lower(2); z <= upper(2); ++z) {
                auto& groups = cells[cellKey(x, y, z)];
                auto g = std::find_if(groups.begin(), groups.end(),
                                      [&](const auto& e) { return e.first == sheet; });
                if (g == groups.end()) g = groups.insert(groups.end(), {sheet, {}});
                g->second.push_back(index);
            }
}

bool CrackFronts::nearOtherSheet(int sheet, const Eigen::Vector3d& p) const {
    const double cell = 2.0 * spacing_, limit = kSlabHalfWidth * spacing_;
    const std::int64_t key =
        cellKey(static_cast<long>(std::floor(p.x() / cell)), static_cast<long>(std::floor(p.y() / cell)),
                static_cast<long>(std::floor(p.z() / cell)));
    for (const auto& [store, cells] :
         {std::pair{&swept_, &cells_}, std::pair{&transient_, &transientCells_}}) {
        const auto it = cells->find(key);
        if (it == cells->end()) continue;
        for (const auto& [other, triangles] : it->second) {
            if (other == sheet) continue;
            const TriangleMesh& m = store->at(other);
            for (const int t : triangles) {
                const auto& tri = m.triangles[t];
                const Eigen::Vector3d q =
                    closestPointOnTriangle(p, m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
                if ((q - p).norm() < limit) return true;
            }
        }
    }
    return false;
}

int CrackFronts::freeOutside(const FrontQueries& queries) {
    int freed = 0;
    for (auto& [sheet, chains] : sheets_)
        for (MarkerChain& chain : chains)
            for (FrontMarker& m : chain.markers)
                if (!m.arrested && !m.free && !queries.insideBody(m.position)) {
                    m.free = true;
                    ++freed;
                }
    return freed;
}

CrackFronts CrackFronts::extractSheets(const std::map<int, int>& newSheetOf,
                                       const std::map<int, int>& newNodeOf) const {
    const auto rename = [](const std::map<int, int>& newIdOf, int id) {
        const auto it = newIdOf.find(id);
        return it == newIdOf.end() ? -1 : it->second;
    };
    CrackFronts out(spacing_);
    for (const auto& [sheet, chains] : sheets_) {
        const int to = rename(newSheetOf, sheet);
        if (to < 0) continue;
        std::vector<MarkerChain>& copy = out.sheets_[to] = chains;
        for (MarkerChain& chain : copy)
            for (FrontMarker& m : chain.markers) {
                m.coarseNode = rename(newNodeOf, m.coarseNode);
                m.home = rename(newSheetOf, m.home);
            }
        const auto moved = movedCoarseNodes_.find(sheet);
        if (moved == movedCoarseNodes_.end()) continue;
        for (const int node : moved->second)
            if (const int n = rename(newNodeOf, node); n >= 0) out.movedCoarseNodes_[to].insert(n);
    }
    return out;
}

std::map<int, TriangleMesh> CrackFronts::takeSwept() {
    std::map<int, TriangleMesh> out;
    out.swap(swept_);
    cells_.clear();
    return out;
}

int CrackFronts::sweptTriangles() const {
    int n = 0;
    for (const auto& [sheet, m] : swept_) n += static_cast<int>(m.triangles.size());
    return n;
}

FrontAdvanceResult CrackFronts::advance(const std::map<int, CoarseFront>& fronts,
                                        const FrontQueries& queries) {
    std::map<int, std::vector<Steps>> steps;
    for (const auto& [sheet, front] : fronts) {
        const auto found = sheets_.find(sheet);
        if (found == sheets_.end()) continue;
        const std::map<int, Eigen::Vector3d>& advances = front.advance;  // (clang 14 captures no bindings)
        auto advanceOf = [&advances](int node) {
            const auto it = advances.find(node);
            return it == advances.end() ? Eigen::Vector3d::Zero().eval() : it->second;
        };
        std::vector<Steps>& sheetSteps = steps[sheet];
        for (MarkerChain& chain : found->second) {
            // Interpolated along the nearest coarse front edge (Hahn & Wojtan 2015 §5).
            Steps raw(chain.markers.size(), Eigen::Vector3d::Zero());
            for (std::size_t i = 0; i < chain.markers.size(); ++i) {
                FrontMarker& m = chain.markers[i];
                if (m.arrested || front.edges.empty()) continue;
                double best = std::numeric_limits<double>::infinity(), bestT = 0.0;
                std::pair<int, int> bestEdge = front.edges.front();
                for (const auto& e : front.edges) {
                    const Eigen::Vector3d& a = front.position.at(e.first);
                    const Eigen::Vector3d& b = front.position.at(e.second);
                    const double t = segmentParameter(m.position, a, b);
                    const double d = (m.position - ((1.0 - t) * a + t * b)).squaredNorm();
                    if (d < best) {
                        best = d;
                        bestT = t;
                        bestEdge = e;
                    }
                }
                raw[i] = (1.0 - bestT) * advanceOf(bestEdge.first) + bestT * advanceOf(bestEdge.second);
                m.coarseNode = bestT < 0.5 ? bestEdge.first : bestEdge.second;
                m.coarseTangent = front.position.at(bestEdge.second) - front.position.at(bestEdge.first);
            }
            // Light smoothing of the steps: half own, a quarter from each active neighbour.
            const std::size_t n = chain.markers.size();
            Steps smooth = raw;
            for (std::size_t i = 0; i < n; ++i) {
                if (chain.markers[i].arrested) continue;
                const bool end = !chain.closed && (i == 0 || i + 1 == n);
                if (end || n < 3) continue;
                const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
                const Eigen::Vector3d sp = chain.markers[prev].arrested ? raw[i] : raw[prev];
                const Eigen::Vector3d sn = chain.markers[next].arrested ? raw[i] : raw[next];
                smooth[i] = 0.5 * raw[i] + 0.25 * (sp + sn);
            }
            for (std::size_t i = 0; i < n; ++i)
                if (!chain.markers[i].arrested && smooth[i].norm() > 0.0)
                    movedCoarseNodes_[sheet].insert(chain.markers[i].coarseNode);
            sheetSteps.push_back(std::move(smooth));
        }
    }
    FrontAdvanceResult result = sweep(steps, queries, false);
    for (const auto& [sheet, front] : fronts)
        if (hasSheet(sheet)) readCoarseTargets(sheet, front, result);
    // Arrest feedback: a coarse node whose markers once moved and now all stopped stops too (one
    // whose markers all started outside, e.g. on a seed poking through the surface, moves on).
    // "Once", not "in this advance": a node's last moving marker may have passed to the
    // neighbouring node (nearest coarse edge half) after its own markers stopped. Only nodes
    // still on the coarse front count (growth replaces a front node by a new one).
    for (const auto& [sheet, nodes] : movedCoarseNodes_) {
        const auto found = sheets_.find(sheet);
        const auto front = fronts.find(sheet);
        if (found == sheets_.end() || front == fronts.end()) continue;
        std::map<int, std::pair<int, int>> count;  // coarse node -> (markers, arrested)
        for (const MarkerChain& chain : found->second)
            for (const FrontMarker& m : chain.markers) {
                auto& c = count[m.coarseNode];
                ++c.first;
                c.second += m.arrested ? 1 : 0;
            }
        for (const int node : nodes) {
            const auto c = count.find(node);
            if (front->second.position.count(node) > 0 && c != count.end() && c->second.first > 0 &&
                c->second.first == c->second.second)
                result.arrestedCoarseNodes.insert(node);
        }
    }
    return result;
}

void CrackFronts::readCoarseTargets(int sheet, const CoarseFront& front, FrontAdvanceResult& result) const {
    // Candidates: the chain edges with a marker of the node at either end (markers keep the node
    // they were interpolated from, so a node's markers sit around it along the front).
    std::map<int, Eigen::Vector3d> aims;  // moving node -> position + advance
    for (const auto& [node, a] : front.advance)
        if (a.norm() > 0.0 && front.position.count(node)) aims[node] = front.position.at(node) + a;
    std::map<int, std::pair<double, Eigen::Vector3d>> best;  // node -> (squared distance, point)
    const auto offer = [&](int node, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        const auto aim = aims.find(node);
        if (aim == aims.end()) return;
        const Eigen::Vector3d q = a + segmentParameter(aim->second, a, b) * (b - a);
        const double d = (q - aim->second).squaredNorm();
        const auto it = best.find(node);
        if (it == best.end() || d < it->second.first) best[node] = {d, q};
    };
    for (const MarkerChain& chain : sheets_.at(sheet)) {
        const std::vector<FrontMarker>& ms = chain.markers;
        const std::size_t n = ms.size(), edges = chain.closed ? n : (n > 0 ? n - 1 : 0);
        if (n == 1) offer(ms[0].coarseNode, ms[0].position, ms[0].position);
        for (std::size_t i = 0; i < edges; ++i) {
            const FrontMarker &a = ms[i], &b = ms[(i + 1) % n];
            offer(a.coarseNode, a.position, b.position);
            if (b.coarseNode != a.coarseNode) offer(b.coarseNode, a.position, b.position);
        }
    }
    for (const auto& [node, found] : best) {
        result.coarseTargets[node] = found.second;
        result.largestTargetShift = std::max(result.largestTargetShift, std::sqrt(found.first));
    }
}

FrontAdvanceResult CrackFronts::extend(const std::map<int, std::set<int>>& stoppedNodes, double distance,
                                       const FrontQueries& queries) {
    std::map<int, std::vector<Steps>> steps;
    for (const auto& [sheet, nodes] : stoppedNodes) {
        const auto found = sheets_.find(sheet);
        if (found == sheets_.end() || nodes.empty()) continue;
        for (const MarkerChain& chain : found->second) {
            Steps s(chain.markers.size(), Eigen::Vector3d::Zero());
            for (std::size_t i = 0; i < s.size(); ++i) {
                const FrontMarker& m = chain.markers[i];
                if (!m.arrested && nodes.count(m.coarseNode)) s[i] = distance * m.direction;
            }
            steps[sheet].push_back(std::move(s));
        }
    }
    FrontAdvanceResult result = sweep(steps, queries, true);
    // Markers that found no obstacle within `distance` stop too: their coarse node has.
    for (const auto& [sheet, nodes] : stoppedNodes) {
        const auto found = sheets_.find(sheet);
        if (found == sheets_.end()) continue;
        for (MarkerChain& chain : found->second)
            for (FrontMarker& m : chain.markers)
                if (!m.arrested && nodes.count(m.coarseNode) && m.direction.norm() > 0.0) {
                    m.arrested = true;
                    ++result.arrestedMarkers;
                }
    }
    return result;
}

FrontAdvanceResult CrackFronts::sweep(std::map<int, std::vector<Steps>>& steps, const FrontQueries& queries,
                                      bool stopAtSheets) {
    FrontAdvanceResult result;
    double longest = 0.0;
    for (const auto& [sheet, chains] : steps)
        for (const Steps& s : chains)
            for (const auto& v : s) {
                if (!v.allFinite())
                    throw Error("CrackFronts: a coarse front advance of sheet " + std::to_string(sheet) +
                                " is not finite");
                longest = std::max(longest, v.norm());
            }
    if (!(longest > 0.0)) return result;
    const int substeps = std::min(kMaxSubsteps, static_cast<int>(std::ceil(longest / (kSubstep * spacing_))));
    result.substeps = substeps;
    // Every chain edge sweeps one strip per advance (each marker moves on a straight line within
    // it): its start is kept per edge and the strip is emitted when the edge ends (split,
    // collapse) or the advance does. With stopAtSheets, fronts of several sheets also see each
    // other's sub-step strips at once (kept apart, dropped at the end).
    std::map<int, std::vector<Strips>> strips;
    for (const auto& [sheet, sheetSteps] : steps)
        for (const MarkerChain& chain : sheets_.at(sheet)) {
            Strips from(chain.markers.size());
            for (std::size_t i = 0; i < from.size(); ++i)
                from[i] = {chain.markers[i].position, chain.markers[(i + 1) % from.size()].position};
            strips[sheet].push_back(std::move(from));
        }
    const bool several = stopAtSheets && steps.size() > 1;
    for (int k = 0; k < substeps; ++k) {
        std::vector<std::pair<int, std::array<Eigen::Vector3d, 3>>> fresh;
        for (auto& [sheet, sheetSteps] : steps) {
            std::vector<MarkerChain>& chains = sheets_.at(sheet);
            for (std::size_t c = 0; c < chains.size(); ++c) {
                MarkerChain& chain = chains[c];
                Steps& s = sheetSteps[c];
                const std::size_t n = chain.markers.size();
                std::vector<Eigen::Vector3d> old(n);
                for (std::size_t i = 0; i < n; ++i) old[i] = chain.markers[i].position;
                for (std::size_t i = 0; i < n; ++i) {
                    FrontMarker& m = chain.markers[i];
                    if (m.arrested || s[i].norm() <= 0.0) continue;
                    const Eigen::Vector3d dir = s[i].normalized();
                    const Eigen::Vector3d p = m.position;
                    Eigen::Vector3d q = p + s[i] / substeps;
                    m.direction = dir;
                    const bool inside = queries.insideBody(q);
                    if (!inside && (m.free || !queries.insideBody(p))) {
                        // Outside already: a free marker follows the coarse front, any other
                        // (inserted beside one stopped at the surface) stops where it is.
                        if (!m.free) {
                            q = p;
                            m.arrested = true;
                            ++result.leftBody;
                        }
                    } else if (!inside) {
                        // Bisect for the surface; slide on along it from just inside (the rest
                        // of this advance along the line SurfaceSlide gives), else stop just past it.
                        double lo = 0.0, hi = 1.0;
                        for (int b = 0; b < 10; ++b) {
                            const double mid = 0.5 * (lo + hi);
                            (queries.insideBody(p + mid * (q - p)) ? lo : hi) = mid;
                        }
                        const SurfaceSlide slide =
                            queries.surfaceNormal
                                ? surfaceSlide(dir, m.coarseTangent, queries.surfaceNormal(p + hi * (q - p)))
                                : SurfaceSlide{};
                        if (slide.slides) {
                            q = p + lo * (q - p);
                            s[i] = s[i].norm() * slide.along * slide.line;
                            ++result.slid;
                        } else {
                            q = p + hi * (q - p) + kPastSurface * spacing_ * dir;
                            m.arrested = true;
                            ++result.leftBody;
                        }
                    } else {
                        m.free = false;
                        const int crack = queries.crackAt(q);
                        if (crack >= 0 && crack != sheet && crack != m.home) {
                            m.arrested = true;
                            ++result.metCrack;
                        } else if (stopAtSheets && nearOtherSheet(sheet, q)) {
                            m.arrested = true;
                            ++result.metSheet;
                        }
                    }
                    if (m.arrested) ++result.arrestedMarkers;
                    m.position = q;
                }
                if (!several) continue;
                const std::size_t edges = chain.closed ? n : (n > 0 ? n - 1 : 0);
                for (std::size_t i = 0; i < edges; ++i) {
                    const std::size_t j = (i + 1) % n;
                    const Eigen::Vector3d &qi = chain.markers[i].position, &qj = chain.markers[j].position;
                    fresh.push_back({sheet, {old[i], old[j], qj}});
                    fresh.push_back({sheet, {old[i], qj, qi}});
                }
            }
        }
        for (const auto& [sheet, t] : fresh)
            addTriangle(transient_, transientCells_, sheet, t[0], t[1], t[2]);
        for (auto& [sheet, sheetSteps] : steps) {
            std::vector<MarkerChain>& chains = sheets_.at(sheet);
            for (std::size_t c = 0; c < chains.size(); ++c)
                resample(sheet, chains[c], sheetSteps[c], strips[sheet][c]);
        }
    }
    for (auto& [sheet, sheetSteps] : steps) {
        const std::vector<MarkerChain>& chains = sheets_.at(sheet);
        for (std::size_t c = 0; c < chains.size(); ++c) {
            const std::size_t n = chains[c].markers.size(),
                              edges = chains[c].closed ? n : (n > 0 ? n - 1 : 0);
            for (std::size_t i = 0; i < edges; ++i) emitStrip(sheet, chains[c], strips[sheet][c], i);
        }
    }
    transient_.clear();
    transientCells_.clear();
    return result;
}

void CrackFronts::emitStrip(int sheet, const MarkerChain& chain, const Strips& from, std::size_t edge) {
    const Eigen::Vector3d& pa = chain.markers[edge].position;
    const Eigen::Vector3d& pb = chain.markers[(edge + 1) % chain.markers.size()].position;
    const auto& [fa, fb] = from[edge];
    addTriangle(swept_, cells_, sheet, fa, fb, pb);
    addTriangle(swept_, cells_, sheet, fa, pb, pa);
}

void CrackFronts::resample(int sheet, MarkerChain& chain, Steps& steps, Strips& from) {
    auto& ms = chain.markers;
    const auto length = [&](std::size_t i) {
        return (ms[(i + 1) % ms.size()].position - ms[i].position).norm();
    };
    const auto isEnd = [&](std::size_t i) { return !chain.closed && (i == 0 || i + 1 == ms.size()); };
    const auto restart = [&](std::size_t e) { from[e] = {ms[e].position, ms[(e + 1) % ms.size()].position}; };
    // Collapse edges shorter than kCollapse spacings: drop one end (never an open chain's end).
    for (std::size_t i = 0; ms.size() > 3 && i < ms.size();) {
        const bool isEdge = chain.closed || i + 1 < ms.size();
        if (!isEdge || length(i) >= kCollapse * spacing_) {
            ++i;
            continue;
        }
        const std::size_t j = (i + 1) % ms.size();
        std::size_t drop = ms.size();
        if (!isEnd(j))
            drop = j;
        else if (!isEnd(i))
            drop = i;
        if (drop == ms.size()) {
            ++i;
            continue;
        }
        const std::size_t n = ms.size(), before = (drop + n - 1) % n;
        emitStrip(sheet, chain, from, before);
        emitStrip(sheet, chain, from, drop);
        ms.erase(ms.begin() + static_cast<std::ptrdiff_t>(drop));
        steps.erase(steps.begin() + static_cast<std::ptrdiff_t>(drop));
        from.erase(from.begin() + static_cast<std::ptrdiff_t>(drop));
        restart(drop == 0 ? ms.size() - 1 : drop - 1);
        if (drop < i) --i;
    }
    // Split edges longer than kSplit spacings into pieces of at most one spacing; the edges
    // around inserted markers start their strips here.
    std::vector<FrontMarker> out;
    Steps outSteps;
    Strips outFrom;
    std::vector<char> restarted;
    const std::size_t n = ms.size();
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(ms[i]);
        outSteps.push_back(steps[i]);
        outFrom.push_back(from[i]);
        restarted.push_back(0);
        if (!chain.closed && i + 1 == n) break;
        const std::size_t j = (i + 1) % n;
        const double len = length(i);
        if (len <= kSplit * spacing_) continue;
        emitStrip(sheet, chain, from, i);
        restarted.back() = 1;
        const int pieces = static_cast<int>(std::ceil(len / spacing_));
        for (int k = 1; k < pieces; ++k) {
            const double t = static_cast<double>(k) / pieces;
            out.push_back(between(ms[i], ms[j], t));
            outSteps.push_back(out.back().arrested ? Eigen::Vector3d::Zero().eval()
                                                   : ((1.0 - t) * steps[i] + t * steps[j]).eval());
            outFrom.emplace_back();
            restarted.push_back(1);
        }
    }
    ms = std::move(out);
    steps = std::move(outSteps);
    from = std::move(outFrom);
    for (std::size_t e = 0; e < ms.size(); ++e)
        if (restarted[e]) restart(e);
}

}  // namespace btfracture
