// SPDX-License-Identifier: Zlib
#include <btFracture/io/SceneWorld.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/dynamics/CollisionShapeBuilder.h>
#include <btFracture/dynamics/FiniteState.h>
#include <btFracture/dynamics/SizeScaledBroadphase.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/io/CrackFaces.h>
#include <btFracture/io/MeshReader.h>

#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace btfracture {
namespace {

btVector3 toBullet(const Eigen::Vector3d& v) {
    return btVector3(static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()),
                     static_cast<btScalar>(v.z()));
}

btTransform toBullet(const Eigen::Isometry3d& pose) {
    const Eigen::Quaterniond q(pose.linear());
    return btTransform(btQuaternion(static_cast<btScalar>(q.x()), static_cast<btScalar>(q.y()),
                                    static_cast<btScalar>(q.z()), static_cast<btScalar>(q.w())),
                       toBullet(Eigen::Vector3d(pose.translation())));
}

Eigen::Isometry3d fromBullet(const btTransform& t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    const btMatrix3x3& r = t.getBasis();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) pose.linear()(i, j) = r[i][j];
    pose.translation() = Eigen::Vector3d(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z());
    return pose;
}

constexpr double kPlaneDisplayHalfSize = 10.0;  // [m]

TriangleMesh planeSurface(const Eigen::Vector3d& normal, double offset) {
    const Eigen::Vector3d helper =
        std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d t1 = normal.cross(helper).normalized() * kPlaneDisplayHalfSize;
    const Eigen::Vector3d t2 = normal.cross(t1);
    const Eigen::Vector3d centre = normal * offset;
    TriangleMesh m;
    m.vertices = {centre - t1 - t2, centre + t1 - t2, centre + t1 + t2, centre - t1 + t2};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

std::string bodyContext(const Scene& scene, const SceneBody& body) {
    return scene.file + ": body '" + body.name + "'";
}

}  // namespace

std::unique_ptr<btDiscreteDynamicsWorld> SceneWorldFactory::createWorld(
    btCollisionDispatcher& dispatcher, btBroadphaseInterface& broadphase, btConstraintSolver& solver,
    btCollisionConfiguration& configuration, const Scene&) const {
    return std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, &broadphase, &solver, &configuration);
}

std::unique_ptr<btRigidBody> SceneWorldFactory::createBody(
    const btRigidBody::btRigidBodyConstructionInfo& info, const SceneBody&, const TriangleMesh&) const {
    return std::make_unique<btRigidBody>(info);
}

struct SceneWorld::Impl {
    // Everything one body's shape points into, kept alive as long as the body.
    struct ShapeStorage {
        std::unique_ptr<CollisionShapeStorage> mesh;  // mesh bodies
        std::unique_ptr<btCollisionShape> shape;      // primitives
        btCollisionShape* get() const { return mesh ? mesh->shape() : shape.get(); }
    };

    Scene scene;
    std::unique_ptr<btDefaultCollisionConfiguration> configuration;
    std::unique_ptr<btCollisionDispatcher> dispatcher;
    std::unique_ptr<btDbvtBroadphase> broadphase;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
    std::unique_ptr<btDiscreteDynamicsWorld> world;
    std::vector<ShapeStorage> shapes;  // one per scene body, alive as long as the world
    std::vector<std::unique_ptr<btRigidBody>> ownedBodies;
    std::vector<std::unique_ptr<btRigidBody>> brokenBodies;  // parents that broke, deleted next frame
    std::vector<Body> bodies;
    std::vector<Removal> removals;
    // Where a breakable body came from: the unbroken original's surface, the map from the body's
    // frame into the original's, and the crack-face tolerance (1.5 level-set voxels).
    struct Lineage {
        std::shared_ptr<const ClosestPointTree> original;
        Eigen::Isometry3d originalFromBody = Eigen::Isometry3d::Identity();
        double tolerance = 0.0;
    };
    std::map<const btRigidBody*, Lineage> lineage;
    // Kinematic bodies: start pose and constant velocities, so that poses come from the elapsed
    // time without accumulating rounding.
    struct Kinematic {
        btRigidBody* body;
        btTransform start;
        btVector3 linearVelocity, angularVelocity;
    };
    std::vector<Kinematic> kinematic;
    int frames = 0;
    long long bulletSteps = 0;

