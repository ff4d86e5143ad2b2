// SPDX-License-Identifier: Zlib
// Fracture driver: propagation law, estimator (§4.2) against FULL on growing mode-I and mode-II
// cracks with and without the right-hand-side update (§4.3) and its gain limit, the inverse
// correlation of §4.3, the hybrid switch (§4.4) and FULL against HYBRID after it,
// initiation (seeds halved to fit a thin wall), arrest at the surface (also of a front edge's
// midpoint across a hole), a manifold front, determinism.
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/fracture/CrackGrowth.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/FractureSolver.h>
#include <btFracture/fracture/PropagationLaw.h>
#include <btFracture/fracture/ReferenceCracks.h>
#include <btFracture/fracture/SifEstimator.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>

using namespace btfracture;

namespace {

// PMMA-like stiffness; strength high (no new seeds) and toughness tiny (every front grows).
const Material kGrowing = growthMaterial();

struct Slab {
    std::unique_ptr<ElasticSolver> solver;
    Eigen::VectorXd tractions;
    double preCrackOffset = 0.03;  // of the pre-crack along y [m]
};

// The growth slab (ReferenceCracks.h) under the constant stress sigma.
Slab slab(const Eigen::Matrix3d& sigma, const Material& material) {
    Slab s;
    s.solver = std::make_unique<ElasticSolver>(SurfaceMesh(growthSlab()), material);
    s.tractions = uniformStressTractions(s.solver->mesh(), sigma);
    return s;
}

// The embedded-growth block (ReferenceCracks.h) with the pre-crack at its centre.
Slab embeddedSlab(const Eigen::Matrix3d& sigma, const Material& material) {
    Slab s;
    s.solver = std::make_unique<ElasticSolver>(SurfaceMesh(embeddedGrowthBlock()), material);
    s.tractions = uniformStressTractions(s.solver->mesh(), sigma);
    s.preCrackOffset = 0.0;
    return s;
}

struct StepSifs {
    double KI, Keff, maxKinkAfterFirst;
};

// Grows a pre-crack (a disc 2 cm under the top face, normal x) with fixed-length steps and
// returns the mean K_I and K_eff over the front before each step (and the largest kink of a
// front point that can still move).
// (`switchAt`: HYBRID threshold in crack triangles above the surface mesh.)
std::vector<StepSifs> growPreCrack(const Slab& s, FractureMethod method, bool update, int steps,
                                   int switchAt = 0) {
    FractureSettings fs = growthSettings(method);
    fs.estimatorUpdate = update;
    fs.hybridElementThreshold = s.solver->mesh().triangleCount() + std::max(1, switchAt);
    FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
    addGrowthPreCrack(fracture.cracks(), s.preCrackOffset);
    fracture.beginEvent(s.tractions);
    std::vector<StepSifs> out;
    for (int i = 0; i < steps; ++i) {
        StepSifs r{0, 0, 0};
        const auto sifs = fracture.frontSifs();
        for (const auto& f : sifs) {
            r.KI += f.KI / sifs.size();
            r.Keff += effectiveK(f.KI, f.KII, f.KIII, kGrowing.poissonRatio()) / sifs.size();
            if (i > 0 && !fracture.isArrested(f.node))
                r.maxKinkAfterFirst = std::max(r.maxKinkAfterFirst, std::abs(kinkAngle(f.KI, f.KII)));
        }
        out.push_back(r);
        if (fracture.step(i).advancedNodes == 0) break;
    }
    return out;
}

}  // namespace

TEST(PropagationLaw, KinkAngleAndItsInverse) {
    EXPECT_DOUBLE_EQ(kinkAngle(1.0, 0.0), 0.0);
    EXPECT_NEAR(kinkAngle(0.0, 1.0), -std::acos(1.0 / 3.0), 1e-12);  // pure mode II: -70.53 degrees
    EXPECT_NEAR(kinkAngle(1e-12, -1.0), std::acos(1.0 / 3.0), 1e-9);
    for (double theta = -1.2; theta <= 1.2; theta += 0.1) {
        const double r = modeRatioForKink(theta);
        EXPECT_NEAR(kinkAngle(1.0, r), theta, 1e-12) << "theta " << theta;
    }
    EXPECT_NEAR(effectiveK(3.0, 4.0, 0.0, 0.3), 5.0, 1e-12);
    EXPECT_NEAR(effectiveK(0.0, 0.0, std::sqrt(0.7), 0.3), 1.0, 1e-12);
}

TEST(SifEstimator, AlignsTheCrackNormalWithThePrincipalDirection) {
    FrontFrame frame{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(),
                     Eigen::Vector3d::UnitX().cross(Eigen::Vector3d::UnitZ())};
    const double A = 1e-4, k = 2.0 / M_PI, s = 1e6;
    // Tension along the crack normal: pure mode I with K = k s (pi A)^(1/4).
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(2, 2) = s;
    FrontSifs f = estimateSifs(frame, sigma, A, 2.0, k);
    EXPECT_NEAR(f.KI, k * s * std::pow(M_PI * A, 0.25), 1e-9 * s);
    EXPECT_NEAR(f.KII, 0.0, 1e-9 * s);
    // Tension rotated by 30 degrees in the (m, n) plane: the kink turns the normal onto it.
    const double beta = M_PI / 6;
    const Eigen::Vector3d d(std::sin(beta), 0.0, std::cos(beta));  // = cos(b) n + sin(b) m
    sigma = s * d * d.transpose();
    f = estimateSifs(frame, sigma, A, 2.0, k);
    const double theta = kinkAngle(f.KI, f.KII);
    const Eigen::Vector3d newNormal = std::cos(theta) * frame.normal - std::sin(theta) * frame.ahead;
    EXPECT_NEAR(std::abs(newNormal.dot(d)), 1.0, 1e-9);
    EXPECT_NEAR(std::hypot(f.KI, f.KII), k * s * std::pow(M_PI * A, 0.25), 1e-6 * s);
    // Tension along the front's tangent cannot be reached by a kink: the estimator falls back
    // to the next eigenvector; pure compression picks the compressive direction.
    sigma = -s * Eigen::Matrix3d::Identity();
    sigma(2, 2) = -3 * s;
    f = estimateSifs(frame, sigma, A, 2.0, k);
    EXPECT_TRUE(f.compressive);
    // Its magnitude is the chosen eigenvalue's, as for tension (§4.2): the compressive factor
    // raises the threshold (PropagationLaw.h), it does not also scale K.
    const EstimatorChoice choice = chooseEigenvector(frame, sigma, 2.0);
    EXPECT_NEAR(std::hypot(f.KI, f.KII), k * std::abs(choice.eigenvalue) * std::pow(M_PI * A, 0.25),
                1e-6 * s);
    // Out-of-plane shear on the crack plane drives mode III.
    sigma.setZero();
    sigma(1, 2) = sigma(2, 1) = s;
    f = estimateSifs(frame, sigma, A, 2.0, k);
    EXPECT_NEAR(std::abs(f.KIII), k * s * std::pow(M_PI * A, 0.25), 1e-6 * s);
}

