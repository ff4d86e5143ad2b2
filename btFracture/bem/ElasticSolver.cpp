// SPDX-License-Identifier: Zlib
#include <btFracture/bem/ElasticSolver.h>

#include <btFracture/bem/RigidModes.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ParallelProduct.h>
#include <btFracture/core/Timer.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace btfracture {

ElasticSolver::ElasticSolver(SurfaceMesh mesh, const Material& material,
                             const ElasticSolverSettings& settings)
    : mesh_(std::move(mesh)), material_(material), settings_(settings) {
    assembleAndFactor();
}

void ElasticSolver::assembleAndFactor() {
    Timer timer;
    {
        BoundaryOperators ops = assembleBoundaryOperators(
            mesh_, {material_.shearModulus(), material_.poissonRatio()}, settings_.quadrature);
        factor_ = std::move(ops.stiffness);
        tractionToLoad_ = ops.tractionToLoad.cast<float>();
    }
    // Rows of T scaled to unit length, so that the gauge fix below is well scaled at any body size
    // (unscaled, translation rows grow as L^2 and rotation rows as L^3).
    rigidModes_ = rigidModeOperator(mesh_);
    for (Eigen::Index r = 0; r < rigidModes_.rows(); ++r) rigidModes_.row(r).normalize();
    netLoadOperator_ = netLoadOperator(mesh_);
    rigidMotions_ = rigidMotions(mesh_);
    rigidBasis_ = Eigen::MatrixXd::Identity(rigidMotions_.rows(), 6);
    Eigen::HouseholderQR<Eigen::MatrixXd>(rigidMotions_).householderQ().applyThisOnTheLeft(rigidBasis_);
    gaugeFix_ = (rigidModes_ * rigidMotions_).partialPivLu().solve(rigidModes_);
    timings_.assembly = timer.seconds();

    // K_R = K + gamma Q Q^T, gamma = tr(K) / 3n, Q an orthonormal basis of the rigid motions
    // (K's null space): symmetric positive definite, so its Cholesky factor L serves the crack
    // Schur complement in the symmetric form D - (L^-1 P C)^T (L^-1 P C). The paper's Eq. 3
    // (K^T K + gamma T^T T) has the same solutions for loads free of rigid-motion work, at N^3
    // more flops and the square of K's condition number (FORMULATION.md). K_R and L take K's
    // lower triangle; K's strict upper triangle stays (K is symmetric) and its diagonal is kept
    // aside, so that K itself costs no storage.
    timer.restart();
    stiffnessDiagonal_ = factor_.diagonal();
    gamma_ = factor_.trace() / static_cast<double>(factor_.rows());
    factor_.selfadjointView<Eigen::Lower>().rankUpdate(rigidBasis_, gamma_);
    timings_.regularisation = timer.seconds();

    timer.restart();
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(factor_);
    timings_.factorisation = timer.seconds();
    rcond_ = llt.info() == Eigen::Success ? llt.rcond() : 0.0;
    if (llt.info() != Eigen::Success || !(rcond_ > 1e-15)) {
        std::ostringstream msg;
        msg << mesh_.triangleCount() << "-triangle BEM system of material '" << material_.name()
            << "' cannot be factored (reciprocal condition estimate " << rcond_
            << "); the mesh is probably degenerate (slivers, near-coincident nodes)";
        throw Error(msg.str());
    }
    if (rcond_ < 1e-12)
        logf(LogLevel::Warning, "BEM system of ", mesh_.triangleCount(),
             " triangles is ill-conditioned (rcond ", rcond_, "); results may be inaccurate");
}

void ElasticSolver::releaseMatrices() {
    stiffnessDiagonal_ = Eigen::VectorXd();
    tractionToLoad_ = decltype(tractionToLoad_)();
    factor_ = Eigen::MatrixXd();
}

void ElasticSolver::restoreMatrices() {
    if (!resident()) assembleAndFactor();
}

void ElasticSolver::requireResident(const char* what) const {
    if (!resident())
        throw Error(std::string("ElasticSolver::") + what + ": the BEM matrices of this " +
                    std::to_string(mesh_.triangleCount()) +
                    "-triangle mesh were released; call restoreMatrices()");
}

Eigen::MatrixXd ElasticSolver::stiffness() const {
    requireResident("stiffness");
    Eigen::MatrixXd K = factor_.triangularView<Eigen::StrictlyUpper>();
    K += K.transpose().eval();
    K.diagonal() = stiffnessDiagonal_;
    return K;
}

Eigen::VectorXd ElasticSolver::stiffnessTimes(const Eigen::VectorXd& x) const {
    requireResident("stiffnessTimes");
    Eigen::VectorXd y = stiffnessDiagonal_.cwiseProduct(x);
    y.noalias() += factor_.triangularView<Eigen::StrictlyUpper>() * x;
    y.noalias() += factor_.triangularView<Eigen::StrictlyUpper>().transpose() * x;
    return y;
}

