// SPDX-License-Identifier: Zlib
#pragma once
// Connects a btFractureDynamicsWorld to a FractureRecorder: every fracture event the world
// reports becomes a statistics row, and its fragments get the recorder's stable names
// ("bunny_f3"), which nameOf() gives to the outputs (the world names its fragments the same way
// after their root body's name: the two agree where the output name is the body's name).
//
//   FractureRecorder recorder(dir + "/statistics.csv");
//   FractureRecorderListener listener(recorder, dt);
//   listener.addOriginal(*bunny, "bunny");
//   world.addFractureListener(&listener);
#include <btFracture/dynamics/FractureListener.h>
#include <btFracture/io/FractureRecorder.h>

#include <map>
#include <string>

class btCollisionObject;

namespace btfracture {

class FractureRecorderListener : public FractureListener {
public:
    // `stepLength`: the world's fixed internal step [s] (event time = step index x stepLength).
    FractureRecorderListener(FractureRecorder& recorder, double stepLength);

    // A breakable scene body and its output name (recorder.addOriginal with its volume).
    void addOriginal(const btFractureRigidBody& body, const std::string& name);

    // method is the body's method setting; bemTriangles its BEM target.
    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>& fragments,
                         const FractureEventInfo& info) override;
    void onFractureEnergyAudit(const FractureEnergyAudit& audit) override;

    // The output name of a body added with addOriginal or created by fracture; empty for others.
    std::string nameOf(const btCollisionObject* body) const;

private:
    FractureRecorder& recorder_;
    double stepLength_;
    std::map<const btCollisionObject*, std::string> names_;
};

}  // namespace btfracture
