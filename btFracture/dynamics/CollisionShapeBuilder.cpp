// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/CollisionShapeBuilder.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/dynamics/BulletEigen.h>
#include <btFracture/dynamics/GraphHullShape.h>
#include <btFracture/geometry/HullSimplification.h>
#include <btFracture/geometry/MeshDecimation.h>
#include <btFracture/geometry/MeshInset.h>
#include <btFracture/geometry/SplitDecomposition.h>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <HACD/hacdHACD.h>
#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace btfracture {

struct CollisionShapeStorage::Impl {
    std::vector<std::unique_ptr<btCollisionShape>> children;
    std::vector<btScalar> vertices;
    std::vector<int> indices;
    std::unique_ptr<btTriangleIndexVertexArray> meshInterface;
    std::unique_ptr<btCollisionShape> root;  // declared last: destroyed before what it references
};

CollisionShapeStorage::CollisionShapeStorage() : impl_(std::make_unique<Impl>()) {}
CollisionShapeStorage::~CollisionShapeStorage() = default;

const char* toString(CollisionShapeKind kind) {
    switch (kind) {
        case CollisionShapeKind::ConvexHull:
            return "convex hull";
        case CollisionShapeKind::ConvexDecomposition:
            return "convex decomposition";
        case CollisionShapeKind::GImpactMesh:
            return "GImpact mesh";
    }
    return "?";
}

namespace {

std::string meshName(const TriangleMesh& mesh) {
    return mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
}

// A hull shape (GraphHullShape) with these corners and margin.
std::unique_ptr<GraphHullShape> hullShape(const std::vector<Eigen::Vector3d>& corners, double margin) {
    std::vector<btVector3> points;
    points.reserve(corners.size());
    for (const auto& p : corners) points.push_back(toBullet(p));
    auto shape = std::make_unique<GraphHullShape>(&points[0].x(), static_cast<int>(points.size()),
                                                  static_cast<int>(sizeof(btVector3)));
    shape->setMargin(btScalar(margin));
    shape->recalcLocalAabb();  // the cached box includes the margin
    return shape;
}

// A hull shape whose hull is the hull of `points` shrunk by `margin` (clamped by Bullet
// to a quarter of the inradius); returns its collision geometry (shrunk points + actual margin),
// or nullptr when the hull is flat or degenerate (fewer than 4 vertices).
std::unique_ptr<GraphHullShape> shrunkHull(const std::vector<Eigen::Vector3d>& points, double margin,
                                           int maxVertices, const std::string& name, ConvexPolytope& piece) {
    std::vector<double> coords;
    coords.reserve(3 * points.size());
    for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    btConvexHullComputer hull;
    const double shrink = hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)),
                                       static_cast<int>(points.size()), btScalar(margin), btScalar(0.25));
    if (hull.vertices.size() < 4) return nullptr;
    // Bullet clamps the shrink for thin pieces; the margin then follows the shrink actually
    // applied so that hull + margin still matches the input.
    const double actualMargin = shrink > 0.0 ? std::min(shrink, margin) : 0.0;
    if (actualMargin < 0.5 * margin)
        logf(LogLevel::Debug, name, ": collision margin reduced from ", margin, " to ", actualMargin,
             " m for a thin convex piece");
    std::vector<Eigen::Vector3d> corners;
    corners.reserve(static_cast<std::size_t>(hull.vertices.size()));
    for (int i = 0; i < hull.vertices.size(); ++i) corners.push_back(toEigen(hull.vertices[i]));
    piece.points = budgetHullPoints(corners, maxVertices);
    piece.margin = actualMargin;
    return hullShape(piece.points, actualMargin);
}

