// SPDX-License-Identifier: Zlib
#include <btFracture/io/Rasterizer.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/PortableMath.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace btfracture {
namespace {

constexpr double kMargin = 1.05;               // framing margin around the bounding sphere
constexpr double kPerspectiveFov = 0.6108652;  // 35 degrees
constexpr double kAmbient = 0.25, kDiffuse = 0.75;
const double kCreaseCosine = pmath::cos(M_PI / 4.0);  // Gouraud: faces within 45 degrees share normals

Eigen::Vector3d unitColour(Rgb c) {
    return Eigen::Vector3d(c.r, c.g, c.b) / 255.0;
}

}  // namespace

Camera Camera::framing(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& view, const Eigen::Vector3d& up,
                       Projection projection, double aspect) {
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite())
        throw Error("Camera::framing: empty or non-finite bounding box");
    if (!(view.norm() > 0.0) || !view.allFinite())
        throw Error("Camera::framing: zero or non-finite view direction");
    if (!(aspect > 0.0)) throw Error("Camera::framing: aspect ratio must be positive");
    Camera camera;
    camera.projection = projection;
    const Eigen::Vector3d centre = box.center();
    double radius = 0.5 * box.diagonal().norm();
    if (!(radius > 1e-9)) {
        logf(LogLevel::Info, "Camera::framing: the bounding box is a point; framing 1 mm around it");
        radius = 1e-3;
    }
    const Eigen::Vector3d back = view.normalized();
    camera.forward = -back;
    Eigen::Vector3d u = up - up.dot(camera.forward) * camera.forward;
    if (!(u.norm() > 1e-6 * up.norm())) {
        // Looking along the up axis: use the world axis least aligned with the view instead.
        Eigen::Index axis;
        camera.forward.cwiseAbs().minCoeff(&axis);
        const Eigen::Vector3d fallback = Eigen::Vector3d::Unit(axis);
        u = fallback - fallback.dot(camera.forward) * camera.forward;
    }
    camera.up = u.normalized();
    camera.right = camera.forward.cross(camera.up);
    if (projection == Projection::Perspective) {
        camera.verticalFov = kPerspectiveFov;
        const double horizontalFov = 2.0 * pmath::atan(aspect * pmath::tan(0.5 * kPerspectiveFov));
        const double distance = kMargin * radius / pmath::sin(0.5 * std::min(kPerspectiveFov, horizontalFov));
        camera.eye = centre + back * distance;
        camera.nearDistance = 1e-2 * distance;
    } else {
        camera.halfHeight = kMargin * radius * std::max(1.0, 1.0 / aspect);
        // Far enough back that a plane's 20 m display square lies in front of the camera.
        const double distance = std::max(3.0 * radius, 30.0);
        camera.eye = centre + back * distance;
        camera.nearDistance = 1e-3 * distance;
    }
    return camera;
}

Rasterizer::Rasterizer(const RenderSettings& settings, const Camera& camera, Rgb background)
    : settings_(settings), camera_(camera) {
    if (settings.supersampling < 1 || settings.supersampling > 4)
        throw Error("Rasterizer: supersampling must lie in [1, 4], got " +
                    std::to_string(settings.supersampling));
    if (settings.width < 1 || settings.height < 1 || settings.width > 8192 || settings.height > 8192)
        throw Error("Rasterizer: image size " + std::to_string(settings.width) + " x " +
                    std::to_string(settings.height) + " outside [1, 8192]");
    width_ = settings.width * settings.supersampling;
    height_ = settings.height * settings.supersampling;
    light_ = (-0.45 * camera.right + 0.65 * camera.up - 0.6 * camera.forward).normalized();
    clear(background);
}

void Rasterizer::clear(Rgb background) {
    const size_t samples = static_cast<size_t>(width_) * height_;
    colour_.resize(3 * samples);
    for (size_t k = 0; k < samples; ++k) {
        colour_[3 * k] = background.r / 255.0f;
        colour_[3 * k + 1] = background.g / 255.0f;
        colour_[3 * k + 2] = background.b / 255.0f;
    }
    depth_.assign(samples, -std::numeric_limits<double>::infinity());
}