TEST(SifEstimator, EstimatesStayWithinWhatTheLoadCanProduce) {
    // A local stress 100 times the surface peak (as the interior integral gives right at the
    // surface) is scaled to 6 / k times the peak, keeping its directions: K_eff then stays
    // within 6 sigma_peak sqrt(pi a) (a = sqrt(A / pi)); a stress below the bound is untouched.
    FrontFrame frame{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(),
                     Eigen::Vector3d::UnitX().cross(Eigen::Vector3d::UnitZ())};
    Eigen::Matrix3d surface = Eigen::Matrix3d::Zero();
    surface(2, 2) = 2e6;
    surface(0, 1) = surface(1, 0) = -1e6;
    const double peak = peakStress({surface, 0.5 * surface});
    EXPECT_NEAR(peak, 2e6, 1e-6);  // eigenvalues 2 MPa and +-1 MPa
    const double k = 2.0 / M_PI, A = 1e-3, bound = kMaxGeometryFactor / k * peak;
    Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
    local(2, 2) = 100 * peak;
    local(0, 2) = local(2, 0) = 10 * peak;
    const Eigen::Matrix3d before = local;
    EXPECT_TRUE(boundStress(local, bound));
    EXPECT_NEAR((local - before * (local(2, 2) / before(2, 2))).norm(), 0.0, 1e-9 * peak);
    const FrontSifs f = estimateSifs(frame, local, A, 2.0, k);
    const double Keff = effectiveK(f.KI, f.KII, f.KIII, 0.3), a = std::sqrt(A / M_PI);
    EXPECT_LE(Keff, 1.0001 * kMaxGeometryFactor * peak * std::sqrt(M_PI * a));
    EXPECT_GT(Keff, 0.5 * kMaxGeometryFactor * peak * std::sqrt(M_PI * a));
    Eigen::Matrix3d small = 0.5 * before / 100.0;
    EXPECT_FALSE(boundStress(small, bound));
    EXPECT_EQ(small, 0.5 * before / 100.0);
}

TEST(SifEstimator, EnergyBoundScalesTheStepToTheStrainEnergy) {
    // One front node well above its toughness, minimum speed 0: it advances d = h (1 - (K_c/K)^2)
    // over its spacing s and releases (1 - nu^2)/E K^2 s d = (1 - nu^2)/E s h (K^2 - K_c^2), so
    // the bound must give (kappa K)^2 = U E / ((1 - nu^2) s h) + K_c^2.
    const double E = 3.1e9, nu = 0.327, Kc = 1e6, h = 0.01;
    FrontSifs f;
    f.frame = FrontFrame{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(),
                         Eigen::Vector3d::UnitX().cross(Eigen::Vector3d::UnitZ())};
    f.KI = 1e4 * Kc;  // what EST reads under a ball without the bound (README: thousands of K_c)
    f.spacing = 0.005;
    const double compliance = (1.0 - nu * nu) / E,
                 release = compliance * f.spacing * h * (f.KI * f.KI - Kc * Kc);
    EXPECT_DOUBLE_EQ(energyBoundScale({f}, {Kc}, E, nu, 2.0, h, 0.0, 2.0 * release), 1.0);
    const double U = 1e-3 * release;
    const double kappa = energyBoundScale({f}, {Kc}, E, nu, 2.0, h, 0.0, U);
    const double expected = std::sqrt(U / (compliance * f.spacing * h) + Kc * Kc) / f.KI;
    EXPECT_NEAR(kappa, expected, 1e-5 * expected);
    EXPECT_LE(kappa, expected);  // never above the energy
    // Two nodes at the same K share the energy: each gets half.
    FrontSifs g = f;
    g.node = 1;
    const double both = energyBoundScale({f, g}, {Kc, Kc}, E, nu, 2.0, h, 0.0, 2.0 * U);
    EXPECT_NEAR(both, expected, 1e-5 * expected);
}

// The pre-cracked growth slab under mode-I tension, with the energy bound.
struct EnergyBoundSlab {
    static FractureSettings settings(FractureMethod method) {
        FractureSettings fs = growthSettings(method);
        fs.energyBound = true;
        return fs;
    }
    explicit EnergyBoundSlab(FractureMethod method = FractureMethod::Estimated)
        : fracture{*s.solver, MaterialField(kGrowing), settings(method)} {
        addGrowthPreCrack(fracture.cracks());
    }
    const Slab s = slab(modeOneStress(), kGrowing);
    FractureSolver fracture;
};

TEST(FractureSolver, StrainEnergyOfTheLoadIsClapeyronsAndLeavesUniformTensionUnbounded) {
    // Uniaxial stress sigma in the crack-free slab stores U = sigma^2 V / (2 E); a 1.2 cm crack
    // growing one step releases about 4 mJ of that 0.19 J, so the energy bound leaves EST's SIFs
    // as estimated.
    EnergyBoundSlab b;
    FractureSolver& fracture = b.fracture;
    fracture.beginEvent(b.s.tractions);
    fracture.frontSifs();
    const double sigma = modeOneStress()(0, 0), volume = 0.2 * 0.1 * 0.06;
    const double expected = sigma * sigma * volume / (2.0 * kGrowing.youngsModulus());
    EXPECT_NEAR(fracture.strainEnergy(), expected, 0.01 * expected);
    EXPECT_EQ(fracture.energyScale(), 1.0);
}

