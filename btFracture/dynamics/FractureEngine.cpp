// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FractureEngine.h>

#include <btFracture/dynamics/btFractureRigidBody.h>

namespace btfracture {

double FractureEngine::meanCurvature(const btFractureRigidBody& body,
                                     const Eigen::Vector3d& bodyPoint) const {
    return body.meanCurvatureAt(bodyPoint);
}

}  // namespace btfracture