// HACD clusters of the mesh as point sets (HACD works in its own normalised [0, 1000] frame
// and returns denormalised hull points).
std::vector<std::vector<Eigen::Vector3d>> decompose(const TriangleMesh& mesh,
                                                    const CollisionShapeOptions& options) {
    std::vector<HACD::Vec3<HACD::Real>> points;
    points.reserve(mesh.vertices.size());
    for (const auto& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());
    std::vector<HACD::Vec3<long>> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);

    HACD::HACD hacd;
    hacd.SetPoints(points.data());
    hacd.SetNPoints(points.size());
    hacd.SetTriangles(triangles.data());
    hacd.SetNTriangles(triangles.size());
    hacd.SetCompacityWeight(0.1);
    hacd.SetVolumeWeight(0.0);
    hacd.SetNClusters(1);
    hacd.SetNVerticesPerCH(static_cast<std::size_t>(std::max(8, options.decompositionMaxHullVertices)));
    hacd.SetConcavity(options.decompositionConcavity * 1000.0);
    // Extra sample points: without them HACD measures concavity at mesh vertices only and keeps
    // a coarse L-shaped prism in one piece.
    hacd.SetAddExtraDistPoints(true);
    hacd.SetAddNeighboursDistPoints(true);
    hacd.SetAddFacesPoints(true);
    if (!hacd.Compute()) throw Error(meshName(mesh) + ": HACD convex decomposition failed");

    std::vector<std::vector<Eigen::Vector3d>> clusters;
    for (std::size_t c = 0; c < hacd.GetNClusters(); ++c) {
        std::vector<HACD::Vec3<HACD::Real>> chPoints(hacd.GetNPointsCH(c));
        std::vector<HACD::Vec3<long>> chTriangles(hacd.GetNTrianglesCH(c));
        if (chPoints.size() < 4) continue;
        hacd.GetCH(c, chPoints.data(), chTriangles.data());
        std::vector<Eigen::Vector3d> cluster;
        for (const auto& p : chPoints) cluster.emplace_back(p.X(), p.Y(), p.Z());
        clusters.push_back(std::move(cluster));
    }
    return clusters;
}

}  // namespace

void CollisionShapeStorage::replacePieces(std::vector<ConvexPolytope> pieces) {
    if (kind_ == CollisionShapeKind::GImpactMesh || pieces.size() != pieces_.size())
        throw Error("collision shape: cannot replace the " + std::to_string(pieces_.size()) +
                    " convex pieces of a " + toString(kind_) + " by " + std::to_string(pieces.size()));
    std::vector<std::unique_ptr<btCollisionShape>> hulls;
    for (const ConvexPolytope& piece : pieces) {
        if (piece.points.size() < 4) throw Error("collision shape: a replacement convex piece has no volume");
        hulls.push_back(hullShape(piece.points, piece.margin));
    }
    if (kind_ == CollisionShapeKind::ConvexHull) {
        impl_->root = std::move(hulls.front());
    } else {
        auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(hulls.size()));
        btTransform identity;
        identity.setIdentity();
        for (const auto& hull : hulls) compound->addChildShape(identity, hull.get());
        compound->setMargin(btScalar(margin_));
        impl_->root = std::move(compound);  // the old compound goes before the children it points to
        impl_->children = std::move(hulls);
    }
    shape_ = impl_->root.get();
    pieces_ = std::move(pieces);
}

