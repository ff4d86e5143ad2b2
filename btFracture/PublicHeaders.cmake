# SPDX-License-Identifier: Zlib
# The public API: the headers `cmake --install` installs and the shared library exports, relative
# to btFracture/. btFracture.h includes what an app needs; the others are what those include.
# cmake/CheckLayering.cmake (CTest core.layering) fails when one of them includes a header that
# is not in this list.
set(BTFRACTURE_PUBLIC_HEADERS
  btFracture.h
  core/Error.h
  core/FractureSettings.h
  core/Log.h
  core/MassProperties.h
  core/Material.h
  core/ThreadLimit.h
  core/TriangleMesh.h
  dynamics/BemFractureEngine.h
  dynamics/BodyContact.h
  dynamics/CollisionShapeBuilder.h
  dynamics/FractureBodySettings.h
  dynamics/FractureEnergy.h
  dynamics/FractureEngine.h
  dynamics/FractureListener.h
  dynamics/FractureState.h
  dynamics/FragmentSleeping.h
  dynamics/RigidBodySnapshot.h
  dynamics/SizeScaledBroadphase.h
  dynamics/btFractureDynamicsWorld.h
  dynamics/btFractureRigidBody.h
  geometry/ConvexPenetration.h
  geometry/Fragment.h
  geometry/FragmentClasses.h
  geometry/LevelSetBody.h)
