// SPDX-License-Identifier: Zlib
#pragma once
// Keeps a SceneWorld's outputs in step with fracture: the recorder names the fragments and
// writes the statistics row (FractureRecorderListener), then the scene's body list swaps the
// parent for the named fragments (SceneWorld::replaceBody). Register it on the scene's
// btFractureDynamicsWorld; the runner and the scenario tests share it.
#include <btFracture/dynamics/FractureListener.h>

namespace btfracture {

class FractureRecorderListener;
class SceneWorld;

class SceneFractureListener : public FractureListener {
public:
    // Adds every breakable body of `world` to `recorder` under its scene name (addOriginal).
    SceneFractureListener(FractureRecorderListener& recorder, SceneWorld& world);
    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>& fragments,
                         const FractureEventInfo& info) override;
    void onFractureEnergyAudit(const FractureEnergyAudit& audit) override;

private:
    FractureRecorderListener& recorder_;
    SceneWorld& world_;
};

}  // namespace btfracture