Eigen::VectorXd ElasticSolver::load(const Eigen::VectorXd& q) const {
    if (q.size() != 3 * mesh_.triangleCount()) {
        std::ostringstream msg;
        msg << "ElasticSolver: expected " << 3 * mesh_.triangleCount() << " traction values, got "
            << q.size();
        throw Error(msg.str());
    }
    if (!q.allFinite()) throw Error("ElasticSolver: tractions contain NaN or Inf");
    const TractionResultant net = netLoad(q);
    if (net.relative > settings_.balanceTolerance) {
        std::ostringstream msg;
        msg << "tractions are not free of net force and torque (|F| = " << net.force.norm()
            << " N, |M| = " << net.torque.norm() << " N m, relative " << net.relative
            << "); remove them first (paper Eq. 6, balanceTractions)";
        throw Error(msg.str());
    }
    requireResident("load");
    return productInDouble(tractionToLoad_, q);
}

double ElasticSolver::strainEnergy(const Eigen::VectorXd& q, const Eigen::VectorXd& u) const {
    double work = 0.0;
    for (int t = 0; t < mesh_.triangleCount(); ++t) {
        const auto& tri = mesh_.triangle(t);
        const Eigen::Vector3d mean =
            (u.segment<3>(3 * tri[0]) + u.segment<3>(3 * tri[1]) + u.segment<3>(3 * tri[2])) / 3.0;
        work += mesh_.area(t) * q.segment<3>(3 * t).dot(mean);
    }
    return 0.5 * work;
}

TractionResultant ElasticSolver::netLoad(const Eigen::VectorXd& q) const {
    const Eigen::Matrix<double, 6, 1> load = netLoadOperator_ * q;
    TractionResultant net{load.head<3>(), load.tail<3>(), 0.0};
    double magnitude = 0.0;
    for (int t = 0; t < mesh_.triangleCount(); ++t) magnitude += mesh_.area(t) * q.segment<3>(3 * t).norm();
    if (magnitude > 0.0)
        net.relative = std::max(net.force.norm(), net.torque.norm() / mesh_.radius()) / magnitude;
    return net;
}

Eigen::MatrixXd ElasticSolver::withoutRigidMotions(const Eigen::MatrixXd& b) const {
    return b - rigidBasis_ * (rigidBasis_.transpose() * b);
}

void ElasticSolver::solveWithFactorInPlace(Eigen::Ref<Eigen::MatrixXd> x, bool transposed) const {
    forEachColumnBlock(x.cols(), 64, [&](int j0, int w) {
        auto xs = x.middleCols(j0, w);
        if (transposed)
            factor_.triangularView<Eigen::Lower>().transpose().solveInPlace(xs);
        else
            factor_.triangularView<Eigen::Lower>().solveInPlace(xs);
    });
}

Eigen::MatrixXd ElasticSolver::factorSolve(const Eigen::MatrixXd& rhs) const {
    requireResident("factorSolve");
    Eigen::MatrixXd x = withoutRigidMotions(rhs);
    solveWithFactorInPlace(x, false);
    return x;
}

Eigen::MatrixXd ElasticSolver::factorTransposeSolve(const Eigen::MatrixXd& rhs) const {
    requireResident("factorTransposeSolve");
    Eigen::MatrixXd x = rhs;
    solveWithFactorInPlace(x, true);
    return x;
}

Eigen::VectorXd ElasticSolver::factorTimes(const Eigen::VectorXd& x) const {
    requireResident("factorTimes");
    return factor_.triangularView<Eigen::Lower>() * x;
}

Eigen::VectorXd ElasticSolver::factorTransposeTimes(const Eigen::VectorXd& x) const {
    requireResident("factorTransposeTimes");
    return factor_.triangularView<Eigen::Lower>().transpose() * x;
}

void ElasticSolver::fixGauge(Eigen::VectorXd& u) const {
    u -= rigidMotions_ * (gaugeFix_ * u);
}

Eigen::VectorXd ElasticSolver::displacements(const Eigen::VectorXd& q) const {
    return displacementsFromLoad(load(q));
}

Eigen::VectorXd ElasticSolver::displacementsFromLoad(const Eigen::VectorXd& f) const {
    requireResident("displacementsFromLoad");
    const Eigen::VectorXd rhs = withoutRigidMotions(f);
    Eigen::VectorXd u = rhs;
    solveWithFactorInPlace(u, false);
    solveWithFactorInPlace(u, true);
    // Residual of K_R u = P f, formed from K (factor_ holds L, not K_R).
    const Eigen::VectorXd residual =
        stiffnessTimes(u) + gamma_ * rigidBasis_ * (rigidBasis_.transpose() * u) - rhs;
    const double relative = residual.norm() / std::max(rhs.norm(), std::numeric_limits<double>::min());
    if (!u.allFinite() || relative > 1e-6) {
        std::ostringstream msg;
        msg << "BEM solve failed: relative residual " << relative << " (reciprocal condition " << rcond_
            << ")";
        throw Error(msg.str());
    }
    fixGauge(u);
    return u;
}

std::size_t ElasticSolver::matrixBytes() const {
    return sizeof(double) * (factor_.size() + stiffnessDiagonal_.size()) +
           sizeof(float) * tractionToLoad_.size();
}

}  // namespace btfracture