    ~Impl() {
        // Bodies leave the world before anything they reference goes away; then the world goes
        // before the parts it was built on.
        for (auto it = ownedBodies.rbegin(); it != ownedBodies.rend(); ++it)
            if (world && *it) world->removeRigidBody(it->get());
        ownedBodies.clear();
        brokenBodies.clear();
        shapes.clear();
        world.reset();
        solver.reset();
        broadphase.reset();
        dispatcher.reset();
        configuration.reset();
    }

    void addBody(const SceneBody& description, const SceneWorldFactory& factory);
};

void SceneWorld::Impl::addBody(const SceneBody& description, const SceneWorldFactory& factory) {
    ShapeStorage storage;
    Body body;
    body.name = description.name;
    const SceneShape& shape = description.shape;
    // Pose of the body frame (centre of mass, principal axes) in the shape's own frame.
    Eigen::Isometry3d bodyInShape = Eigen::Isometry3d::Identity();
    Eigen::Vector3d unitDensityInertia = Eigen::Vector3d::Zero();  // principal moments / density [m^5]

    switch (shape.type) {
        case SceneShapeType::Mesh: {
            TriangleMesh mesh;
            MassProperties mass;
            PrincipalAxes axes;
            try {
                if (shape.meshData) {
                    mesh = *shape.meshData;
                    requireClosedSolid(mesh);
                } else {
                    mesh = readMesh(shape.meshFile);
                }
                for (auto& v : mesh.vertices) v = v.cwiseProduct(description.scale);
                mass = computeMassProperties(mesh);
                axes = principalAxes(mass.inertiaPerDensity);
            } catch (const Error& e) {
                throw Error(bodyContext(scene, description) + ": " + e.what());
            }
            for (auto& v : mesh.vertices) v = axes.rotation.transpose() * (v - mass.centreOfMass);
            bodyInShape.linear() = axes.rotation;
            bodyInShape.translation() = mass.centreOfMass;
            unitDensityInertia = axes.moments;
            body.volume = mass.volume;
            // A shrunk hull (hull + margin matches the mesh) or a GImpact mesh over every triangle
            // (fragments' GImpact meshes are decimated; a scene body is the surface it names).
            const CollisionShapeKind kind = shape.collision == SceneMeshCollision::ConvexHull
                                                ? CollisionShapeKind::ConvexHull
                                                : CollisionShapeKind::GImpactMesh;
            CollisionShapeOptions everyTriangle;
            everyTriangle.gimpactMaxTriangles = 0;
            try {
                storage.mesh = buildCollisionShape(mesh, kind, everyTriangle);
            } catch (const Error& e) {
                throw Error(bodyContext(scene, description) + ": " + e.what());
            }
            body.surface = std::move(mesh);
            break;
        }
        case SceneShapeType::Box: {
            const Eigen::Vector3d h = shape.halfExtents.cwiseProduct(description.scale);
            storage.shape = std::make_unique<btBoxShape>(toBullet(h));
            body.surface = makeBox(h);
            body.volume = 8.0 * h.prod();
            const Eigen::Vector3d h2 = h.cwiseProduct(h);
            unitDensityInertia =
                body.volume / 3.0 * Eigen::Vector3d(h2.y() + h2.z(), h2.x() + h2.z(), h2.x() + h2.y());
            break;
        }
        case SceneShapeType::Sphere: {
            const double r = shape.radius * description.scale.x();
            storage.shape = std::make_unique<btSphereShape>(static_cast<btScalar>(r));
            body.surface = makeGeodesicSphere(r, 8);  // 1280 triangles
            body.volume = 4.0 / 3.0 * M_PI * r * r * r;
            unitDensityInertia = Eigen::Vector3d::Constant(0.4 * body.volume * r * r);
            break;
        }
        case SceneShapeType::Plane:
            storage.shape = std::make_unique<btStaticPlaneShape>(toBullet(shape.normal),
                                                                 static_cast<btScalar>(shape.offset));
            body.surface = planeSurface(shape.normal, shape.offset);
            body.plane = true;
            break;
    }
    body.surface.name = description.name;

    double mass = 0.0;
    if (!description.isStatic() && description.motion != SceneMotion::Kinematic)
        mass = description.mass ? *description.mass : description.density * body.volume;
    const Eigen::Vector3d inertia = body.volume > 0.0
                                        ? Eigen::Vector3d(mass / body.volume * unitDensityInertia)
                                        : Eigen::Vector3d::Zero();
    Eigen::Isometry3d shapeInWorld = Eigen::Isometry3d::Identity();
    shapeInWorld.translation() = description.position;
    shapeInWorld.linear() = description.orientation.toRotationMatrix();

    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), nullptr, storage.get(),
                                                  toBullet(inertia));
    info.m_startWorldTransform = toBullet(shapeInWorld * bodyInShape);
    std::unique_ptr<btRigidBody> rigidBody = factory.createBody(info, description, body.surface);
    if (!rigidBody) throw Error(bodyContext(scene, description) + ": the scene factory created no body");
    if (const btFractureRigidBody* breakable = btFractureRigidBody::upcast(rigidBody.get())) {
        body.surface = breakable->mesh();
        body.surface.name = description.name;
        body.volume = breakable->volume();
    }
    rigidBody->setLinearVelocity(toBullet(description.linearVelocity));
    rigidBody->setAngularVelocity(toBullet(description.angularVelocity));
    rigidBody->setFriction(static_cast<btScalar>(description.friction));
    rigidBody->setRestitution(static_cast<btScalar>(description.restitution));
    if (description.motion == SceneMotion::Kinematic) {
        rigidBody->setCollisionFlags(rigidBody->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
        rigidBody->setActivationState(DISABLE_DEACTIVATION);
        kinematic.push_back({rigidBody.get(), rigidBody->getWorldTransform(), rigidBody->getLinearVelocity(),
                             rigidBody->getAngularVelocity()});
    }
    world->addRigidBody(rigidBody.get());
    if (description.motion == SceneMotion::Sleeping) rigidBody->setActivationState(ISLAND_SLEEPING);
    body.rigidBody = rigidBody.get();
    ownedBodies.push_back(std::move(rigidBody));
    shapes.push_back(std::move(storage));
    bodies.push_back(std::move(body));
}

