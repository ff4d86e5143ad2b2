// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FractureEnergy.h>

#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

namespace btfracture {

double kineticEnergy(const btRigidBody& body) {
    if (body.getInvMass() == 0) return 0.0;
    const btVector3 v = body.getLinearVelocity();
    // Angular part in the body's principal frame: w_local = R^T w, I = diag(1 / invInertiaLocal).
    const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
    const btVector3 inverseInertia = body.getInvInertiaDiagLocal();
    double rotation = 0.0;
    for (int a = 0; a < 3; ++a)
        if (inverseInertia[a] > 0) rotation += double(w[a]) * double(w[a]) / double(inverseInertia[a]);
    return 0.5 * double(v.length2()) / double(body.getInvMass()) + 0.5 * rotation;
}

double potentialEnergy(const btRigidBody& body) {
    if (body.getInvMass() == 0) return 0.0;
    const btVector3 g = body.getGravity(), x = body.getCenterOfMassPosition();
    return -(double(g.x()) * x.x() + double(g.y()) * x.y() + double(g.z()) * x.z()) /
           double(body.getInvMass());
}

double mechanicalEnergy(const btRigidBody& body) {
    return kineticEnergy(body) + potentialEnergy(body);
}

double mechanicalEnergy(const btDiscreteDynamicsWorld& world) {
    double sum = 0.0;
    const btCollisionObjectArray& objects = world.getCollisionObjectArray();
    for (int i = 0; i < objects.size(); ++i)
        if (const btRigidBody* body = btRigidBody::upcast(objects[i]);
            body && !body->isStaticOrKinematicObject())
            sum += mechanicalEnergy(*body);
    return sum;
}

double FractureEnergyAudit::addedFraction() const {
    const double scale = bodyKinetic + partnersKinetic;
    return scale > 0.0 ? worldGain / scale : 0.0;
}

}  // namespace btfracture
