// SPDX-License-Identifier: Zlib
#pragma once
// btFracture: brittle fracture for Bullet. The one header an application includes:
//
//   btFractureDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);  // a Bullet world
//   world.setFractureEngine(std::make_unique<BemFractureEngine>());              // that breaks
//   btFractureRigidBody slab(Material::glass(), btBoxShape(halfExtents), settings, pose);
//   world.addRigidBody(&slab);
//
// Bullet's own btBulletDynamicsCommon.h comes with it. Names outside Bullet's bt prefix live in
// namespace btfracture. README.md lists the settings and their units; docs/DESIGN.md explains
// the pipeline and the frames.
#include <btFracture/core/Error.h>
#include <btFracture/core/FractureSettings.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/Material.h>
#include <btFracture/core/ThreadLimit.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/dynamics/FractureBodySettings.h>
#include <btFracture/dynamics/FractureEngine.h>
#include <btFracture/dynamics/FractureListener.h>
#include <btFracture/dynamics/SizeScaledBroadphase.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/LevelSetBody.h>

#include <btBulletDynamicsCommon.h>
