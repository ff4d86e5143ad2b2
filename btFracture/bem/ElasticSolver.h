// SPDX-License-Identifier: Zlib
#pragma once
// Pure-Neumann elastostatics on one body (paper §3): assemble K and F, regularise with the
// rigid motions (Eq. 1-3), factor K_R = K + gamma Q Q^T once (Q: orthonormal rigid motions),
// then u = K_R^-1 P F q for any number of traction fields q (P: the projection off the rigid
// motions), shifted by a rigid motion so that T u = 0 (Eq. 1-2).
#include <btFracture/bem/BoundaryOperators.h>
#include <btFracture/bem/SurfaceMesh.h>
#include <btFracture/core/Material.h>

#include <Eigen/Core>

namespace btfracture {

struct ElasticSolverSettings {
    QuadratureSettings quadrature;
    // Tractions whose net force or torque exceed this fraction of their total magnitude are
    // rejected (Eq. 6 must remove them first).
    double balanceTolerance = 1e-8;
};

struct TractionResultant {
    Eigen::Vector3d force;   // int q dx [N]
    Eigen::Vector3d torque;  // int x x q dx about the centre of mass [N m]
    double relative;         // max(|force|, |torque| / radius) / int |q| dx
};

struct ElasticSolverTimings {
    double assembly = 0.0;        // K and F [s]
    double regularisation = 0.0;  // K + gamma Q Q^T [s]
    double factorisation = 0.0;   // dense Cholesky [s]
};

class ElasticSolver {
public:
    // Assembles and factors; throws btfracture::Error for a bad mesh or a system that cannot be
    // factored (reporting its reciprocal condition estimate).
    ElasticSolver(SurfaceMesh mesh, const Material& material, const ElasticSolverSettings& settings = {});

    const SurfaceMesh& mesh() const { return mesh_; }
    const Material& material() const { return material_; }
    const ElasticSolverSettings& settings() const { return settings_; }

    // Nodal displacements u (3n, [m], node-major) for P0 tractions q (3m, [Pa], triangle-major,
    // body frame). Throws if q carries net force or torque (see TractionResultant).
    Eigen::VectorXd displacements(const Eigen::VectorXd& tractions) const;

    // u = K_R^-1 P f, T u = 0, for a load vector f (3n) that does no work on rigid motions (F q
    // of balanced tractions, possibly corrected by crack terms, §4.3). Checks the residual.
    Eigen::VectorXd displacementsFromLoad(const Eigen::VectorXd& load) const;

    // With K_R = L L^T: L^-1 P B, L^-T B, L x and L^T x (3n rows); the crack Schur complement is
    // D - (L^-1 P C)^T (L^-1 P C).
    Eigen::MatrixXd factorSolve(const Eigen::MatrixXd& rhs) const;
    Eigen::MatrixXd factorTransposeSolve(const Eigen::MatrixXd& rhs) const;
    Eigen::VectorXd factorTimes(const Eigen::VectorXd& x) const;
    Eigen::VectorXd factorTransposeTimes(const Eigen::VectorXd& x) const;
    // P B: B without its components along the rigid motions (Euclidean).
    Eigen::MatrixXd withoutRigidMotions(const Eigen::MatrixXd& b) const;
    // Adds the rigid motion that makes T u = 0 (Eq. 1-2); stresses do not change.
    void fixGauge(Eigen::VectorXd& u) const;

    TractionResultant netLoad(const Eigen::VectorXd& tractions) const;

    // Strain energy U = 1/2 integral t.u dA [J] (Clapeyron) of P0 tractions q and nodal
    // displacements u they produce. (u.K u is not it: K u = (1/2 M - K') q is the Neumann
    // equation, not the Dirichlet-to-Neumann map.)
    double strainEnergy(const Eigen::VectorXd& tractions, const Eigen::VectorXd& displacements) const;

    // K, formed from the factor's storage (O(n^2) bytes per call), and K x (both throw once the
    // matrices were released: releaseMatrices).
    Eigen::MatrixXd stiffness() const;
    Eigen::VectorXd stiffnessTimes(const Eigen::VectorXd& x) const;
    // The load f = F q (3n) of P0 tractions q (3m [Pa]), in double from F's single-precision
    // entries: F only forms this product, so the rounding stays near 1e-7 of f (and F takes half
    // the bytes; at 1,500 triangles 41 of the BEM's 82 MB). Throws if q carries net force or
    // torque, as displacements() does.
    Eigen::VectorXd load(const Eigen::VectorXd& tractions) const;
    const Eigen::MatrixXd& regulariser() const { return rigidModes_; }  // T (6 x 3n), Eq. 1-2, unit rows
    const Eigen::MatrixXd& rigidBasis() const { return rigidBasis_; }   // Q (3n x 6), orthonormal
    double regularisationWeight() const { return gamma_; }
    double reciprocalCondition() const { return rcond_; }
    const ElasticSolverTimings& timings() const { return timings_; }
    // Bytes held by dense matrices (the Cholesky factor with K, F).
    std::size_t matrixBytes() const;

    // K, F and the factor are a cache of the mesh: releaseMatrices frees them (the solves and
    // the operator accessors then throw), restoreMatrices assembles and factors them again,
    // bit-identical (the assembly is deterministic). The mesh, T and A stay.
    void releaseMatrices();
    void restoreMatrices();
    bool resident() const { return factor_.size() > 0; }

private:
    void assembleAndFactor();
    void requireResident(const char* what) const;
    // x <- L^-1 x, or L^-T x if transposed (K_R = L L^T), in blocks of 64 columns.
    void solveWithFactorInPlace(Eigen::Ref<Eigen::MatrixXd> x, bool transposed) const;

    SurfaceMesh mesh_;
    Material material_;
    ElasticSolverSettings settings_;
    Eigen::VectorXd stiffnessDiagonal_;  // K's diagonal (K's strict upper triangle: in factor_)
    Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> tractionToLoad_;  // F
    Eigen::MatrixXd rigidModes_;                                                            // T (6 x 3n)
    Eigen::MatrixXd rigidMotions_;                                                          // R (3n x 6)
    Eigen::MatrixXd rigidBasis_;       // Q (3n x 6), orthonormal, span R
    Eigen::MatrixXd gaugeFix_;         // (T R)^-1 T (6 x 3n)
    Eigen::MatrixXd netLoadOperator_;  // A (6 x 3m)
    Eigen::MatrixXd factor_;           // lower: Cholesky factor of K_R; strictly upper: K's
    double gamma_ = 0.0;
    double rcond_ = 0.0;
    ElasticSolverTimings timings_;
};

}  // namespace btfracture