TEST(SifEstimator, DeliverableEnergyIsTheImpactsPlusTheRestingLoad) {
    // window's first event: the ball's J / t_c stores 20.7 kJ, the ball brings 266 J and the
    // frame's resting contacts store 250 J.
    EXPECT_EQ(deliverableEnergy(2.07e4, 266.0, 250.0), 516.0);
    EXPECT_EQ(deliverableEnergy(2.07e4, 3.0e4, 0.0), 2.07e4);  // never more than the tractions store
    EXPECT_EQ(deliverableEnergy(2.07e4, std::numeric_limits<double>::infinity(), 0.0), 2.07e4);
}

// The uniform tension of the slab stores 0.19 J (test above), enough for the step. An impact
// bringing a hundredth of that, plus resting tractions of a tenth of the load (a hundredth of its
// energy), let the step release a fiftieth: the SIFs are scaled below 1, every node by the same
// factor, FULL's as EST's.
void expectEnergyBoundReleasesNoMoreThanTheContactsDeliver(FractureMethod method) {
    EnergyBoundSlab b(method);
    FractureSolver& fracture = b.fracture;
    const Slab& s = b.s;
    ContactEnergy energy;
    fracture.beginEvent(s.tractions, energy);
    const std::vector<FrontSifs> free = fracture.frontSifs();
    ASSERT_EQ(fracture.energyScale(), 1.0);
    const double U = fracture.strainEnergy();
    // Without contacts: EST at most the tractions' strain energy, FULL unbounded (its solution
    // releases what the cracked body stores).
    EXPECT_EQ(fracture.releasableEnergy(),
              method == FractureMethod::Full ? std::numeric_limits<double>::infinity() : U);
    energy.kinetic = 0.01 * U;
    energy.restingTractions = 0.1 * s.tractions;
    fracture.beginEvent(s.tractions, energy);
    const std::vector<FrontSifs> bounded = fracture.frontSifs();
    EXPECT_NEAR(fracture.releasableEnergy(), 0.02 * U, 1e-9 * U);
    EXPECT_LT(fracture.energyScale(), 1.0);
    ASSERT_EQ(bounded.size(), free.size());
    for (std::size_t i = 0; i < free.size(); ++i)
        EXPECT_NEAR(bounded[i].KI, fracture.energyScale() * free[i].KI, 1e-9 * std::abs(free[i].KI));
}

TEST(FractureSolver, EnergyBoundReleasesNoMoreThanTheContactsDeliver) {
    expectEnergyBoundReleasesNoMoreThanTheContactsDeliver(FractureMethod::Estimated);
}

TEST(FractureSolver, EnergyBoundScalesFullsSifsToo) {
    expectEnergyBoundReleasesNoMoreThanTheContactsDeliver(FractureMethod::Full);
}

TEST(SifEstimator, OpeningFromSifsInvertsTheCorrelationAndClosesUnderCompression) {
    // A hexagon (one ring): the centre is the only opening node, the same distance r behind every
    // front edge. Its opening from K_I (§4.3) must give K_I back through the correlation, with the
    // sign of the load: EST's K_I is a magnitude, and a compressive front must close (the old
    // inverse opened it, so the estimator's update pulled the surface outward under compression).
    CrackMesh cracks;
    addDiscCrack(cracks, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.01, 1);
    cracks.refreshUnknowns();
    ASSERT_EQ(cracks.unknownCount(), 1);
    const int centre = cracks.nodeOfUnknown()[0];
    const auto& e = cracks.frontEdges()[0];
    const Eigen::Vector3d s = (cracks.node(e.b) - cracks.node(e.a)).normalized(),
                          toCentre = cracks.node(centre) - cracks.node(e.a);
    const double r = (toCentre - toCentre.dot(s) * s).norm();
    for (const bool compressive : {false, true}) {
        FrontSifs f;
        f.frame.normal = cracks.normal(e.triangle);
        f.frame.ahead = s.cross(f.frame.normal);
        f.frame.tangent = f.frame.ahead.cross(f.frame.normal);
        f.KI = 2e5;  // EST: the magnitude, also when compressive
        f.compressive = compressive;
        Eigen::VectorXd cod = Eigen::VectorXd::Zero(3 * cracks.nodeCount());
        cod.segment<3>(3 * centre) = openingFromSifs(f, r, kGrowing);
        for (const FrontSifs& back : displacementCorrelation(cracks, cod, kGrowing)) {
            EXPECT_NEAR(back.KI, compressive ? -2e5 : 2e5, 2e5 * 1e-9) << "node " << back.node;
            EXPECT_EQ(back.compressive, compressive);
        }
    }
}

TEST(FractureSolver, EstimatorUpdateGainLimitBoundsTheUpdatedEstimate) {
    // Step 0 has no update, so after it both runs have the same crack; at step 1 the §4.3 update
    // raises K_I by 38 % on average (mode-I test above). With a limit of 1.2 every front stays
    // within 1.2 of the run without update, and the limited fronts are counted.
    const Slab s = slab(modeOneStress(), kGrowing);
    auto run = [&](bool update, double limit) {
        FractureSettings fs = growthSettings(FractureMethod::Estimated);
        fs.estimatorUpdate = update;
        fs.estimatorUpdateGainLimit = limit;
        auto fracture = std::make_unique<FractureSolver>(*s.solver, MaterialField(kGrowing), fs);
        addGrowthPreCrack(fracture->cracks());
        fracture->beginEvent(s.tractions);
        fracture->step(0);
        return fracture;
    };
    auto limited = run(true, 1.2), plain = run(false, 0.0);
    const auto a = limited->frontSifs(), b = plain->frontSifs();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_GT(limited->gainLimitedNodes(), 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].node, b[i].node);
        const double Ka = effectiveK(a[i].KI, a[i].KII, a[i].KIII, kGrowing.poissonRatio()),
                     Kb = effectiveK(b[i].KI, b[i].KII, b[i].KIII, kGrowing.poissonRatio());
        EXPECT_LE(Ka, 1.2 * Kb * (1.0 + 1e-9)) << "node " << a[i].node;
    }
}