SceneWorld::SceneWorld(const Scene& scene, const SceneWorldFactory& factory)
    : impl_(std::make_unique<Impl>()) {
    Impl& w = *impl_;
    w.scene = scene;
    w.configuration = std::make_unique<btDefaultCollisionConfiguration>();
    w.dispatcher = std::make_unique<btCollisionDispatcher>(w.configuration.get());
    const bool anyGImpact = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const SceneBody& b) {
        return b.shape.type == SceneShapeType::Mesh && b.shape.collision == SceneMeshCollision::GImpact;
    });
    if (anyGImpact) btGImpactCollisionAlgorithm::registerAlgorithm(w.dispatcher.get());
    w.broadphase = std::make_unique<SizeScaledBroadphase>();
    w.solver = std::make_unique<btSequentialImpulseConstraintSolver>();
    w.world = factory.createWorld(*w.dispatcher, *w.broadphase, *w.solver, *w.configuration, scene);
    if (!w.world) throw Error(scene.file + ": the scene factory created no world");
    w.world->setGravity(toBullet(scene.world.gravity));
    for (const SceneBody& body : scene.bodies) w.addBody(body, factory);
}

SceneWorld::~SceneWorld() = default;

btDiscreteDynamicsWorld& SceneWorld::world() {
    return *impl_->world;
}
const Scene& SceneWorld::scene() const {
    return impl_->scene;
}