Rasterizer::ScreenVertex Rasterizer::project(const Eigen::Vector3d& p, const Eigen::Vector3d& colour) const {
    ScreenVertex s;
    if (camera_.projection == Projection::Perspective) {
        const double focal = 0.5 * height_ / pmath::tan(0.5 * camera_.verticalFov);
        s.x = 0.5 * width_ + focal * p.x() / p.z();
        s.y = 0.5 * height_ - focal * p.y() / p.z();
        s.depth = 1.0 / p.z();
    } else {
        const double scale = 0.5 * height_ / camera_.halfHeight;
        s.x = 0.5 * width_ + scale * p.x();
        s.y = 0.5 * height_ - scale * p.y();
        s.depth = -p.z();
    }
    s.colour = colour;
    return s;
}

void Rasterizer::draw(const TriangleMesh& mesh, Rgb colour, Faces faces) {
    const Eigen::Vector3d base = unitColour(colour);
    const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
    for (const auto& t : mesh.triangles)
        for (int k : t)
            if (k < 0 || static_cast<size_t>(k) >= nv)
                throw Error("Rasterizer: mesh '" + mesh.name + "' has a vertex index out of range");

    std::vector<Eigen::Vector3d> cameraPoints(nv);
    for (size_t i = 0; i < nv; ++i) {
        const Eigen::Vector3d d = mesh.vertices[i] - camera_.eye;
        cameraPoints[i] = Eigen::Vector3d(d.dot(camera_.right), d.dot(camera_.up), d.dot(camera_.forward));
    }
    std::vector<Eigen::Vector3d> areaNormal(nt), unitNormal(nt);
    for (size_t t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        areaNormal[t] = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                            .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
        const double length = areaNormal[t].norm();
        unitNormal[t] = length > 0.0 ? Eigen::Vector3d(areaNormal[t] / length) : Eigen::Vector3d::Zero();
    }
    // Gouraud: area-weighted vertex normals; a corner whose vertex normal turns more than 45
    // degrees away from its face (an edge or corner of a box) takes the face normal instead.
    std::vector<Eigen::Vector3d> vertexNormal;
    if (settings_.shading == Shading::Gouraud) {
        vertexNormal.assign(nv, Eigen::Vector3d::Zero());
        for (size_t t = 0; t < nt; ++t)
            for (int k : mesh.triangles[t]) vertexNormal[k] += areaNormal[t];
        for (auto& n : vertexNormal) n.normalize();
    }
    auto shade = [&](const Eigen::Vector3d& normal) {
        return Eigen::Vector3d(base * (kAmbient + kDiffuse * std::max(0.0, normal.dot(light_))));
    };

    for (size_t t = 0; t < nt; ++t) {
        const Eigen::Vector3d& n = unitNormal[t];
        if (n.isZero()) continue;
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d toCamera = camera_.projection == Projection::Perspective
                                             ? Eigen::Vector3d(camera_.eye - mesh.vertices[tri[0]])
                                             : Eigen::Vector3d(-camera_.forward);
        double side = 1.0;
        if (n.dot(toCamera) <= 0.0) {
            if (faces == Faces::Front) continue;
            side = -1.0;  // the back of an open surface, lit as seen
        }
        // Corners: camera-space position and lit colour.
        Eigen::Vector3d corner[3], lit[3];
        for (int k = 0; k < 3; ++k) {
            corner[k] = cameraPoints[tri[k]];
            if (settings_.shading == Shading::Flat) {
                lit[k] = shade(side * n);
            } else {
                const Eigen::Vector3d& smooth = vertexNormal[tri[k]];
                lit[k] = shade(side * (smooth.dot(n) > kCreaseCosine ? smooth : n));
            }
        }
        // Clip against the near plane (Sutherland-Hodgman, one plane: at most 4 corners).
        Eigen::Vector3d clipped[4], clippedColour[4];
        int count = 0;
        for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            const bool inK = corner[k].z() >= camera_.nearDistance,
                       inL = corner[l].z() >= camera_.nearDistance;
            if (inK) {
                clipped[count] = corner[k];
                clippedColour[count++] = lit[k];
            }
            if (inK != inL) {
                const double s = (camera_.nearDistance - corner[k].z()) / (corner[l].z() - corner[k].z());
                clipped[count] = corner[k] + s * (corner[l] - corner[k]);
                clippedColour[count++] = lit[k] + s * (lit[l] - lit[k]);
            }
        }
        if (count < 3) continue;
        const ScreenVertex first = project(clipped[0], clippedColour[0]);
        for (int k = 1; k + 1 < count; ++k)
            fillTriangle(first, project(clipped[k], clippedColour[k]),
                         project(clipped[k + 1], clippedColour[k + 1]));
    }
}

