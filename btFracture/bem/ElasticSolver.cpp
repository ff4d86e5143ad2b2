// SPDX-License-Identifier: Zlib
#include <btFracture/bem/ElasticSolver.h>

#include <btFracture/bem/RigidModes.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ParallelProduct.h>
#include <btFracture/core/Timer.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace btfracture {
namespace {

// Lower triangle of K^T K (the upper one is left untouched): independent block products
// spread over the threads, N^3 flops instead of a full GEMM's 2 N^3. Deterministic: each block
// is one GEMM on one thread.
void lowerGram(const Eigen::MatrixXd& K, Eigen::MatrixXd& out) {
    const int n = static_cast<int>(K.cols());
    constexpr int kBlock = 192;
    const int blocks = (n + kBlock - 1) / kBlock;
    std::vector<std::pair<int, int>> tasks;
    for (int j = 0; j < blocks; ++j)
        for (int i = j; i < blocks; ++i) tasks.emplace_back(i, j);
    out.resize(n, n);
#pragma omp parallel for schedule(dynamic, 1)
    for (int t = 0; t < static_cast<int>(tasks.size()); ++t) {
        const int i0 = tasks[t].first * kBlock, j0 = tasks[t].second * kBlock;
        const int h = std::min(kBlock, n - i0), w = std::min(kBlock, n - j0);
        out.block(i0, j0, h, w).noalias() = K.middleCols(i0, h).transpose() * K.middleCols(j0, w);
    }
}

}  // namespace

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
        stiffness_ = std::move(ops.stiffness);
        tractionToLoad_ = ops.tractionToLoad.cast<float>();
    }
    // Rows of T scaled to unit length: the regulariser then has the size of K^T K at any body
    // size (unscaled, translation rows grow as L^2 and rotation rows as L^3 while K grows as L,
    // so a millimetre body's K_R was singular to machine precision: rcond 2e-16). The null space,
    // and so the solution, is the same (Eq. 2 only asks T u = 0).
    rigidModes_ = rigidModeOperator(mesh_);
    for (Eigen::Index r = 0; r < rigidModes_.rows(); ++r) rigidModes_.row(r).normalize();
    netLoadOperator_ = netLoadOperator(mesh_);
    timings_.assembly = timer.seconds();

    // Eq. 3: K_R = K^T K + gamma T^T T, gamma = (tr(K) / 3n)^2. K is symmetric, so K^T K = K K.
    timer.restart();
    const Eigen::MatrixXd& K = stiffness_;
    const double n3 = static_cast<double>(K.rows());
    gamma_ = (K.trace() / n3) * (K.trace() / n3);
    lowerGram(K, factor_);
    factor_.triangularView<Eigen::Lower>() += gamma_ * rigidModes_.transpose() * rigidModes_;
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
    stiffness_ = Eigen::MatrixXd();
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

const Eigen::MatrixXd& ElasticSolver::stiffness() const {
    requireResident("stiffness");
    return stiffness_;
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

Eigen::MatrixXd ElasticSolver::solveRegularised(const Eigen::MatrixXd& rhs) const {
    requireResident("solveRegularised");
    Eigen::MatrixXd x = rhs;
    forEachColumnBlock(x.cols(), 16, [&](int j0, int w) {
        auto xs = x.middleCols(j0, w);
        factor_.triangularView<Eigen::Lower>().solveInPlace(xs);
        factor_.triangularView<Eigen::Lower>().transpose().solveInPlace(xs);
    });
    return x;
}

Eigen::VectorXd ElasticSolver::displacements(const Eigen::VectorXd& q) const {
    return displacementsFromLoad(load(q));
}

Eigen::VectorXd ElasticSolver::displacementsFromLoad(const Eigen::VectorXd& f) const {
    requireResident("displacementsFromLoad");
    const Eigen::VectorXd rhs = transposedTimes(stiffness_, f);
    Eigen::VectorXd u = solveRegularised(rhs);
    // Residual of K_R u = K^T f, formed without K_R.
    const Eigen::VectorXd residual = transposedTimes(stiffness_, stiffness_ * u) +
                                     gamma_ * rigidModes_.transpose() * (rigidModes_ * u) - rhs;
    const double relative = residual.norm() / std::max(rhs.norm(), std::numeric_limits<double>::min());
    if (!u.allFinite() || relative > 1e-6) {
        std::ostringstream msg;
        msg << "BEM solve failed: relative residual " << relative << " (reciprocal condition " << rcond_
            << ")";
        throw Error(msg.str());
    }
    return u;
}

std::size_t ElasticSolver::matrixBytes() const {
    return sizeof(double) * (stiffness_.size() + factor_.size()) + sizeof(float) * tractionToLoad_.size();
}

}  // namespace btfracture