TEST(FractureSolver, EstimatorTracksFullOnGrowingModeICrack) {
    // In the embedded-crack block, over the four steps in which the crack's radius stays below
    // the ligament to the surface (measured: EST with the §4.3 update within 5.8 %, without it
    // 12.0 %; at the fifth and sixth steps the thinning ligament raises FULL's K_I by 14.6 and
    // 24.1 % above EST's, a finite-body effect the estimate does not model).
    const Slab s = embeddedSlab(modeOneStress(), kGrowing);
    const int steps = kEmbeddedGrowthSteps;
    const auto full = growPreCrack(s, FractureMethod::Full, true, steps);
    const auto est = growPreCrack(s, FractureMethod::Estimated, true, steps);
    const auto plain = growPreCrack(s, FractureMethod::Estimated, false, steps);
    ASSERT_GE(full.size(), 4u);
    double worstUpdated = 0.0, worstPlain = 0.0;
    for (std::size_t i = 0; i < std::min({full.size(), est.size(), plain.size()}); ++i) {
        const double e = est[i].KI / full[i].KI - 1.0, p = plain[i].KI / full[i].KI - 1.0;
        std::printf(
            "mode I step %zu: K_I FULL %.3e, EST %.3e (%+.1f %%), EST without update %.3e (%+.1f %%)\n", i,
            full[i].KI, est[i].KI, 100 * e, plain[i].KI, 100 * p);
        worstUpdated = std::max(worstUpdated, std::abs(e));
        worstPlain = std::max(worstPlain, std::abs(p));
    }
    EXPECT_LT(worstUpdated, 0.15);
    EXPECT_GT(worstPlain, 1.5 * worstUpdated);  // without §4.3 the estimate falls behind as it grows
    // A nominally mode-I crack stays nearly straight in both methods: no front point turns by
    // more than 10 degrees in one step (measured: under 6).
    for (const auto& r : est) EXPECT_LT(r.maxKinkAfterFirst, 10.0 * M_PI / 180.0);
    for (const auto& r : full) EXPECT_LT(r.maxKinkAfterFirst, 10.0 * M_PI / 180.0);
}

TEST(FractureSolver, EstimatorTracksFullOnGrowingModeIICrack) {
    // Shear parallel to the pre-crack (embedded-crack block): it kinks out of its plane, then
    // opens in mode I. The two methods kink differently at first, so their paths separate and
    // come together again (measured K_eff EST / FULL at steps 2, 3, 4: +32.4, +15.0, +4.4 %).
    const Slab s = embeddedSlab(modeTwoStress(), kGrowing);
    const int steps = 5;
    const auto full = growPreCrack(s, FractureMethod::Full, true, steps);
    const auto est = growPreCrack(s, FractureMethod::Estimated, true, steps);
    const auto plain = growPreCrack(s, FractureMethod::Estimated, false, steps);
    double worstUpdated = 0.0, worstPlain = 0.0, last = 1.0;
    for (std::size_t i = 2; i < std::min({full.size(), est.size(), plain.size()}); ++i) {
        const double e = est[i].Keff / full[i].Keff - 1.0, p = plain[i].Keff / full[i].Keff - 1.0;
        std::printf(
            "mode II step %zu: K_eff FULL %.3e, EST %.3e (%+.1f %%), without update %+.1f %%; EST max kink "
            "%.1f deg\n",
            i, full[i].Keff, est[i].Keff, 100 * e, 100 * p, est[i].maxKinkAfterFirst * 180 / M_PI);
        worstUpdated = std::max(worstUpdated, std::abs(e));
        worstPlain = std::max(worstPlain, std::abs(p));
        last = std::abs(e);
    }
    EXPECT_LT(worstUpdated, 0.4);
    EXPECT_LT(last, 0.1);
    // Once turned onto the principal plane the estimated path does not oscillate.
    for (std::size_t i = 1; i < est.size(); ++i)
        EXPECT_LT(est[i].maxKinkAfterFirst, 10.0 * M_PI / 180.0) << "step " << i;
}

TEST(FractureSolver, HybridSwitchesToTheEstimatorAtTheThreshold) {
    const Slab s = embeddedSlab(modeOneStress(), kGrowing);
    FractureSettings fs = growthSettings(FractureMethod::Hybrid);
    fs.hybridElementThreshold = s.solver->mesh().triangleCount() + 60;  // after a few steps
    FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
    addGrowthPreCrack(fracture.cracks(), s.preCrackOffset);
    fracture.beginEvent(s.tractions);
    EXPECT_EQ(fracture.activeMethod(), FractureMethod::Full);
    std::vector<FractureMethod> used;
    double lastFullK = 0.0;
    for (int i = 0; i < 6; ++i) {
        const auto sifs = fracture.frontSifs();
        double K = 0.0;
        for (const auto& f : sifs) K += f.KI / sifs.size();
        const FractureStepRecord r = fracture.step(i);
        used.push_back(r.method);
        if (r.method == FractureMethod::Full) lastFullK = K;
        const int elements = s.solver->mesh().triangleCount() + fracture.cracks().triangleCount();
        if (r.method == FractureMethod::Estimated) {
            // The switch carries the FULL openings over (C cod): no drop in the estimate.
            EXPECT_GT(K, 0.85 * lastFullK);
        }
        (void)elements;
    }
    ASSERT_EQ(used.front(), FractureMethod::Full);
    EXPECT_EQ(used.back(), FractureMethod::Estimated);
    // Once switched, never back.
    const auto firstEst = std::find(used.begin(), used.end(), FractureMethod::Estimated);
    EXPECT_TRUE(
        std::all_of(firstEst, used.end(), [](FractureMethod m) { return m == FractureMethod::Estimated; }));
}

