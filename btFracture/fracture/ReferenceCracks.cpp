// SPDX-License-Identifier: Zlib
#include <btFracture/core/PortableMath.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/ReferenceCracks.h>

#include <cmath>

namespace btfracture {

Eigen::VectorXd uniformStressTractions(const SurfaceMesh& mesh, const Eigen::Matrix3d& sigma) {
    Eigen::VectorXd q(3 * mesh.triangleCount());
    for (int t = 0; t < mesh.triangleCount(); ++t) q.segment<3>(3 * t) = sigma * mesh.normal(t);
    return q;
}

PennyCrackSifs pennyCrackSifs(double stress, double radius, double alpha, double poissonRatio) {
    // Kassir & Sih (validation.md (a)): K_I = 2/pi s sin^2(alpha) sqrt(pi a),
    // K_II = 4/(pi (2 - nu)) s sin cos cos(w) sqrt(pi a), K_III = (1 - nu) K_II amplitude sin(w).
    const double root = std::sqrt(M_PI * radius), sc = pmath::sin(alpha) * pmath::cos(alpha);
    PennyCrackSifs k;
    k.KI = 2.0 / M_PI * stress * pmath::sin(alpha) * pmath::sin(alpha) * root;
    k.KIIAmplitude = 4.0 / (M_PI * (2.0 - poissonRatio)) * stress * sc * root;
    k.KIIIAmplitude = (1.0 - poissonRatio) * k.KIIAmplitude;
    return k;
}

TriangleMesh pennyCrackCube(double radius) {
    return makeBox(Eigen::Vector3d(4 * radius, 4 * radius, 4 * radius), 6, 6, 6);
}

TriangleMesh growthSlab() {
    return makeBox(Eigen::Vector3d(0.1, 0.05, 0.03), 10, 5, 3);
}

Material growthMaterial() {
    return Material(3.1e9, 0.327, 1200.0, 1e9, 1e3, 2.0, "growing");
}

FractureSettings growthSettings(FractureMethod method) {
    FractureSettings fs;
    fs.method = method;
    fs.minimumSpeed = 1.0;  // full step for every growing node: the same step lengths in each run
    fs.maxNewCracksPerEvent = 0;
    fs.frontEdgeLength = 0.6;
    return fs;
}

void addGrowthPreCrack(CrackMesh& cracks, double offsetY) {
    addDiscCrack(cracks, Eigen::Vector3d(0.0, offsetY, 0.0), Eigen::Vector3d::UnitX(), 0.012, 2);
}

Eigen::Matrix3d modeOneStress() {
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(0, 0) = 1e6;
    return sigma;
}

Eigen::Matrix3d modeTwoStress() {
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(0, 1) = sigma(1, 0) = 1e6;
    return sigma;
}

}  // namespace btfracture
