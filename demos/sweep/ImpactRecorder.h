// SPDX-License-Identifier: Zlib
#pragma once
// Follows a sweep run's target through fracture and records its impact.
//
// Lineage: every piece of the target (the target itself, its fragments, theirs) keeps the map
// from its body frame to the target's rest frame. A fragment's is its parent's times the
// parent-to-fragment transform at the event (both at the parent's pre-step pose, before the
// separation push, btFractureDynamicsWorld.h), so the final pieces, drawn with it, sit where they
// came from in the unbroken target.
//
// Contacts: after every internal Bullet step (a post-tick callback; the world leaves that slot
// to the application), each solved contact point between the impactor (or its pieces) and a
// target piece with a positive normal impulse: point and inward normal in the rest frame, impulse.
// A step that fractures is replayed (btFractureDynamicsWorld.h); its discarded pass is replaced by
// the replay, so every step counts once.
#include <btFracture/dynamics/FractureListener.h>

#include <LinearMath/btScalar.h>
#include <Eigen/Geometry>

#include <map>
#include <set>
#include <string>
#include <vector>

class btCollisionObject;
class btDynamicsWorld;
class btRigidBody;

namespace btfracture {

class SceneWorld;

class ImpactRecorder : public FractureListener {
public:
    // `targetRestToWorld`: the target's rest frame at the start of the run. Installs the tick
    // callback on world.world() (removed again by the destructor).
    ImpactRecorder(SceneWorld& world, const btRigidBody& target, const btRigidBody& impactor,
                   const Eigen::Isometry3d& targetRestToWorld);
    ~ImpactRecorder() override;
    ImpactRecorder(const ImpactRecorder&) = delete;
    ImpactRecorder& operator=(const ImpactRecorder&) = delete;

    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>& fragments,
                         const FractureEventInfo& info) override;

    // Body frame to rest frame of a target piece; nullptr for other bodies.
    const Eigen::Isometry3d* restFrameOf(const btCollisionObject* body) const;

    struct Contact {
        long step = 0;  // internal step, counting from 1
        std::string piece;
        Eigen::Vector3d point, normal;  // rest frame; normal points into the target
        double impulse = 0.0;           // [N s]
    };
    // Completes the last step; call once after the run.
    void finish();
    const std::vector<Contact>& contacts() const { return contacts_; }
    double stepLength() const { return stepLength_; }

    // contacts.csv: step,time_s,piece,x,y,z,nx,ny,nz,impulse_Ns (time at the end of the step).
    void writeCsv(const std::string& path) const;

private:
    static void tick(btDynamicsWorld* world, btScalar timeStep);
    void scan();

    SceneWorld& world_;
    double stepLength_;
    std::map<const btCollisionObject*, Eigen::Isometry3d> restFrames_;  // target pieces
    std::set<const btCollisionObject*> impactor_;                       // impactor pieces
    std::vector<Contact> contacts_, pending_;                           // committed; the current step's
    long step_ = 0;
};

}  // namespace btfracture