TEST(FractureSolver, HybridTracksFullRightAfterTheSwitch) {
    // The switch must carry FULL's cracks over as EST would have built them (§4.3: each node's
    // opening estimated when the front left it). Carrying the solved openings instead counted the
    // crack twice (in the surface-only stress and in sqrt(pi a)): K_I 22 / 41 % above FULL's with
    // the switch at +30 / +60 crack triangles. Measured now, over the steps in which EST tracks
    // FULL (mode-I test above): within 5.8 %.
    const Slab s = embeddedSlab(modeOneStress(), kGrowing);
    const int steps = kEmbeddedGrowthSteps;
    const auto full = growPreCrack(s, FractureMethod::Full, true, steps);
    ASSERT_GE(full.size(), 4u);
    for (const int switchAt : {30, 60}) {
        const auto hybrid = growPreCrack(s, FractureMethod::Hybrid, true, steps, switchAt);
        ASSERT_EQ(hybrid.size(), full.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < full.size(); ++i) {
            const double e = hybrid[i].KI / full[i].KI - 1.0;
            std::printf("hybrid (switch at +%d) step %zu: K_I FULL %.3e, HYBRID %.3e (%+.1f %%)\n", switchAt,
                        i, full[i].KI, hybrid[i].KI, 100 * e);
            worst = std::max(worst, std::abs(e));
        }
        EXPECT_LT(worst, 0.15) << "switch at +" << switchAt;
    }
}

// §4.2's crack area A counts only the part of a sheet inside the body: a fragment carries its
// parent's whole sheet (§5.3), and the part past its surface is no crack of it. The growth slab's
// pre-crack disc centred on the top face (half of it outside) under uniform tension normal to
// it: K_I = (2/pi) sigma (pi A)^(1/4) at every front node inside, with A the inside half. Before,
// A was the whole disc (K 24 % higher: 42 % of it is inside) and the demo's `bunny_0`, carrying such sheets,
// broke into 432 pieces in its 40-step budget (123 after, in 29 steps).
TEST(FractureSolver, EstimatorCountsOnlyTheCrackAreaInsideTheBody) {
    const Slab s = slab(modeOneStress(), kGrowing);
    FractureSettings fs = growthSettings(FractureMethod::Estimated);
    fs.estimatorUpdate = false;
    FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
    addDiscCrack(fracture.cracks(), Eigen::Vector3d(0.0, 0.05, 0.0), Eigen::Vector3d::UnitX(), 0.012, 2);
    fracture.beginEvent(s.tractions);
    const SurfaceMesh& m = s.solver->mesh();
    const CrackMesh& cracks = fracture.cracks();
    double insideArea = 0.0, wholeArea = 0.0;
    for (int t = 0; t < cracks.triangleCount(); ++t) {
        const auto& tri = cracks.triangle(t);
        wholeArea += cracks.area(t);
        if (m.encloses((cracks.node(tri[0]) + cracks.node(tri[1]) + cracks.node(tri[2])) / 3.0))
            insideArea += cracks.area(t);
    }
    ASSERT_NEAR(insideArea / wholeArea, 0.5, 0.15);
    const double expected = 2.0 / M_PI * modeOneStress()(0, 0) * std::pow(M_PI * insideArea, 0.25);
    int checked = 0;
    for (const FrontSifs& f : fracture.frontSifs()) {
        if (!m.encloses(f.position)) continue;
        EXPECT_NEAR(f.KI / expected, 1.0, 0.03) << "front node " << f.node;
        ++checked;
    }
    std::printf("inside area %.3g of %.3g m^2, %d front nodes inside\n", insideArea, wholeArea, checked);
    EXPECT_GE(checked, 4);

    // The inside test is kept across events. A crack mesh replaced through cracks() (the same
    // triangle count, the disc moved to the slab's centre) is tested again: all of it counts
    // (kept flags would count half and read K_I 16 % low).
    fracture.cracks() = CrackMesh();
    addDiscCrack(fracture.cracks(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.012, 2);
    ASSERT_EQ(fracture.cracks().triangleCount(), cracks.triangleCount());
    fracture.beginEvent(s.tractions);
    const double whole = 2.0 / M_PI * modeOneStress()(0, 0) * std::pow(M_PI * wholeArea, 0.25);
    ASSERT_FALSE(fracture.frontSifs().empty());
    for (const FrontSifs& f : fracture.frontSifs())
        EXPECT_NEAR(f.KI / whole, 1.0, 0.03) << "front node " << f.node;
}

TEST(FractureSolver, InitiationSeedsCracksPerpendicularToTension) {
    // A bar pulled along x above its strength: seeds appear with normals along x, at most the
    // cap, none next to another; FULL's with surfaceSeeds are half-hexagons on the surface whose
    // diameter opens as mouth, EST's hexagons inside.
    const Material weak(3.1e9, 0.327, 1200.0, 5e5, 1e9, 2.0, "weak");  // tough: seeds do not grow
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(0, 0) = 1e6;
    const Slab s = slab(sigma, weak);
    const SurfaceMesh& m = s.solver->mesh();
    {
        FractureSettings fs;
        fs.method = FractureMethod::Estimated;
        fs.maxNewCracksPerEvent = 3;
        FractureSolver fracture(*s.solver, MaterialField(weak), fs);
        EXPECT_EQ(fracture.run(s.tractions, 0.0).seeds, 3);
        const CrackMesh& cracks = fracture.cracks();
        EXPECT_EQ(cracks.triangleCount(), 18);  // three hexagons
        for (int i = 0; i < cracks.nodeCount(); ++i)
            EXPECT_GT(windingNumber(m.nodes(), m.triangles(), cracks.node(i)), 0.5);
    }
    FractureSettings fs;
    fs.method = FractureMethod::Full;
    fs.surfaceSeeds = true;
    fs.maxNewCracksPerEvent = 3;
    FractureSolver fracture(*s.solver, MaterialField(weak), fs);
    const FractureEventReport report = fracture.run(s.tractions, 0.0);
    EXPECT_EQ(report.seeds, 3);
    const CrackMesh& cracks = fracture.cracks();
    EXPECT_EQ(cracks.triangleCount(), 36);  // three two-ring half-hexagons
    for (int t = 0; t < cracks.triangleCount(); ++t) EXPECT_GT(std::abs(cracks.normal(t).x()), 0.99);
    int mouth = 0;
    for (int i = 0; i < cracks.nodeCount(); ++i) {
        mouth += cracks.isMouth(i);
        if (!cracks.onSurface(i)) {
            EXPECT_GT(windingNumber(m.nodes(), m.triangles(), cracks.node(i)), 0.5);
        }
    }
    EXPECT_EQ(mouth, 9);  // of each seed's five diameter nodes, all but the ends
    // Tough material: nothing grows, no step advances.
    for (const auto& r : report.steps) EXPECT_EQ(r.advancedNodes, 0);
    // A second event at the same load seeds elsewhere: no new seed within the diameter of a
    // surface triangle (2 cm here) of an existing front.
    const int oldNodes = cracks.nodeCount();
    const FractureEventReport again = fracture.run(s.tractions, 0.0);
    EXPECT_LE(again.seeds, 3);
    double closest = INFINITY;
    for (int i = oldNodes; i < fracture.cracks().nodeCount(); ++i)
        for (int j = 0; j < oldNodes; ++j)
            closest = std::min(closest, (fracture.cracks().node(i) - fracture.cracks().node(j)).norm());
    if (again.seeds > 0) {
        EXPECT_GT(closest, 0.01);
    }
}

TEST(FractureSolver, FrontsArrestAtTheSurfaceAndRunsAreDeterministic) {
    const Slab s = slab(modeOneStress(), kGrowing);
    auto grow = [&](std::vector<Eigen::Vector3d>& nodes) {
        FractureSettings fs = growthSettings(FractureMethod::Estimated);
        fs.frontEdgeLength = 1.0;
        fs.maxStepsPerEvent = 30;
        FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
        addGrowthPreCrack(fracture.cracks(), 0.02);
        const FractureEventReport report = fracture.run(s.tractions, 0.0);
        for (int i = 0; i < fracture.cracks().nodeCount(); ++i) nodes.push_back(fracture.cracks().node(i));
        return report;
    };
    std::vector<Eigen::Vector3d> first, second;
    const FractureEventReport report = grow(first);
    grow(second);
    // The crack spans the slab's cross-section and stops: the last step advances nothing.
    ASSERT_FALSE(report.steps.empty());
    EXPECT_EQ(report.steps.back().advancedNodes, 0);
    EXPECT_LT(static_cast<int>(report.steps.size()), 30);
    const SurfaceMesh& m = s.solver->mesh();
    for (const auto& p : first) EXPECT_GT(windingNumber(m.nodes(), m.triangles(), p), 0.5);
    double reachY = 0.0;
    for (const auto& p : first) reachY = std::max(reachY, std::abs(p.y() - 0.02));
    EXPECT_GT(reachY, 0.05);  // grew across most of the 10 cm height
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i], second[i]);
}

