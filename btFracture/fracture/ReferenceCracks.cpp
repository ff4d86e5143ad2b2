// SPDX-License-Identifier: Zlib
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/FractureSolver.h>
#include <btFracture/fracture/ReferenceCracks.h>
#include <btFracture/fracture/StressIntensity.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

TriangleMesh pennyCrackCube(double radius, int cells) {
    return makeBox(Eigen::Vector3d(4 * radius, 4 * radius, 4 * radius), cells, cells, cells);
}

namespace {

// Grid lines on [lo, hi]: spacing h on [f0, f1], growing by 1.5 per cell away from it (the
// last cell towards each end stretched or merged to land on it).
std::vector<double> gradedLines(double lo, double hi, double f0, double f1, double h) {
    std::vector<double> lines;
    const int n = std::max(1, static_cast<int>(std::ceil((f1 - f0) / h - 1e-9)));
    for (int i = 0; i <= n; ++i) lines.push_back(f0 + (f1 - f0) * i / n);
    auto march = [h](double from, double to) {  // lines after `from` up to `to` (included)
        std::vector<double> out;
        const double sign = to > from ? 1.0 : -1.0;
        double x = from, step = h;
        while (sign * (to - x) > 1e-12) {
            step *= 1.5;
            if (sign * (to - (x + sign * step)) < 0.5 * step) break;
            x += sign * step;
            out.push_back(x);
        }
        out.push_back(to);
        return out;
    };
    if (f0 > lo)
        for (double x : march(f0, lo)) lines.push_back(x);
    if (f1 < hi)
        for (double x : march(f1, hi)) lines.push_back(x);
    std::sort(lines.begin(), lines.end());
    return lines;
}

// u values from `to` down to `from` in steps of h (count = round((to - from) / h)), then
// `extension` h beyond `from`; with ascending order.
std::vector<double> sheetLines(double from, double to, double h, double extension) {
    const int n = std::max(1, static_cast<int>(std::lround((to - from) / h)));
    std::vector<double> out;
    if (extension > 0.0) out.push_back(from - extension * (to - from) / n);
    for (int i = 0; i <= n; ++i) out.push_back(from + (to - from) * i / n);
    return out;
}

}  // namespace

double edgeCrackFactor(double a, double b) {
    const double r = a / b;
    return std::sqrt(M_PI * a) *
           (1.122 - 0.231 * r + 10.550 * r * r - 21.710 * std::pow(r, 3) + 30.382 * std::pow(r, 4));
}

SurfaceCrackCase edgeCrackCase(double ratio, int elementsPerDepth, double extension, int crackRefinement) {
    const double b = kEdgeCrackPlateWidth, a = ratio * b, thickness = kEdgeCrackPlateThickness,
                 sigma = kEdgeCrackTension;
    const double h = a / elementsPerDepth;
    SurfaceCrackCase c;
    char name[64];
    std::snprintf(name, sizeof name, "edge crack a/b = %.2f", ratio);
    c.name = name;
    c.body = makeGridBox({gradedLines(0.0, b, 0.0, a + h, h), gradedLines(-2 * b, 2 * b, -h, h, h),
                          gradedLines(-0.5 * thickness, 0.5 * thickness, -0.5 * thickness, 0.5 * thickness,
                                      thickness / (2 * std::ceil(0.25 * thickness / h)))});
    c.origin = Eigen::Vector3d::Zero();
    c.U = Eigen::Vector3d::UnitX();
    c.V = Eigen::Vector3d::UnitZ();
    c.along = sheetLines(0.0, a, h / crackRefinement, extension);
    const int acrossCells = 2 * static_cast<int>(std::ceil(0.25 * thickness / h)) * crackRefinement;
    std::vector<double> across;
    if (extension > 0.0) across.push_back(-0.5 * thickness - extension * thickness / acrossCells);
    for (int i = 0; i <= acrossCells; ++i) across.push_back(thickness * (double(i) / acrossCells - 0.5));
    if (extension > 0.0) across.push_back(-across.front());
    c.across = across;
    c.midFront = Eigen::Vector3d(a, 0.0, 0.0);
    Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
    stress(1, 1) = sigma;
    c.tractions = [stress](const SurfaceMesh& mesh) { return uniformStressTractions(mesh, stress); };
    c.exactKI = sigma * edgeCrackFactor(a, b);
    return c;
}

