#pragma once
// Principal frame of an inertia tensor (Bullet bodies need a diagonal local inertia, so a body
// frame is always a principal frame).
#include <Eigen/Core>

namespace btfracture {

// inertia = rotation * diag(moments) * rotation^T with moments ascending, rotation a proper
// rotation (det +1) with a deterministic sign convention (the largest-magnitude component of each
// of the first two columns is positive). Throws btfracture::Error for a non-finite tensor.
struct PrincipalAxes {
    Eigen::Vector3d moments;
    Eigen::Matrix3d rotation;
};
PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia);

}  // namespace btfracture
