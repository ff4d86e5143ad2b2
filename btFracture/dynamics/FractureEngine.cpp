// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FractureEngine.h>

#include <btFracture/dynamics/btFractureRigidBody.h>

namespace btfracture {

FragmentSpec::Class fragmentSpecClass(FragmentClass c) {
    switch (c) {
        case FragmentClass::ConvexHull:
            return FragmentSpec::Class::ConvexHull;
        case FragmentClass::Unbreakable:
            return FragmentSpec::Class::Mesh;
        case FragmentClass::Breakable:
            return FragmentSpec::Class::Breakable;
        case FragmentClass::KeepsParentSolver:
            return FragmentSpec::Class::KeepsParentSolver;
    }
    return FragmentSpec::Class::Mesh;
}

double FractureEngine::meanCurvature(const btFractureRigidBody& body,
                                     const Eigen::Vector3d& bodyPoint) const {
    return body.meanCurvatureAt(bodyPoint);
}

}  // namespace btfracture