SurfaceCrackCase notchedBeamCase(int elementsPerDepth, double extension) {
    const double W = 0.1, S = 4 * W, B = 0.5 * W, a = 0.5 * W, P = 1e4;
    const double h = a / elementsPerDepth, patch = 0.05 * W;  // half width of each load patch
    SurfaceCrackCase c;
    c.name = "notched beam a/W = 0.5";
    std::vector<double> x = gradedLines(-0.5 * S - 0.25 * W, 0.5 * S + 0.25 * W, -h, h, h);
    for (double side : {-1.0, 1.0}) {  // lines on the support patches' edges
        x.erase(std::remove_if(x.begin(), x.end(),
                               [&](double v) { return std::abs(v - side * 0.5 * S) < 1.5 * patch; }),
                x.end());
        for (double d : {-patch, patch}) x.push_back(side * 0.5 * S + d);
    }
    std::sort(x.begin(), x.end());
    const int acrossCells = 2 * static_cast<int>(std::ceil(0.5 * B / h));
    std::vector<double> z;
    for (int i = 0; i <= acrossCells; ++i) z.push_back(B * (double(i) / acrossCells - 0.5));
    c.body = makeGridBox({x, gradedLines(0.0, W, 0.0, a + h, h), z});
    c.origin = Eigen::Vector3d::Zero();
    c.U = Eigen::Vector3d::UnitY();
    c.V = Eigen::Vector3d::UnitZ();
    c.along = sheetLines(0.0, a, h, extension);
    std::vector<double> across = z;
    if (extension > 0.0) {
        across.insert(across.begin(), -0.5 * B - extension * B / acrossCells);
        across.push_back(0.5 * B + extension * B / acrossCells);
    }
    c.across = across;
    c.midFront = Eigen::Vector3d(0.0, a, 0.0);
    c.tractions = [=](const SurfaceMesh& mesh) {
        // Top patch: the cells next to the crack plane, |x| < h (P down); bottom patches |x -+ S/2| < patch
        // (P/2 up each).
        Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * mesh.triangleCount());
        std::vector<int> top, left, right;
        double topArea = 0.0, leftArea = 0.0, rightArea = 0.0;
        for (int t = 0; t < mesh.triangleCount(); ++t) {
            const Eigen::Vector3d p = mesh.centroid(t) + mesh.offset();
            if (mesh.normal(t).y() > 0.99 && std::abs(p.x()) < h) top.push_back(t), topArea += mesh.area(t);
            if (mesh.normal(t).y() < -0.99 && std::abs(p.x() + 0.5 * S) < patch)
                left.push_back(t), leftArea += mesh.area(t);
            if (mesh.normal(t).y() < -0.99 && std::abs(p.x() - 0.5 * S) < patch)
                right.push_back(t), rightArea += mesh.area(t);
        }
        for (int t : top) q(3 * t + 1) = -P / topArea;
        for (int t : left) q(3 * t + 1) = 0.5 * P / leftArea;
        for (int t : right) q(3 * t + 1) = 0.5 * P / rightArea;
        return q;
    };
    const double r = a / W;
    const double f = 3.0 * std::sqrt(r) * (1.99 - r * (1 - r) * (2.15 - 3.93 * r + 2.7 * r * r)) /
                     (2.0 * (1 + 2 * r) * std::pow(1 - r, 1.5));
    c.exactKI = P * S / (B * std::pow(W, 1.5)) * f;
    return c;
}

void addSurfaceCrackSheet(CrackMesh& cracks, const SurfaceCrackCase& c, const SurfaceMesh& body) {
    std::vector<std::vector<int>> node(c.along.size(), std::vector<int>(c.across.size()));
    for (std::size_t i = 0; i < c.along.size(); ++i)
        for (std::size_t j = 0; j < c.across.size(); ++j)
            node[i][j] = cracks.addNode(c.origin + c.along[i] * c.U + c.across[j] * c.V - body.offset());
    for (std::size_t i = 0; i + 1 < c.along.size(); ++i)
        for (std::size_t j = 0; j + 1 < c.across.size(); ++j) {
            cracks.addTriangle(node[i][j], node[i + 1][j], node[i + 1][j + 1]);
            cracks.addTriangle(node[i][j], node[i + 1][j + 1], node[i][j + 1]);
        }
}

const FrontSifs& midThicknessSifs(const std::vector<FrontSifs>& sifs, const SurfaceCrackCase& c,
                                  const SurfaceMesh& body) {
    if (sifs.empty()) throw Error(c.name + ": the crack has no front");
    auto across = [&](const FrontSifs& f) {
        return std::abs((f.position + body.offset() - c.origin).dot(c.V));
    };
    return *std::min_element(sifs.begin(), sifs.end(),
                             [&](const FrontSifs& x, const FrontSifs& y) { return across(x) < across(y); });
}

