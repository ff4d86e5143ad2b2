// SPDX-License-Identifier: Zlib
#include "ImpactRecorder.h"

#include <btFracture/core/Error.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/io/SceneWorld.h>

#include <btBulletDynamicsCommon.h>

#include <cstdio>
#include <fstream>

namespace btfracture {
namespace {

Eigen::Isometry3d isometry(const btTransform& t) {
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m.linear()(r, c) = t.getBasis()[r][c];
        m.translation()[r] = t.getOrigin()[r];
    }
    return m;
}

Eigen::Vector3d vector(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}

}  // namespace

ImpactRecorder::ImpactRecorder(SceneWorld& world, const btRigidBody& target, const btRigidBody& impactor,
                               const Eigen::Isometry3d& targetRestToWorld)
    : world_(world), stepLength_(world.scene().world.dt / world.scene().world.substeps) {
    restFrames_[&target] = targetRestToWorld.inverse() * isometry(target.getWorldTransform());
    impactor_.insert(&impactor);
    world_.world().setInternalTickCallback(&ImpactRecorder::tick, this, false);
}

ImpactRecorder::~ImpactRecorder() {
    world_.world().setInternalTickCallback(nullptr, nullptr, false);
}

void ImpactRecorder::onFractureEvent(btFractureRigidBody& parent,
                                     const std::vector<btFractureRigidBody*>& fragments,
                                     const FractureEventInfo&) {
    const auto piece = restFrames_.find(&parent);
    if (piece != restFrames_.end()) {
        const Eigen::Isometry3d parentToRest = piece->second * isometry(parent.getWorldTransform()).inverse();
        for (const btFractureRigidBody* f : fragments)
            restFrames_[f] = parentToRest * isometry(f->getWorldTransform());
        restFrames_.erase(piece);  // the parent leaves the world; its address may be reused
    } else if (impactor_.erase(&parent) > 0) {
        impactor_.insert(fragments.begin(), fragments.end());
    }
}

const Eigen::Isometry3d* ImpactRecorder::restFrameOf(const btCollisionObject* body) const {
    const auto piece = restFrames_.find(body);
    return piece == restFrames_.end() ? nullptr : &piece->second;
}

void ImpactRecorder::tick(btDynamicsWorld* world, btScalar) {
    auto* self = static_cast<ImpactRecorder*>(world->getWorldUserInfo());
    const auto* fractureWorld = dynamic_cast<const btFractureDynamicsWorld*>(world);
    if (fractureWorld && fractureWorld->isReplayingStep()) {
        self->pending_.clear();  // the replay replaces the discarded pass of this step
    } else {
        self->contacts_.insert(self->contacts_.end(), self->pending_.begin(), self->pending_.end());
        self->pending_.clear();
        ++self->step_;
    }
    self->scan();
}

void ImpactRecorder::scan() {
    btDispatcher* dispatcher = world_.world().getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
        const btCollisionObject *a = manifold->getBody0(), *b = manifold->getBody1();
        const bool targetIsA = restFrames_.count(a) && impactor_.count(b);
        const bool targetIsB = restFrames_.count(b) && impactor_.count(a);
        if (!targetIsA && !targetIsB) continue;
        const btCollisionObject* piece = targetIsA ? a : b;
        const Eigen::Isometry3d& toRest = restFrames_.at(piece);
        const Eigen::Matrix3d worldToBody = isometry(piece->getWorldTransform()).linear().transpose();
        std::string name;
        for (const SceneWorld::Body& body : world_.bodies())
            if (body.rigidBody == piece) name = body.name;
        for (int i = 0; i < manifold->getNumContacts(); ++i) {
            const btManifoldPoint& p = manifold->getContactPoint(i);
            if (!(p.getAppliedImpulse() > 0)) continue;
            // m_normalWorldOnB points from B towards A: into A.
            const Eigen::Vector3d into =
                targetIsA ? vector(p.m_normalWorldOnB) : Eigen::Vector3d(-vector(p.m_normalWorldOnB));
            Contact c;
            c.step = step_;
            c.piece = name;
            c.point = toRest * vector(targetIsA ? p.m_localPointA : p.m_localPointB);
            c.normal = toRest.linear() * (worldToBody * into);
            c.impulse = p.getAppliedImpulse();
            pending_.push_back(c);
        }
    }
}

void ImpactRecorder::finish() {
    contacts_.insert(contacts_.end(), pending_.begin(), pending_.end());
    pending_.clear();
}

void ImpactRecorder::writeCsv(const std::string& path) const {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot create contact file '" + path + "'");
    out << "step,time_s,piece,x,y,z,nx,ny,nz,impulse_Ns\n";
    char line[320];
    for (const Contact& c : contacts_) {
        std::snprintf(line, sizeof line, "%ld,%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", c.step,
                      c.step * stepLength_, c.piece.c_str(), c.point.x(), c.point.y(), c.point.z(),
                      c.normal.x(), c.normal.y(), c.normal.z(), c.impulse);
        out << line;
    }
    out.close();
    if (!out) throw Error("writing contact file '" + path + "' failed");
}

}  // namespace btfracture
