// SPDX-License-Identifier: Zlib
#include <btFracture/io/FractureRecorderListener.h>

#include <btFracture/core/Error.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

namespace btfracture {

FractureRecorderListener::FractureRecorderListener(FractureRecorder& recorder, double stepLength)
    : recorder_(recorder), stepLength_(stepLength) {
    if (!(stepLength > 0.0)) throw Error("FractureRecorderListener: the step length must be positive");
}

void FractureRecorderListener::addOriginal(const btFractureRigidBody& body, const std::string& name) {
    recorder_.addOriginal(name, body.volume());
    names_[&body] = name;
}

void FractureRecorderListener::onFractureEvent(btFractureRigidBody& parent,
                                               const std::vector<btFractureRigidBody*>& fragments,
                                               const FractureEventInfo& info) {
    const auto found = names_.find(&parent);
    if (found == names_.end())
        throw Error("FractureRecorderListener: body '" + parent.name() +
                    "' broke but was never added with addOriginal");
    FractureEventRecord record;
    record.worldEvent = info.event;
    record.step = info.step;
    record.time = static_cast<double>(info.step) * stepLength_;
    record.body = found->second;
    record.contacts = info.contacts;
    record.impulse = info.impulseSum;
    record.contactDuration = info.contactDuration;
    record.crackTriangles = info.crackTriangles;
    record.method = parent.settings().method;
    record.bemTriangles = parent.settings().bemTriangleTarget;
    record.fractureSeconds = info.engineSeconds;
    record.swapSeconds = info.swapSeconds;
    std::vector<double> volumes;
    for (const btFractureRigidBody* fragment : fragments) volumes.push_back(fragment->volume());
    const std::vector<std::string> names = recorder_.record(record, volumes);
    names_.erase(found);  // the parent leaves the world; its address may be reused
    for (size_t k = 0; k < fragments.size(); ++k) names_[fragments[k]] = names[k];
}

void FractureRecorderListener::onFractureEnergyAudit(const FractureEnergyAudit& audit) {
    recorder_.addEnergyAudit(audit);
}

std::string FractureRecorderListener::nameOf(const btCollisionObject* body) const {
    const auto found = names_.find(body);
    return found == names_.end() ? std::string() : found->second;
}

}  // namespace btfracture