std::unique_ptr<CollisionShapeStorage> buildCollisionShape(const TriangleMesh& mesh, CollisionShapeKind kind,
                                                           const CollisionShapeOptions& options) {
    const std::string name = meshName(mesh);
    if (mesh.vertices.size() < 4 || mesh.triangles.size() < 4)
        throw Error(name +
                    ": a collision shape needs a closed mesh with at least 4 vertices and 4 triangles");
    if (!(options.margin >= 0.0) || !std::isfinite(options.margin)) {
        std::ostringstream out;
        out << name << ": collision margin " << options.margin << " m (need finite, >= 0)";
        throw Error(out.str());
    }
    if (options.hullMaxVertices != 0 && options.hullMaxVertices < 4)
        throw Error(name + ": hull vertex budget " + std::to_string(options.hullMaxVertices) +
                    " (need 0 for all corners, or at least 4)");
    if (options.gimpactMaxTriangles < 0)
        throw Error(name + ": GImpact triangle budget " + std::to_string(options.gimpactMaxTriangles) +
                    " (need 0 for every triangle, or a positive count)");
    const double volume = computeMassProperties(mesh).volume;
    const double margin = options.margin > 0.0 ? options.margin : std::min(0.04, 0.02 * std::cbrt(volume));

    auto storage = std::make_unique<CollisionShapeStorage>();
    storage->kind_ = kind;
    storage->margin_ = margin;
    CollisionShapeStorage::Impl& impl = *storage->impl_;
    // A btGImpactMeshShape over the mesh (any closed mesh, convex or not), decimated to the budget
    // and moved in by its margin, so that mesh + margin lies on the body's surface (MeshInset.h).
    const auto buildGImpactMesh = [&mesh, &name, margin, &impl, &options] {
        const int budget = options.gimpactMaxTriangles;
        const bool decimate = budget > 0 && mesh.triangles.size() > static_cast<std::size_t>(budget);
        const MeshInset inset = insetMesh(decimate ? decimateMesh(mesh, budget) : mesh, margin);
        if (inset.reducedVertices > 0)
            logf(LogLevel::Debug, name, ": ", inset.reducedVertices,
                 " GImpact vertices in walls thinner than ", 2.0 * margin, " m moved in by as little as ",
                 inset.smallestFraction, " of the margin");
        const TriangleMesh& collided = inset.mesh;
        for (const auto& v : collided.vertices)
            impl.vertices.insert(impl.vertices.end(), {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())});
        for (const auto& t : collided.triangles) impl.indices.insert(impl.indices.end(), {t[0], t[1], t[2]});
        impl.meshInterface = std::make_unique<btTriangleIndexVertexArray>(
            static_cast<int>(collided.triangles.size()), impl.indices.data(),
            3 * static_cast<int>(sizeof(int)), static_cast<int>(collided.vertices.size()),
            impl.vertices.data(), 3 * static_cast<int>(sizeof(btScalar)));
        auto gimpact = std::make_unique<btGImpactMeshShape>(impl.meshInterface.get());
        gimpact->setMargin(btScalar(margin));
        gimpact->updateBound();
        impl.root = std::move(gimpact);
    };
    switch (kind) {
        case CollisionShapeKind::ConvexHull: {
            ConvexPolytope piece;
            impl.root = shrunkHull(mesh.vertices, margin, options.hullMaxVertices, name, piece);
            if (!impl.root)
                throw Error(name + ": convex hull of " + std::to_string(mesh.vertices.size()) +
                            " points is flat or degenerate");
            storage->pieces_.push_back(std::move(piece));
            break;
        }
        case CollisionShapeKind::ConvexDecomposition: {
            std::vector<std::vector<Eigen::Vector3d>> clusters;
            if (options.fitsHacd(mesh.triangles.size())) {
                clusters = decompose(mesh, options);
            } else {
                SplitDecompositionOptions split;
                split.maxPieces = options.splitMaxPieces;
                split.concavity = options.splitConcavity;
                SplitDecomposition d = splitDecomposition(mesh, split);
                logf(LogLevel::Debug, name, ": ", mesh.triangles.size(), " triangles (HACD limit ",
                     options.decompositionTriangleLimit, "): split into ", d.pieces.size(),
                     " convex pieces, hull volume ", d.hullVolume / d.meshVolume, " of the mesh's");
                clusters = std::move(d.pieces);
            }
            auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(clusters.size()));
            btTransform identity;
            identity.setIdentity();
            int flat = 0;
            for (std::size_t c = 0; c < clusters.size(); ++c) {
                ConvexPolytope piece;
                auto hull = shrunkHull(clusters[c], margin, options.hullMaxVertices,
                                       name + " piece " + std::to_string(c), piece);
                if (!hull) {  // a flat cluster holds no volume: leaving it out loses nothing
                    ++flat;
                    continue;
                }
                impl.children.push_back(std::move(hull));
                compound->addChildShape(identity, impl.children.back().get());
                storage->pieces_.push_back(std::move(piece));
            }
            if (flat > 0)
                logf(LogLevel::Info, name, ": ", flat, " of ", clusters.size(),
                     " convex decomposition pieces are flat and left out");
            if (impl.children.empty()) {
                logf(LogLevel::Info, name,
                     ": no convex decomposition piece has volume; using a GImpact mesh shape");
                storage->kind_ = CollisionShapeKind::GImpactMesh;
                buildGImpactMesh();
                break;
            }
            compound->setMargin(btScalar(margin));
            impl.root = std::move(compound);
            break;
        }
        case CollisionShapeKind::GImpactMesh:
            buildGImpactMesh();
            break;
    }
    storage->shape_ = impl.root.get();
    return storage;
}

}  // namespace btfracture
