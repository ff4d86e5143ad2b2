// SPDX-License-Identifier: Zlib
#include "SceneCases.h"

#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/MottHistogram.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

using namespace btfracture;

namespace accuracy {

namespace {

const std::string kSceneFile = std::string(BTFRACTURE_MESH_DIR) + "/../scenes/bunny_smash.json";

Eigen::Vector3d toWorld(const btTransform& t, const Eigen::Vector3d& p) {
    const btVector3 w = t * btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z()));
    return Eigen::Vector3d(w.x(), w.y(), w.z());
}

TriangleMesh worldMesh(const btFractureRigidBody& body) {
    TriangleMesh m = body.mesh();
    for (auto& v : m.vertices) v = toWorld(body.getWorldTransform(), v);
    return m;
}

double boxDiagonal(const TriangleMesh& m) {
    Eigen::AlignedBox3d box;
    for (const auto& v : m.vertices) box.extend(v);
    return box.diagonal().norm();
}

// Every event's engine time; the first event's pattern (crack triangles, fragment volumes, the
// fragments' faces off the parent's surface), which is what the runs are compared on.
struct BunnyEvents : FractureListener {
    int events = 0;
    EngineTimings timings;      // summed over events
    double otherSeconds = 0.0;  // summed: engine time outside the engine's own split
    double firstEventSeconds = 0.0;
    int firstEventCrackTriangles = 0;
    std::vector<double> volumes;
    TriangleMesh surface;
    double bodySize = 0.0;
    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>& pieces,
                         const FractureEventInfo& event) override {
        const EngineTimings& t = event.engineTimings;
        timings.bem += t.bem;
        timings.fracture += t.fracture;
        timings.geometry += t.geometry;
        otherSeconds += event.engineSeconds - t.bem - t.fracture - t.geometry;
        if (events++ > 0) return;
        firstEventSeconds = event.engineSeconds;
        firstEventCrackTriangles = event.crackTriangles;
        const TriangleMesh outer = worldMesh(parent);
        const ClosestPointTree tree(outer);
        bodySize = boxDiagonal(outer);
        const double tolerance = 0.01 * bodySize;  // faces farther than 1 % are fracture faces
        for (const btFractureRigidBody* piece : pieces) {
            volumes.push_back(piece->volume() / parent.volume());
            const TriangleMesh m = worldMesh(*piece);
            std::vector<int> index(m.vertices.size(), -1);  // only the vertices of fracture faces
            auto vertex = [&](int v) {
                if (index[v] < 0) {
                    index[v] = static_cast<int>(surface.vertices.size());
                    surface.vertices.push_back(m.vertices[v]);
                }
                return index[v];
            };
            for (const auto& t : m.triangles) {
                const Eigen::Vector3d c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
                if (tree.closestPoint(c).squaredDistance > tolerance * tolerance)
                    surface.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
            }
        }
    }
};

Scene loadScene(const SceneCaseInfo& info, const MethodChoice& method) {
    Scene scene = readSceneFile(kSceneFile);
    overrideFractureMethod(scene, method.method);
    for (SceneBody& b : scene.bodies) {
        if (!b.fracture.fracturable) continue;
        b.fracture.bemTriangleTarget = info.bemTriangles;
        b.fracture.hybridElementThreshold = std::max(1, method.threshold);
        b.fracture.maxRefractureDepth = 0;
        if (info.weak) {  // Fig. 8's "even weaker material": half the strength, 40 % of the toughness
            const Material& m = b.material;
            b.material = Material(m.youngsModulus(), m.poissonRatio(), m.density(), 0.5 * m.tensileStrength(),
                                  0.4 * m.fractureToughness(), m.compressiveFactor(), "weak bunny");
        }
    }
    return scene;
}

}  // namespace

std::vector<SceneCaseInfo> sceneCases(bool smoke) {
    if (smoke) return {};
    // 2,000 triangles is left out of the plain bunny: its FULL run alone took over 8 minutes
    // (1.4 GB). The weak bunny runs FULL and EST only, at four resolutions: which pieces break
    // again, and so the FULL / EST time ratio, changes with the resolution (README).
    return {{"bunny_500", 500, false, true},        {"bunny_750", 750, false, true},
            {"bunny_1000", 1000, false, true},      {"bunny_weak_750", 750, true, false},
            {"bunny_weak_1000", 1000, true, false}, {"bunny_weak_1500", 1500, true, false},
            {"bunny_weak_2000", 2000, true, false}};
}

RunResult runSceneCase(const SceneCaseInfo& info, const MethodChoice& method, int frames, double gainLimit) {
    const Scene scene = loadScene(info, method);
    RunResult r;
    r.caseName = info.name;
    r.method = method.label;
    r.threshold = method.method == FractureMethod::Hybrid ? method.threshold : 0;
    BemFractureEngineSettings engine;
    if (gainLimit >= 0.0) engine.fracture.estimatorUpdateGainLimit = gainLimit;
    FractureSceneWorldFactory factory(scene.effects.seed, engine);
    SceneWorld world(scene, factory);
    auto& fractureWorld = dynamic_cast<btFractureDynamicsWorld&>(world.world());
    BunnyEvents event;
    fractureWorld.addFractureListener(&event);
    double wall = 0.0, idleCallSeconds = 0.0;
    for (int f = 0; f < std::min(frames, scene.world.steps); ++f) {
        const auto callsBefore = fractureWorld.fractureStatistics().engineCalls;
        const int eventsBefore = event.events;
        Timer timer;
        world.stepFrame();
        const double seconds = timer.seconds();
        wall += seconds;
        if (event.events == eventsBefore && fractureWorld.fractureStatistics().engineCalls > callsBefore)
            idleCallSeconds += seconds;  // engine calls that broke nothing (mostly BEM set-up)
    }
    fractureWorld.removeFractureListener(&event);
    r.bemSeconds = event.timings.bem;
    r.fractureSeconds = event.timings.fracture;
    r.geometrySeconds = event.timings.geometry;
    r.otherEngineSeconds = event.otherSeconds + idleCallSeconds;
    r.firstEventSeconds = event.firstEventSeconds;
    r.events = event.events;
    r.crackTriangles = event.firstEventCrackTriangles;
    r.rigidSeconds = wall - r.engineSeconds();
    r.surfaceTriangles = info.bemTriangles;
    r.fragments = event.events > 0 ? static_cast<int>(event.volumes.size()) : 0;
    r.fragmentVolumes = event.volumes;
    if (event.volumes.size() >= 2) r.mottKs = compareWithMott(event.volumes).ksDistance;
    r.surface = event.surface;
    r.bodySize = event.bodySize;
    if (event.events == 0) r.note = "nothing broke";
    return r;
}

}  // namespace accuracy
