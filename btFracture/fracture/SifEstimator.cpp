// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/SifEstimator.h>

#include <btFracture/core/PortableMath.h>
#include <btFracture/fracture/PropagationLaw.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

// Kink theta that turns the crack normal n towards +-v within the (m, n) plane, and whether
// it is admissible (cos theta >= 1/3, about 70.5 degrees).
bool kinkTowards(const FrontFrame& f, const Eigen::Vector3d& v, double& theta) {
    double vm = v.dot(f.ahead), vn = v.dot(f.normal);
    if (vn < 0.0) vm = -vm, vn = -vn;  // either sign of the eigenvector
    const double inPlane = std::hypot(vm, vn);
    if (inPlane < 1e-9) return false;
    // New normal after kinking by theta: cos(theta) n - sin(theta) m.
    theta = pmath::atan2(-vm, vn);
    return pmath::cos(theta) >= 1.0 / 3.0;
}

}  // namespace

EstimatorChoice chooseEigenvector(const FrontFrame& frame, const Eigen::Matrix3d& stress,
                                  double compressiveFactor) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(stress);  // ascending eigenvalues
    const Eigen::Vector3d values = eig.eigenvalues();
    EstimatorChoice choice;
    double theta = 0.0;
    auto take = [&](int i) {
        choice.eigenvector = i;
        choice.eigenvalue = values[i];
        choice.kink = theta;
        choice.compressive = values[i] < 0.0;
    };
    if (kinkTowards(frame, eig.eigenvectors().col(2), theta)) {
        take(2);
        return choice;
    }
    // Second largest against the most negative (scaled by the compressive toughness ratio).
    const bool negative = values[0] < 0.0;
    const double second = std::abs(values[1]),
                 compressive = negative ? std::abs(values[0]) / compressiveFactor : -1.0;
    const int first = compressive > second ? 0 : 1, other = first == 0 ? 1 : 0;
    if (kinkTowards(frame, eig.eigenvectors().col(first), theta)) {
        take(first);
    } else if (kinkTowards(frame, eig.eigenvectors().col(other), theta)) {
        take(other);
    } else {  // numerically borderline: fall back to the largest eigenvalue without kinking
        theta = 0.0;
        take(2);
    }
    return choice;
}

FrontSifs estimateSifs(const FrontFrame& frame, const Eigen::Matrix3d& stress, double crackArea,
                       double compressiveFactor, double k) {
    FrontSifs f;
    f.frame = frame;
    const EstimatorChoice choice = chooseEigenvector(frame, stress, compressiveFactor);
    const double scale = k * pmath::pow(M_PI * crackArea, 0.25);
    const double r = modeRatioForKink(choice.kink);
    const double magnitude = std::abs(choice.eigenvalue) * scale;
    f.KI = magnitude / std::sqrt(1.0 + r * r);
    f.KII = r * f.KI;
    f.KIII = scale * frame.tangent.dot(stress * frame.normal);
    f.compressive = choice.compressive;
    return f;
}

namespace {
double largestMagnitude(const Eigen::Matrix3d& stress) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(stress, Eigen::EigenvaluesOnly);
    return eig.eigenvalues().cwiseAbs().maxCoeff();
}
}  // namespace

bool boundStress(Eigen::Matrix3d& stress, double peak) {
    const double magnitude = largestMagnitude(stress);
    if (!(magnitude > peak)) return false;
    stress *= peak / magnitude;
    return true;
}

double peakStress(const std::vector<Eigen::Matrix3d>& stresses) {
    double peak = 0.0;
    for (const Eigen::Matrix3d& s : stresses) peak = std::max(peak, largestMagnitude(s));
    return peak;
}

double energyBoundScale(const std::vector<FrontSifs>& sifs, const std::vector<double>& toughness,
                        double youngsModulus, double poissonRatio, double compressiveFactor, double step,
                        double minimumSpeed, double strainEnergy) {
    const double compliance = (1.0 - poissonRatio * poissonRatio) / youngsModulus;
    auto released = [&](double kappa) {
        double sum = 0.0;
        for (std::size_t i = 0; i < sifs.size(); ++i) {
            FrontSifs f = sifs[i];
            f.KI *= kappa, f.KII *= kappa, f.KIII *= kappa;
            const double d =
                advanceOf(f, toughness[i], compressiveFactor, poissonRatio, step, minimumSpeed).distance;
            const double K = effectiveK(f.KI, f.KII, f.KIII, poissonRatio);
            sum += compliance * K * K * f.spacing * d;
        }
        return sum;
    };
    if (!(released(1.0) > strainEnergy)) return 1.0;
    double lo = 0.0, hi = 1.0;  // released() grows with kappa: bisect to 1e-6
    for (int i = 0; i < 20; ++i) {
        const double mid = 0.5 * (lo + hi);
        (released(mid) > strainEnergy ? hi : lo) = mid;
    }
    return lo;
}

double deliverableEnergy(double strainEnergy, double kinetic, double resting) {
    return std::min(strainEnergy, kinetic + resting);
}

}  // namespace btfracture
