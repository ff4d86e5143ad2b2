// SPDX-License-Identifier: Zlib
#pragma once
// Opaque per-body fracture state (BEM solver, level set, cracks, ...), created lazily by a
// FractureEngine and owned by the btFractureRigidBody it belongs to. The world never looks
// inside; it only moves states between bodies (fragments carrying cracks, §5.3, or the > 95 %
// fragment keeping its parent's solver, §5.2).
namespace btfracture {

class FractureState {
public:
    virtual ~FractureState() = default;

protected:
    FractureState() = default;
    FractureState(const FractureState&) = delete;
    FractureState& operator=(const FractureState&) = delete;
};

}  // namespace btfracture