SurfaceCrackResult solveSurfaceCrack(const SurfaceCrackCase& c, const Material& material) {
    const ElasticSolver solver{SurfaceMesh(c.body), material};
    const Eigen::VectorXd q = c.tractions(solver.mesh());
    SurfaceCrackResult out;
    for (const FractureMethod method : {FractureMethod::Full, FractureMethod::Estimated}) {
        FractureSettings fs;
        fs.method = method;
        FractureSolver fracture(solver, MaterialField(material), fs);
        addSurfaceCrackSheet(fracture.cracks(), c, solver.mesh());
        fracture.beginEvent(q);
        const double K = midThicknessSifs(fracture.frontSifs(), c, solver.mesh()).KI;
        (method == FractureMethod::Full ? out.KI : out.estimatedKI) = K;
        out.crackUnknowns = fracture.cracks().unknownCount();
    }
    out.surfaceTriangles = solver.mesh().triangleCount();
    return out;
}

double newmanRajuDeepestFactor(double aOverT, double cOverB) {
    // Newman & Raju (1981), a/c = 1, phi = 90 degrees: M1 = 1.04, M2 = -0.54 + 0.89 / 1.2,
    // M3 = 0.5 - 1 / 1.65, g = f_phi = 1, Q = 1 + 1.464, f_w = sec(pi c / 2b sqrt(a/t))^(1/2).
    const double m2 = -0.54 + 0.89 / 1.2, m3 = 0.5 - 1.0 / 1.65;
    const double F = 1.04 + m2 * std::pow(aOverT, 2) + m3 * std::pow(aOverT, 4);
    const double fw = std::sqrt(1.0 / std::cos(0.5 * M_PI * cOverB * std::sqrt(aOverT)));
    return F * fw / std::sqrt(2.464);
}

SemicircularCrackResult solveSemicircularCrack(int rings, const Material& material) {
    const double a = 0.02, t = 4 * a, halfWidth = 4 * a, sigma = kEdgeCrackTension, h = a / rings;
    const TriangleMesh body =
        makeGridBox({gradedLines(0.0, t, 0.0, a + h, h), gradedLines(-8 * a, 8 * a, -h, h, h),
                     gradedLines(-halfWidth, halfWidth, -a - h, a + h, h)});
    const ElasticSolver solver{SurfaceMesh(body), material};
    const SurfaceMesh& mesh = solver.mesh();
    Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
    stress(1, 1) = sigma;
    FractureSettings fs;
    fs.method = FractureMethod::Full;
    FractureSolver fracture(solver, MaterialField(material), fs);
    addHalfDiscCrack(fracture.cracks(), -mesh.offset(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX(), a,
                     rings);
    fracture.beginEvent(uniformStressTractions(mesh, stress));
    const std::vector<FrontSifs> sifs = fracture.frontSifs();
    if (sifs.empty()) throw Error("semicircular crack: the crack has no front");
    const auto [shallowest, deepest] = std::minmax_element(
        sifs.begin(), sifs.end(),
        [](const FrontSifs& x, const FrontSifs& y) { return x.position.x() < y.position.x(); });
    SemicircularCrackResult out;
    out.deepestKI = deepest->KI;
    out.surfaceKI = shallowest->KI;
    out.exactKI = sigma * std::sqrt(M_PI * a) * newmanRajuDeepestFactor(a / t, a / halfWidth);
    out.surfaceTriangles = mesh.triangleCount();
    out.crackUnknowns = fracture.cracks().unknownCount();
    for (int i = 0; i < fracture.cracks().nodeCount(); ++i) out.mouthNodes += fracture.cracks().isMouth(i);
    return out;
}

TriangleMesh growthSlab() {
    return makeBox(Eigen::Vector3d(0.1, 0.05, 0.03), 10, 5, 3);
}

TriangleMesh embeddedGrowthBlock() {
    return makeBox(Eigen::Vector3d(0.1, 0.13, 0.13), 10, 13, 13);
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

void addGrowthPreCrack(CrackMesh& cracks, double offsetY, int rings) {
    addDiscCrack(cracks, Eigen::Vector3d(0.0, offsetY, 0.0), Eigen::Vector3d::UnitX(), 0.012, rings);
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