// CrackSettings::estimatorSurfaceFronts: EST's fronts end on the faces they reach, so the pre-crack
// grown under uniform tension (full-length steps) cuts more of the slab's 10 x 6 cm section than
// with EST's default fronts, which stop just inside the faces: measured 0.909 against 0.832 of it
// (the corners stay uncut, the fronts arrested on the faces next to them). Every node lies inside
// or on the surface; same run, same crack.
TEST(FractureSolver, EstimatorSurfaceFrontsCutTheSlabThrough) {
    const Slab s = slab(modeOneStress(), kGrowing);
    const SurfaceMesh& m = s.solver->mesh();
    auto grow = [&](bool surfaceFronts, std::vector<Eigen::Vector3d>& nodes) {
        FractureSettings fs = growthSettings(FractureMethod::Estimated);
        fs.frontEdgeLength = 1.0;
        fs.maxStepsPerEvent = 30;
        fs.estimatorSurfaceFronts = surfaceFronts;
        FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
        addGrowthPreCrack(fracture.cracks(), 0.02);
        const FractureEventReport report = fracture.run(s.tractions, 0.0);
        EXPECT_FALSE(report.steps.empty());
        if (!report.steps.empty()) {
            EXPECT_EQ(report.steps.back().advancedNodes, 0);
        }
        const CrackMesh& cracks = fracture.cracks();
        double area = 0.0;
        for (int t = 0; t < cracks.triangleCount(); ++t) area += cracks.area(t);
        for (int i = 0; i < cracks.nodeCount(); ++i) {
            nodes.push_back(cracks.node(i));
            if (!cracks.onSurface(i)) {
                EXPECT_GT(windingNumber(m.nodes(), m.triangles(), cracks.node(i)), 0.5);
            }
        }
        return area;
    };
    const double section = 0.1 * 0.06;
    std::vector<Eigen::Vector3d> first, second, inside;
    const double through = grow(true, first) / section, justInside = grow(false, inside) / section;
    std::printf("crack area / section: surface fronts %.4f, default %.4f\n", through, justInside);
    EXPECT_GT(through, 0.88);
    EXPECT_LE(through, 1.0);
    EXPECT_LT(justInside, 0.86);
    grow(true, second);
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i], second[i]);
}