void SceneWorld::stepFrame() {
    const SceneWorldSettings& settings = impl_->scene.world;
    const btScalar h = static_cast<btScalar>(settings.dt / settings.substeps);
    // maxSubSteps = 0: exactly one internal step of h per call, with no accumulator that could
    // round to one step more or less.
    impl_->brokenBodies.clear();
    for (int k = 0; k < settings.substeps; ++k) {
        // Kinematic bodies move at their constant velocities: pose at the end of this step, from
        // the start pose and the elapsed time. Bullet derives the velocity the contact solver
        // sees from the change of transform (btRigidBody::saveKinematicState).
        const double t = static_cast<double>(++impl_->bulletSteps) * settings.dt / settings.substeps;
        for (const Impl::Kinematic& kin : impl_->kinematic) {
            btTransform pose = kin.start;
            pose.setOrigin(kin.start.getOrigin() + kin.linearVelocity * static_cast<btScalar>(t));
            const btScalar speed = kin.angularVelocity.length();
            if (speed > btScalar(0))
                pose.setRotation(btQuaternion(kin.angularVelocity / speed, speed * static_cast<btScalar>(t)) *
                                 kin.start.getRotation());
            kin.body->setCenterOfMassTransform(pose);
        }
        impl_->world->stepSimulation(h, 0);
    }
    ++impl_->frames;
}

int SceneWorld::framesTaken() const {
    return impl_->frames;
}

const SceneWorld::Body* SceneWorld::firstNonFiniteBody() const {
    for (const Body& b : bodies())
        if (!hasFiniteState(*b.rigidBody)) return &b;
    return nullptr;
}

double SceneWorld::time() const {
    return impl_->frames * impl_->scene.world.dt;
}
const std::vector<SceneWorld::Body>& SceneWorld::bodies() const {
    return impl_->bodies;
}

void SceneWorld::replaceBody(const btRigidBody& parent,
                             const std::vector<std::pair<btFractureRigidBody*, std::string>>& fragments) {
    Impl& w = *impl_;
    const auto found =
        std::find_if(w.bodies.begin(), w.bodies.end(), [&](const Body& b) { return b.rigidBody == &parent; });
    if (found == w.bodies.end()) throw Error("SceneWorld::replaceBody: the broken body is not in the scene");
    auto lineage = w.lineage.find(&parent);
    if (lineage == w.lineage.end()) {
        // An original scene body: its surface is the reference for all its fragments' faces.
        Impl::Lineage root;
        root.original = std::make_shared<const ClosestPointTree>(found->surface);
        const btFractureRigidBody* breakable = btFractureRigidBody::upcast(&parent);
        double voxel = breakable ? breakable->settings().voxelSize : 0.0;
        if (!(voxel > 0.0)) voxel = LevelSetBody::defaultVoxelSize(found->surface);
        root.tolerance = 1.5 * voxel;
        lineage = w.lineage.emplace(&parent, std::move(root)).first;
    }
    const Impl::Lineage parentLineage = lineage->second;
    w.lineage.erase(lineage);
    const Eigen::Isometry3d parentPose = fromBullet(parent.getWorldTransform());
    w.removals.push_back(
        {found->name, parent.getWorldTransform(), parent.getLinearVelocity(), parent.getAngularVelocity()});
    std::vector<Body> pieces;
    for (const auto& [fragment, name] : fragments) {
        Body piece;
        piece.name = name;
        piece.rigidBody = fragment;
        piece.surface = fragment->mesh();
        piece.surface.name = name;
        piece.volume = fragment->volume();
        piece.parent = found->name;
        Impl::Lineage own = parentLineage;
        own.originalFromBody =
            parentLineage.originalFromBody * parentPose.inverse() * fromBullet(fragment->getWorldTransform());
        piece.crackFaces = crackFaces(piece.surface, own.originalFromBody, *own.original, own.tolerance);
        w.lineage.emplace(fragment, std::move(own));
        pieces.push_back(std::move(piece));
    }
    const auto position = w.bodies.erase(found);
    w.bodies.insert(position, std::make_move_iterator(pieces.begin()), std::make_move_iterator(pieces.end()));
    for (auto owned = w.ownedBodies.begin(); owned != w.ownedBodies.end(); ++owned)
        if (owned->get() == &parent) {
            w.brokenBodies.push_back(std::move(*owned));
            w.ownedBodies.erase(owned);
            break;
        }
}

const std::vector<SceneWorld::Removal>& SceneWorld::removals() const {
    return impl_->removals;
}

TriangleMesh SceneWorld::worldSurface(size_t index) const {
    const Body& body = impl_->bodies.at(index);
    const Eigen::Isometry3d pose = fromBullet(body.rigidBody->getWorldTransform());
    TriangleMesh mesh = body.surface;
    for (auto& v : mesh.vertices) v = pose * v;
    return mesh;
}

}  // namespace btfracture