void Rasterizer::fillTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (!(std::abs(area) > 1e-12)) return;
    const double minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
    const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
    // Pixel (i, j) is sampled at its centre (i + 0.5, j + 0.5).
    const int x0 = std::max(0, static_cast<int>(std::floor(minX - 0.5)));
    const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(minY - 0.5)));
    const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil(maxY - 0.5)));
    if (x0 > x1 || y0 > y1) return;
    const double inverseArea = 1.0 / area;
    // Edge functions, linear in the sample position: w_a is opposite corner a, and so on.
    auto edge = [](const ScreenVertex& u, const ScreenVertex& v, double px, double py) {
        return (v.x - u.x) * (py - u.y) - (v.y - u.y) * (px - u.x);
    };
    const double stepA = -(c.y - b.y), stepB = -(a.y - c.y), stepC = -(b.y - a.y);
    const double steps[3] = {stepA * inverseArea, stepB * inverseArea, stepC * inverseArea};
    for (int j = y0; j <= y1; ++j) {
        const double py = j + 0.5;
        // The span of this row inside all three edges (barycentric l(x) = l0 + step (x - x0) >= 0),
        // widened by a pixel each side; the exact test below decides.
        const double atX0[3] = {edge(b, c, x0 + 0.5, py) * inverseArea,
                                edge(c, a, x0 + 0.5, py) * inverseArea,
                                edge(a, b, x0 + 0.5, py) * inverseArea};
        double lo = x0, hi = x1;
        for (int e = 0; e < 3; ++e) {
            if (steps[e] > 0.0)
                lo = std::max(lo, x0 - atX0[e] / steps[e]);
            else if (steps[e] < 0.0)
                hi = std::min(hi, x0 - atX0[e] / steps[e]);
            else if (atX0[e] < 0.0)
                hi = lo - 1.0;  // parallel to this edge and outside it
        }
        if (!(hi >= lo - 1.0)) continue;
        const int first = std::max(x0, static_cast<int>(std::floor(lo)) - 1);
        const int last = std::min(x1, static_cast<int>(std::ceil(hi)) + 1);
        const double px = first + 0.5;
        double wa = edge(b, c, px, py), wb = edge(c, a, px, py), wc = edge(a, b, px, py);
        for (int i = first; i <= last; ++i, wa += stepA, wb += stepB, wc += stepC) {
            const double la = wa * inverseArea, lb = wb * inverseArea, lc = wc * inverseArea;
            if (la < 0.0 || lb < 0.0 || lc < 0.0) continue;
            const double depth = la * a.depth + lb * b.depth + lc * c.depth;
            const size_t index = static_cast<size_t>(j) * width_ + i;
            if (depth <= depth_[index]) continue;
            depth_[index] = depth;
            const Eigen::Vector3d colour = la * a.colour + lb * b.colour + lc * c.colour;
            for (int k = 0; k < 3; ++k) colour_[3 * index + k] = static_cast<float>(colour[k]);
        }
    }
}

Image Rasterizer::image() const {
    const int s = settings_.supersampling;
    const float scale = 255.0f / static_cast<float>(s * s);
    Image out(settings_.width, settings_.height);
    Rgb* pixel = out.data();
    for (int y = 0; y < settings_.height; ++y)
        for (int x = 0; x < settings_.width; ++x, ++pixel) {
            float sum[3] = {0.0f, 0.0f, 0.0f};
            for (int v = 0; v < s; ++v) {
                const float* row =
                    &colour_[3 * (static_cast<size_t>(y * s + v) * width_ + static_cast<size_t>(x * s))];
                for (int u = 0; u < 3 * s; u += 3)
                    for (int k = 0; k < 3; ++k) sum[k] += row[u + k];
            }
            auto byte = [scale](float total) {
                return static_cast<std::uint8_t>(std::clamp(total * scale + 0.5f, 0.0f, 255.0f));
            };
            *pixel = Rgb{byte(sum[0]), byte(sum[1]), byte(sum[2])};
        }
    return out;
}

}  // namespace btfracture