// A new front edge longer than the edge limit is split at its midpoint; across a concave part of
// the body that midpoint lies outside it and must move back inside. A torus (R 10 cm, tube 4 cm)
// with a crack quad in its mid-plane whose front edge joins -+30 degrees on the tube's centre
// circle: those two nodes move along it to -+60 degrees, so the new front edge's midpoint, 5 cm
// from the axis, is in the hole; it moves to 5 mm (0.05 of the edge limit) inside the tube's inner
// wall, 6 cm from the axis. Left in the hole, such midpoints grew on outside the body.
TEST(CrackGrowth, AFrontEdgeSplitAcrossAHoleKeepsItsMidpointInside) {
    const SurfaceMesh torus(makeTorus(0.1, 0.04, 48, 16));
    auto onCircle = [](double degrees) {
        const double a = degrees * M_PI / 180.0;
        return Eigen::Vector3d(0.1 * std::cos(a), 0.1 * std::sin(a), 0.0);
    };
    CrackMesh cracks;
    const int c1 = cracks.addNode(Eigen::Vector3d(0.11, -0.07, 0.0)),
              c2 = cracks.addNode(Eigen::Vector3d(0.11, 0.07, 0.0));
    const int a = cracks.addNode(onCircle(-30.0)), b = cracks.addNode(onCircle(30.0));
    cracks.addTriangle(c1, b, a);
    cracks.addTriangle(c1, c2, b);
    cracks.refreshUnknowns();
    std::map<int, FrontAdvance> advances;
    for (const auto& [node, to] : {std::pair{a, -60.0}, std::pair{b, 60.0}}) {
        const Eigen::Vector3d step = onCircle(to) - cracks.node(node);
        advances[node] = {step.norm(), 0.0, step.normalized()};
    }
    std::vector<char> arrested;
    const GrowthResult growth = growFronts(cracks, advances, torus, 0.1, arrested);
    ASSERT_EQ(growth.advancedNodes, 2);  // the chords from -+30 to -+60 degrees stay in the tube
    ASSERT_EQ(growth.heldNodes, 0);
    // 4 + 2 moved + 1 midpoint: the new front edge (17 cm) split, the side edges (6 cm) not.
    ASSERT_EQ(cracks.nodeCount(), 7);
    int nearAxis = -1;  // the new front edge's midpoint: the node closest to the torus' axis
    for (int i = 0; i < cracks.nodeCount(); ++i)
        if (nearAxis < 0 || cracks.node(i).head<2>().norm() < cracks.node(nearAxis).head<2>().norm())
            nearAxis = i;
    const double rho = cracks.node(nearAxis).head<2>().norm();
    EXPECT_GT(rho, 0.0605);  // inside the inner wall (6 cm, less the faceting of 16 segments)
    EXPECT_LT(rho, 0.0700);
    EXPECT_FALSE(arrested[nearAxis]);
    for (int i = 0; i < cracks.nodeCount(); ++i)
        EXPECT_GT(windingNumber(torus.nodes(), torus.triangles(), cracks.node(i)), 0.5)
            << "crack node " << i << " outside the body";
}

// A front node whose step would put its strip behind its front edge (the new triangle folded back
// over the sheet, where the crack-crack block of Eq. 4 is indefinite) stays where it is for that
// step; its neighbour, stepping ahead, moves. A square crack (10 cm) in the mid-plane of a 1 m
// cube, one front edge along y = 0 with the sheet on y > 0: its end node steps 3 cm at 30 degrees
// from -y to +x (ahead of both of its front edges), its start node 3 cm at 30 degrees from +y to
// -x (behind that edge). Its start node turned to 30 degrees from -y to -x, both move.
TEST(CrackGrowth, AStepBehindTheFrontEdgeIsHeldNotFolded) {
    const SurfaceMesh cube(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 4.0));
    for (const bool backwards : {true, false}) {
        CrackMesh cracks;
        const int a = cracks.addNode(Eigen::Vector3d(0.0, 0.0, 0.0)),
                  b = cracks.addNode(Eigen::Vector3d(0.1, 0.0, 0.0));
        const int c = cracks.addNode(Eigen::Vector3d(0.1, 0.1, 0.0)),
                  d = cracks.addNode(Eigen::Vector3d(0.0, 0.1, 0.0));
        cracks.addTriangle(a, b, c);
        cracks.addTriangle(a, c, d);
        cracks.refreshUnknowns();
        const Eigen::Vector3d normal = cracks.normal(0);
        std::map<int, FrontAdvance> advances;
        const double sin30 = 0.5, cos30 = std::sqrt(3.0) / 2.0;
        advances[b] = {0.03, 0.0, Eigen::Vector3d(sin30, -cos30, 0.0)};
        advances[a] = {0.03, 0.0, Eigen::Vector3d(-sin30, backwards ? cos30 : -cos30, 0.0)};
        std::vector<char> arrested;
        const int before = cracks.triangleCount();
        const GrowthResult growth = growFronts(cracks, advances, cube, 0.2, arrested);
        EXPECT_EQ(growth.heldNodes, backwards ? 1 : 0);
        EXPECT_EQ(growth.advancedNodes, backwards ? 1 : 2);
        EXPECT_EQ(growth.newNode.count(a), backwards ? 0u : 1u);
        EXPECT_GT(cracks.triangleCount(), before);
        for (int t = before; t < cracks.triangleCount(); ++t)
            EXPECT_GT(cracks.normal(t).dot(normal), 0.99) << "new triangle " << t << " turns over the sheet";
    }
}

