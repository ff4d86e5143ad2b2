// SPDX-License-Identifier: Zlib
#pragma once
// One contact of a fracturable body during one rigid-body step, as the fracture engine sees it.
#include <Eigen/Core>

namespace btfracture {

struct BodyContact {
    // Contact point on this body's surface, body frame (origin at the centre of mass, principal
    // axes) [m].
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    // Unit direction of the impulse applied to this body, body frame: it points into the body
    // (the direction of approach of the other body, paper §5.1).
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    double impulse = 0.0;        // J >= 0, normal impulse of the step (Bullet's m_appliedImpulse) [N s]
    double approachSpeed = 0.0;  // normal approach speed before the solve [m/s] (unfloored)
    double duration = 0.0;       // Hertz contact duration t_c [s] (HertzContact.h), > 0
    double peakForce = 0.0;      // Hertz peak force F_max [N] at the floored approach speed
    // The Hertz effective quantities of the pair (HertzContact.h): E* [Pa], R* [m] (capped at the
    // body's characteristic length), m* [kg].
    double effectiveModulus = 0.0;
    double effectiveRadius = 0.0;
    double effectiveMass = 0.0;
};

}  // namespace btfracture
