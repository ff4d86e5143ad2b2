// SPDX-License-Identifier: Zlib
// Writes the FractureRB-style example of demos/fracturerb/: a Bullet world file serialized with
// btDefaultSerializer (as FractureRB's Maya exporter would leave it) and the per-object CSV.
//
//   make_fracturerb_example OUTDIR   ->  OUTDIR/brick_shot.bullet, OUTDIR/brick_shot.csv
//
// The scene: a concrete brick (a triangle mesh, as FractureRB scenes store breakable bodies)
// lying on a static ground box, a steel ball that the CSV throws at it, and a convex rock that
// the CSV puts to sleep beside it. Run it with
//   btfracture-run --fracturerb demos/fracturerb/brick_shot.bullet demos/fracturerb/brick_shot.csv
#include <btFracture/core/Primitives.h>

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

struct Body {
    std::unique_ptr<btCollisionShape> shape;
    std::unique_ptr<btRigidBody> body;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_fracturerb_example OUTDIR\n");
        return 2;
    }
    const std::string dir = argv[1];

    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, btScalar(-9.81), 0));

    std::vector<Body> bodies;
    auto add = [&](std::unique_ptr<btCollisionShape> shape, btScalar mass, const btVector3& position,
                   btScalar friction) {
        btVector3 inertia(0, 0, 0);
        if (mass > 0 && shape->getShapeType() != TRIANGLE_MESH_SHAPE_PROXYTYPE)
            shape->calculateLocalInertia(mass, inertia);
        if (mass > 0 && shape->getShapeType() == TRIANGLE_MESH_SHAPE_PROXYTYPE) inertia = btVector3(1, 1, 1);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(position);
        info.m_friction = friction;
        auto body = std::make_unique<btRigidBody>(info);
        world.addRigidBody(body.get());
        bodies.push_back({std::move(shape), std::move(body)});
        return bodies.back().body.get();
    };

    // Ground: a static 10 m x 1 m x 10 m box whose top face is y = 0.
    btRigidBody* ground = add(std::make_unique<btBoxShape>(btVector3(5, btScalar(0.5), 5)), 0,
                              btVector3(0, btScalar(-0.5), 0), btScalar(0.8));

    // Brick: 0.24 m x 0.07 m x 0.115 m, a closed triangle mesh of 4 x 1 x 2 cells per face pair.
    const btfracture::TriangleMesh brickMesh =
        btfracture::makeBox(Eigen::Vector3d(0.12, 0.035, 0.0575), 4, 1, 2);
    std::vector<btScalar> vertices;
    std::vector<int> indices;
    for (const auto& v : brickMesh.vertices)
        for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<btScalar>(v[k]));
    for (const auto& t : brickMesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    btTriangleIndexVertexArray brickData(static_cast<int>(brickMesh.triangles.size()), indices.data(),
                                         3 * sizeof(int), static_cast<int>(brickMesh.vertices.size()),
                                         vertices.data(), 3 * sizeof(btScalar));
    btRigidBody* brick = add(std::make_unique<btBvhTriangleMeshShape>(&brickData, true), btScalar(3.7),
                             btVector3(0, btScalar(0.035), 0), btScalar(0.6));

    // Ball: steel, 4 cm radius, to the left of the brick; its velocity comes from the CSV.
    btRigidBody* ball = add(std::make_unique<btSphereShape>(btScalar(0.04)), btScalar(2.1),
                            btVector3(btScalar(-0.6), btScalar(0.06), 0), btScalar(0.3));

    // Rock: a convex hull of an irregular octahedron, resting behind the brick.
    auto rockShape = std::make_unique<btConvexHullShape>();
    const btScalar r = btScalar(0.05);
    for (const btVector3& p :
         {btVector3(r, 0, 0), btVector3(-r, 0, btScalar(0.01)), btVector3(0, r, 0),
          btVector3(btScalar(0.01), -r, 0), btVector3(0, 0, r), btVector3(0, btScalar(0.01), -r)})
        rockShape->addPoint(p, false);
    rockShape->recalcLocalAabb();
    btRigidBody* rock =
        add(std::move(rockShape), btScalar(0.5), btVector3(0, r, btScalar(0.3)), btScalar(0.7));

    btDefaultSerializer serializer;
    serializer.startSerialization();
    const std::pair<btRigidBody*, const char*> names[] = {
        {ground, "pGround"}, {brick, "pBrick1"}, {ball, "pSphere1"}, {rock, "pRock1"}};
    for (const auto& [body, name] : names) serializer.registerNameForPointer(body, name);
    world.serialize(&serializer);
    {
        std::ofstream out(dir + "/brick_shot.bullet", std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(serializer.getBufferPointer()),
                  serializer.getCurrentBufferSize());
        if (!out) {
            std::fprintf(stderr, "make_fracturerb_example: cannot write %s/brick_shot.bullet\n", dir.c_str());
            return 1;
        }
    }

    std::ofstream csv(dir + "/brick_shot.csv", std::ios::binary | std::ios::trunc);
    csv << "% FractureRB parameters for brick_shot.bullet (written by make_fracturerb_example).\n"
           "% Columns (';'-separated; FractureRB's own header counts from 0):\n"
           "% collision-shape name;object name;ini. vel. x;init. vel. y;init. vel. z;init. rot. x;init. rot. "
           "y;"
           "init. rot. z;init. sleeping;mesh size;voxel size;Young's modulus;Possion ratio;density;strength;"
           "toughness;compressive factor;remesh target;ignore crack self-intersections;material model;"
           "max cracks per BEM run;fracture method;sampling density\n"
           "%\n"
           "% The brick breaks: concrete (E 30 GPa, nu 0.2, 2300 kg/m^3, strength 1 MPa, toughness 0.2 MPa "
           "m^1/2,\n"
           "% compressive factor 10), crack mesh size 2.5 cm (about the BEM triangles' size), voxel 2 mm, "
           "remeshed to 800 BEM triangles, full BEM.\n"
           "pBrick1;brick;0;0;0;0;0;0;0;0.025;0.002;30e9;0.2;2300;1e6;2e5;10;800;0;default;-1;0\n"
           "% The ball is thrown at it at 15 m/s (spinning a little); the rock sleeps until something hits "
           "it.\n"
           "pSphere1;ball;15;0.5;0;0;0;5;0\n"
           "pRock1;rock;0;0;0;0;0;0;1\n";
    csv.close();
    if (!csv) {
        std::fprintf(stderr, "make_fracturerb_example: cannot write %s/brick_shot.csv\n", dir.c_str());
        return 1;
    }
    for (auto it = bodies.rbegin(); it != bodies.rend(); ++it) world.removeRigidBody(it->body.get());
    std::printf("wrote %s/brick_shot.bullet (%d bytes) and %s/brick_shot.csv\n", dir.c_str(),
                serializer.getCurrentBufferSize(), dir.c_str());
    return 0;
}