// FULL's fronts end on the surface they head for (SurfaceReach::OnSurface): a front 0.5 mm inside
// a face of a 1 m cube, stepping 3 cm square to it, goes on to it (before, its step was too short
// to take and it was arrested there, shut, a sliver inside), and a step ending 5 mm short of the
// face (a quarter of the 0.05 max-edge snap) ends on it; its middle node then opens as mouth. EST
// (Inside) keeps both fronts inside.
TEST(CrackGrowth, FullFrontsNearAFaceEndOnIt) {
    const SurfaceMesh cube(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 4.0));
    struct Case {
        double start, distance;
    };
    for (const Case c : {Case{0.4995, 0.03}, Case{0.46, 0.035}})
        for (const SurfaceReach reach : {SurfaceReach::OnSurface, SurfaceReach::Inside}) {
            CrackMesh cracks;  // a trapezoid in the plane x = 0, its front a - m - b at y = c.start
            const int p = cracks.addNode(Eigen::Vector3d(0.0, 0.3, -0.2)),
                      q = cracks.addNode(Eigen::Vector3d(0.0, 0.3, 0.2));
            const int a = cracks.addNode(Eigen::Vector3d(0.0, c.start, -0.1)),
                      m = cracks.addNode(Eigen::Vector3d(0.0, c.start, 0.0)),
                      b = cracks.addNode(Eigen::Vector3d(0.0, c.start, 0.1));
            cracks.addTriangle(p, a, m);
            cracks.addTriangle(p, m, q);
            cracks.addTriangle(q, m, b);
            cracks.refreshUnknowns(cube);
            std::map<int, FrontAdvance> advances;
            for (const int node : {a, m, b}) advances[node] = {c.distance, 0.0, Eigen::Vector3d::UnitY()};
            std::vector<char> arrested;
            const GrowthResult growth =
                growFronts(cracks, advances, cube, 0.2, arrested, FoldGuard::Hold, reach);
            const bool full = reach == SurfaceReach::OnSurface;
            const bool tooClose = c.start > 0.49;
            SCOPED_TRACE(std::string(full ? "FULL" : "EST") + " from y = " + std::to_string(c.start));
            EXPECT_EQ(growth.advancedNodes, full || !tooClose ? 3 : 0);
            if (growth.advancedNodes != 3) continue;
            const int mNew = growth.newNode.at(m);
            EXPECT_NEAR(cracks.node(mNew).y(), full ? 0.5 : c.start + c.distance, 1e-12);
            cracks.refreshUnknowns(cube);
            EXPECT_EQ(cracks.onSurface(mNew), full);
            EXPECT_EQ(cracks.isMouth(mNew), full);
        }
}

// Issue 5: the coarse front stays a manifold curve - every front node has exactly one front
// edge arriving and one leaving, except the ends of FULL's fronts on the surface (its cracks open
// there) - while fronts grow, meet each other, slide along the faces and stop there (two coplanar
// pre-cracks 4.5 cm apart in the growth slab).
TEST(FractureSolver, FrontStaysAManifoldCurveWhileGrowingToTheSurface) {
    const Slab s = slab(modeOneStress(), kGrowing);
    for (const FractureMethod method : {FractureMethod::Full, FractureMethod::Estimated}) {
        FractureSettings fs = growthSettings(method);
        FractureSolver fracture(*s.solver, MaterialField(kGrowing), fs);
        addGrowthPreCrack(fracture.cracks(), 0.02);
        addGrowthPreCrack(fracture.cracks(), -0.025);
        fracture.beginEvent(s.tractions);
        int steps = 0;
        for (; steps < 60; ++steps) {
            const bool advanced = fracture.step(steps).advancedNodes > 0;
            std::map<int, std::pair<int, int>> degree;  // node -> (arriving, leaving) front edges
            for (const auto& e : fracture.cracks().frontEdges()) {
                ++degree[e.a].second;
                ++degree[e.b].first;
            }
            for (const auto& [node, d] : degree)
                EXPECT_TRUE((d.first == 1 && d.second == 1) ||
                            (method == FractureMethod::Full && fracture.cracks().onSurface(node) &&
                             d.first + d.second == 1))
                    << toString(method) << " step " << steps << ": front node " << node << " has " << d.first
                    << " arriving and " << d.second << " leaving front edges";
            if (!advanced) break;
        }
        std::printf("%s: %d steps, %d crack triangles\n", toString(method), steps,
                    fracture.cracks().triangleCount());
        EXPECT_GT(fracture.cracks().triangleCount(), 2 * 24) << toString(method);  // it grew ...
        EXPECT_LT(steps, 60) << toString(method);                                  // ... and stopped
    }
}

// A seed that would poke out of a thin wall is halved (up to twice) instead of skipped: an 8 mm
// plate under tension with 2 cm BEM triangles, where a full seed (circumradius half a triangle
// diameter, 1.4 cm) does not fit anywhere.
TEST(FractureSolver, SeedsInAThinWallAreHalvedToFit) {
    const Material weak(3.1e9, 0.327, 1200.0, 5e5, 1e9, 2.0, "weak");  // tough: seeds do not grow
    ElasticSolver solver(SurfaceMesh(makeBox(Eigen::Vector3d(0.1, 0.004, 0.06), 10, 1, 6)), weak);
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(0, 0) = 1e6;
    const SurfaceMesh& m = solver.mesh();
    double fullRadius = 0.0;
    for (int t = 0; t < m.triangleCount(); ++t)
        fullRadius = std::max(fullRadius, FractureSettings().seedRadius * m.diameter(t));
    // EST's one-ring hexagon inside (1.05 r + r across the 8 mm wall, edges r) fits at a quarter
    // of the full seed at most, FULL's two-ring half-disc on a face (r across it, surfaceSeeds;
    // outer edges 2 sin(18 deg) r = 0.62 r) at a half: edges of 0.31 of the full seed's radius at
    // most either way, 0.5 and 0.62 unhalved. Which face gets a seed follows the rounding (the
    // stress is uniform), so the bound holds on every face.
    for (const FractureMethod method : {FractureMethod::Estimated, FractureMethod::Full}) {
        FractureSettings fs;
        fs.method = method;
        fs.surfaceSeeds = true;  // FULL's half-hexagons; EST seeds hexagons inside regardless
        fs.maxNewCracksPerEvent = 3;
        FractureSolver fracture(solver, MaterialField(weak), fs);
        const FractureEventReport report = fracture.run(uniformStressTractions(solver.mesh(), sigma), 0.0);
        EXPECT_EQ(report.seeds, 3) << toString(method);
        const CrackMesh& cracks = fracture.cracks();
        for (int i = 0; i < cracks.nodeCount(); ++i) {
            if (!cracks.onSurface(i)) {
                EXPECT_GT(windingNumber(m.nodes(), m.triangles(), cracks.node(i)), 0.5) << toString(method);
            }
        }
        for (int t = 0; t < cracks.triangleCount(); ++t) {
            const auto& tri = cracks.triangle(t);
            for (int k = 0; k < 3; ++k)
                EXPECT_LE((cracks.node(tri[k]) - cracks.node(tri[(k + 1) % 3])).norm(), 0.35 * fullRadius)
                    << toString(method);
        }
    }
}
