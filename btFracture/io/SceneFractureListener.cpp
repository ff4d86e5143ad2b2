// SPDX-License-Identifier: Zlib
#include <btFracture/io/SceneFractureListener.h>

#include <btFracture/dynamics/btFractureRigidBody.h>

#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/SceneWorld.h>

#include <string>
#include <utility>

namespace btfracture {

SceneFractureListener::SceneFractureListener(FractureRecorderListener& recorder, SceneWorld& world)
    : recorder_(recorder), world_(world) {
    for (const auto& body : world.bodies())
        if (const btFractureRigidBody* b = btFractureRigidBody::upcast(body.rigidBody))
            recorder.addOriginal(*b, body.name);
}

void SceneFractureListener::onFractureEvent(btFractureRigidBody& parent,
                                            const std::vector<btFractureRigidBody*>& fragments,
                                            const FractureEventInfo& info) {
    recorder_.onFractureEvent(parent, fragments, info);
    std::vector<std::pair<btFractureRigidBody*, std::string>> named;
    for (btFractureRigidBody* fragment : fragments) named.emplace_back(fragment, recorder_.nameOf(fragment));
    world_.replaceBody(parent, named);
}

void SceneFractureListener::onFractureEnergyAudit(const FractureEnergyAudit& audit) {
    recorder_.onFractureEnergyAudit(audit);
}

}  // namespace btfracture
