// SPDX-License-Identifier: Zlib
#pragma once
// Bookkeeping of fracture events for the scenario and stability suites: a FractureListener that,
// at every event (parent still in its pre-step state, fragments just swapped in), records
//  - the sum of fragment masses and volumes against the parent's (level-set volumes; dust that
//    is too small to mesh is dropped, so a little is lost);
//  - the linear-momentum identity of the swap: every fragment gets v + w x r at its centre, so
//    sum m_i v_i = m v + w x sum m_i (c_i - c) (m: fragment mass), up to what the separation push
//    explains (it moves centres, not velocities: |w| m push). Reported relative to
//    M (|v| + |w| L), L the cube root of the parent's volume;
//  - the fragment volumes (for determinism checks);
//  - the event's energy audit when the world completes it (dynamics/FractureEnergy.h).
// Register it before listeners that delete or rename the parent.
#include <btFracture/dynamics/FractureListener.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace btfracture::test {

struct FractureEventCheck {
    std::string body;
    double time = 0.0;  // event time [s] (internal step x step length)
    int fragments = 0;
    int refractureDepth = 0;       // of the parent
    double massRatio = 0.0;        // sum of fragment masses / parent mass
    double volumeRatio = 0.0;      // sum of fragment volumes / parent volume
    double momentumError = 0.0;    // relative, see above
    std::vector<double> volumes;   // fragment volumes [m^3], in spawn order
    double engineSeconds = 0.0;    // the fracture engine's time for this event [s]
    EngineTimings engineTimings;   // ... split into BEM, fracture and geometry
    std::uint64_t worldEvent = 0;  // FractureEventInfo::event
    bool hasEnergy = false;        // the audit arrived
    FractureEnergyAudit energy;
};

class FractureEventAccounting : public FractureListener {
public:
    // `stepLength`: the world's internal step [s]; `nameOf`: the parent's name (default: its mesh name).
    explicit FractureEventAccounting(double stepLength,
                                     std::function<std::string(const btFractureRigidBody&)> nameOf = {})
        : step_(stepLength), nameOf_(std::move(nameOf)) {}

    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>& fragments,
                         const FractureEventInfo& info) override {
        auto eig = [](const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); };
        FractureEventCheck e;
        e.body = nameOf_ ? nameOf_(parent) : parent.name();
        e.time = static_cast<double>(info.step) * step_;
        e.fragments = static_cast<int>(fragments.size());
        e.refractureDepth = parent.settings().refractureDepth;
        e.engineSeconds = info.engineSeconds;
        e.engineTimings = info.engineTimings;
        e.worldEvent = info.event;
        const double M = 1.0 / parent.getInvMass();
        const Eigen::Vector3d c = eig(parent.getCenterOfMassPosition()), v = eig(parent.getLinearVelocity()),
                              w = eig(parent.getAngularVelocity());
        double mass = 0.0, volume = 0.0;
        Eigen::Vector3d momentum = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
        for (const btFractureRigidBody* f : fragments) {
            const double m = 1.0 / f->getInvMass();
            mass += m;
            volume += f->volume();
            e.volumes.push_back(f->volume());
            momentum += m * eig(f->getLinearVelocity());
            moment += m * (eig(f->getCenterOfMassPosition()) - c);
        }
        const Eigen::Vector3d expected = mass * v + w.cross(moment);
        const double scale = M * (v.norm() + w.norm() * std::cbrt(parent.volume()));
        e.momentumError =
            std::max(0.0, (momentum - expected).norm() - w.norm() * mass * info.maxSeparationPush) /
            std::max(1e-12, scale);
        e.massRatio = mass / M;
        e.volumeRatio = volume / parent.volume();
        events.push_back(std::move(e));
    }

    void onFractureEnergyAudit(const FractureEnergyAudit& audit) override {
        for (FractureEventCheck& e : events)
            if (e.worldEvent == audit.event) {
                e.hasEnergy = true;
                e.energy = audit;
            }
    }

    std::vector<FractureEventCheck> events;

private:
    double step_;
    std::function<std::string(const btFractureRigidBody&)> nameOf_;
};

}  // namespace btfracture::test
