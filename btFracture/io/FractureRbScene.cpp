// SPDX-License-Identifier: Zlib
#include <btFracture/io/FractureRbScene.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/geometry/ConvexHull.h>
#include <btFracture/io/ReadFile.h>

#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <BulletFileLoader/btBulletFile.h>
#include <BulletWorldImporter/btBulletWorldImporter.h>
#include <btBulletDynamicsCommon.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <type_traits>

namespace btfracture {
namespace {

// ---------------------------------------------------------------------------------------------
// CSV

const char* const kColumnNames[] = {"object name",
                                    "new name",
                                    "linear velocity x",
                                    "linear velocity y",
                                    "linear velocity z",
                                    "angular velocity x",
                                    "angular velocity y",
                                    "angular velocity z",
                                    "state",
                                    "crack mesh size",
                                    "voxel size",
                                    "Young's modulus E",
                                    "Poisson ratio nu",
                                    "density",
                                    "tensile strength",
                                    "fracture toughness",
                                    "compressive factor",
                                    "remesh target",
                                    "ignore crack self-intersection",
                                    "material model",
                                    "max cracks",
                                    "method",
                                    "sampling density"};
constexpr int kMaxColumns = 23;

std::string trim(const std::string& text) {
    const char* blanks = " \t\r\f\v";
    const size_t first = text.find_first_not_of(blanks);
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

std::string shownToken(const std::string& token) {
    std::string shown;
    for (unsigned char c : token.substr(0, 60))
        shown += std::isprint(c) ? std::string(1, static_cast<char>(c)) : std::string("?");
    return shown + (token.size() > 60 ? "..." : "");
}

class CsvRow {
public:
    CsvRow(std::vector<std::string> fields, std::string source, int line)
        : fields_(std::move(fields)), source_(std::move(source)), line_(line) {}

    size_t size() const { return fields_.size(); }
    const std::string& text(int column) const { return fields_[column - 1]; }

    [[noreturn]] void fail(int column, const std::string& expected) const {
        throw Error(source_ + ":" + std::to_string(line_) + ": column " + std::to_string(column) + " (" +
                    kColumnNames[column - 1] + "): expected " + expected + ", got '" +
                    shownToken(text(column)) + "'");
    }
    [[noreturn]] void failRow(const std::string& problem) const {
        throw Error(source_ + ":" + std::to_string(line_) + ": " + problem);
    }

    double number(int column, const std::string& expected) const {
        const std::string& t = text(column);
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(t.c_str(), &end);
        if (t.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) fail(column, expected);
        return value;
    }
    double positive(int column, const std::string& unit) const {
        const std::string expected = "a positive number [" + unit + "]";
        const double value = number(column, expected);
        if (!(value > 0.0)) fail(column, expected);
        return value;
    }
    long integer(int column, long minimum, long maximum, const std::string& expected) const {
        const std::string& t = text(column);
        char* end = nullptr;
        errno = 0;
        const long value = std::strtol(t.c_str(), &end, 10);
        if (t.empty() || *end != '\0' || errno == ERANGE || value < minimum || value > maximum)
            fail(column, expected);
        return value;
    }
    std::string name(int column) const {
        const std::string& t = text(column);
        if (t.empty() || std::any_of(t.begin(), t.end(),
                                     [](unsigned char c) { return std::isspace(c) || !std::isprint(c); }))
            fail(column, "a non-empty name without spaces");
        return t;
    }
    int line() const { return line_; }
    const std::string& source() const { return source_; }

private:
    std::vector<std::string> fields_;
    std::string source_;
    int line_;
};

FractureRbObject parseRow(const CsvRow& row) {
    FractureRbObject o;
    o.line = row.line();
    const size_t n = row.size();
    if (!(n == 2 || n == 9 || (n >= 20 && n <= static_cast<size_t>(kMaxColumns))))
        row.failRow("a row has 2 columns (name, new name), 9 (plus velocities and state) or 20 to " +
                    std::to_string(kMaxColumns) + " (a breakable body), got " + std::to_string(n));
    o.key = row.name(1);
    o.name = row.name(2);
    if (n < 9) return o;
    Eigen::Vector3d v, w;
    for (int k = 0; k < 3; ++k) {
        v[k] = row.number(3 + k, "a number [m/s]");
        w[k] = row.number(6 + k, "a number [rad/s]");
    }
    o.linearVelocity = v;
    o.angularVelocity = w;
    o.motion = static_cast<SceneMotion>(row.integer(9, 0, 2, "0 (dynamic), 1 (sleeping) or 2 (kinematic)"));
    if (n < 20) return o;
    FractureRbObject::Breakable b;
    b.crackMeshSize = row.positive(10, "m");
    b.voxelSize = row.positive(11, "m");
    const double E = row.number(12, "a number [Pa]"), nu = row.number(13, "a number");
    const double density = row.number(14, "a number [kg/m^3]"), strength = row.number(15, "a number [Pa]");
    const double toughness = row.number(16, "a number [Pa m^1/2]"), compressive = row.number(17, "a number");
    try {
        b.material = Material(E, nu, density, strength, toughness, compressive, o.name);
    } catch (const Error& e) {
        row.failRow(std::string("columns 12-17 (material): ") + e.what());
    }
    b.remeshTarget = static_cast<int>(row.integer(18, -1000000000L, 100000000L, "an integer [triangles]"));
    b.ignoreCrackSelfIntersection = row.number(19, "a number (> 0: ignore)") > 0.0;
    b.materialModel = row.text(20);
    if (b.materialModel.empty()) row.fail(20, "a material model (\"default\" for a homogeneous material)");
    if (n >= 21)
        b.maxCracks = static_cast<int>(row.integer(21, -1, 1000000L, "an integer >= -1 (-1: no limit)"));
    if (n >= 22)
        b.method = row.integer(22, 0, 1, "0 (full BEM) or 1 (estimated SIFs)") == 0
                       ? FractureMethod::Full
                       : FractureMethod::Estimated;
    if (n >= 23) b.samplingDensity = row.positive(23, "samples per crack-front edge");
    o.breakable = b;
    return o;
}

}  // namespace

std::vector<FractureRbObject> parseFractureRbCsv(const std::string& text, const std::string& source) {
    std::vector<FractureRbObject> objects;
    std::map<std::string, int> keys;
    int lineNumber = 0;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = trim(text.substr(start, end - start));
        start = end + 1;
        ++lineNumber;
        if (line.empty() || line[0] == '%') continue;
        std::vector<std::string> fields;
        size_t from = 0;
        for (;;) {
            const size_t semicolon = line.find(';', from);
            const std::string field = trim(
                line.substr(from, semicolon == std::string::npos ? std::string::npos : semicolon - from));
            if (!field.empty() && field[0] == '%') break;  // the rest of the line is a comment
            fields.push_back(field);
            if (semicolon == std::string::npos) break;
            from = semicolon + 1;
        }
        // A trailing ';' leaves one empty field (FractureRB's files often end rows that way).
        if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
        FractureRbObject object = parseRow(CsvRow(std::move(fields), source, lineNumber));
        const auto [found, added] = keys.emplace(object.key, lineNumber);
        if (!added)
            throw Error(source + ":" + std::to_string(lineNumber) + ": column 1 (object name): '" +
                        object.key + "' already has a row (line " + std::to_string(found->second) + ")");
        objects.push_back(std::move(object));
    }
    return objects;
}

// ---------------------------------------------------------------------------------------------
// Bullet world file

namespace {

Eigen::Vector3d toEigen(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}

Eigen::Isometry3d toEigen(const btTransform& t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) pose.linear()(i, j) = t.getBasis()[i][j];
    pose.translation() = toEigen(t.getOrigin());
    return pose;
}

// Sends stdout to /dev/null while it lives (Bullet's importer prints with printf).
class SilencedStdout {
public:
    SilencedStdout() {
        std::fflush(stdout);
        saved_ = dup(STDOUT_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        if (saved_ >= 0 && null >= 0) dup2(null, STDOUT_FILENO);
        if (null >= 0) close(null);
    }
    ~SilencedStdout() {
        std::fflush(stdout);
        if (saved_ >= 0) {
            dup2(saved_, STDOUT_FILENO);
            close(saved_);
        }
    }
    SilencedStdout(const SilencedStdout&) = delete;
    SilencedStdout& operator=(const SilencedStdout&) = delete;

private:
    int saved_ = -1;
};

// Keeps the gravity of the file's dynamics world (the importer runs without a world).
class Importer : public btBulletWorldImporter {
public:
    Importer() : btBulletWorldImporter(nullptr) {}
    ~Importer() override { deleteAllData(); }
    void setDynamicsWorldInfo(const btVector3& g, const btContactSolverInfo&) override {
        gravity = toEigen(g);
    }
    std::optional<Eigen::Vector3d> gravity;
};

// One object of the file as the scene needs it. Most come through btBulletWorldImporter; what
// it gets wrong or drops is read from the file's own records:
//  - bodies with a "non-moving" shape (triangle meshes) come back static: their inverse mass is
//    taken from the record;
//  - velocities are not restored: taken from the record;
//  - GImpact bodies are dropped (Debian's importer has no GImpact support): rebuilt from the
//    record and the mesh data of their btGImpactMeshShapeData.
struct FileObject {
    std::string name;
    const btCollisionShape* shape = nullptr;          // the importer's shape, or
    std::shared_ptr<const TriangleMesh> gimpactMesh;  // a GImpact mesh read from the file
    btTransform transform = btTransform::getIdentity();
    bool rigidBody = true, kinematic = false;
    double inverseMass = 0.0, friction = 0.5, restitution = 0.0;
    Eigen::Vector3d linearVelocity = Eigen::Vector3d::Zero(), angularVelocity = Eigen::Vector3d::Zero();
};

struct Record {
    const void* shapeData = nullptr;  // the collision shape's record (btCollisionShapeData first)
    btTransform transform;
    int collisionFlags = 0;
    double inverseMass = 0.0, friction = 0.5, restitution = 0.0;
    Eigen::Vector3d linearVelocity, angularVelocity;
};

template <class Data>
Record recordOf(const Data& data) {
    Record r;
    const auto& object = data.m_collisionObjectData;
    r.shapeData = object.m_collisionShape;
    if constexpr (std::is_same_v<Data, btRigidBodyDoubleData>)
        r.transform.deSerializeDouble(object.m_worldTransform);
    else
        r.transform.deSerializeFloat(object.m_worldTransform);
    r.collisionFlags = object.m_collisionFlags;
    r.inverseMass = data.m_inverseMass;
    r.friction = object.m_friction;
    r.restitution = object.m_restitution;
    for (int k = 0; k < 3; ++k) {
        r.linearVelocity[k] = data.m_linearVelocity.m_floats[k];
        r.angularVelocity[k] = data.m_angularVelocity.m_floats[k];
    }
    return r;
}

// The file's rigid-body records by name (unnamed ones cannot be matched and are left out).
std::map<std::string, Record> recordsOf(bParse::btBulletFile& file) {
    std::map<std::string, Record> records;
    const bool doublePrecision = (file.getFlags() & bParse::FD_DOUBLE_PRECISION) != 0;
    for (int i = 0; i < file.m_rigidBodies.size(); ++i) {
        const char* name;
        Record record;
        if (doublePrecision) {
            const auto& data = *reinterpret_cast<const btRigidBodyDoubleData*>(file.m_rigidBodies[i]);
            name = data.m_collisionObjectData.m_name;
            record = recordOf(data);
        } else {
            const auto& data = *reinterpret_cast<const btRigidBodyFloatData*>(file.m_rigidBodies[i]);
            name = data.m_collisionObjectData.m_name;
            record = recordOf(data);
        }
        if (name && *name) records[name] = record;
    }
    return records;
}

TriangleMesh stridingMesh(const btStridingMeshInterface& data, const btVector3& scaling,
                          const std::string& context);

// Every object of the file, in the importer's order, then the GImpact bodies it dropped.
std::vector<FileObject> fileObjects(Importer& importer, bParse::btBulletFile& file, const std::string& path) {
    const std::map<std::string, Record> records = recordsOf(file);
    std::vector<FileObject> objects;
    std::set<std::string> seen;
    for (int i = 0; i < importer.getNumRigidBodies(); ++i) {
        const btCollisionObject* object = importer.getRigidBodyByIndex(i);
        const char* name = importer.getNameForPointer(object);
        FileObject o;
        o.name = name && *name ? name : "object" + std::to_string(i);
        o.shape = object->getCollisionShape();
        o.transform = object->getWorldTransform();
        o.kinematic = object->isKinematicObject();
        o.friction = object->getFriction();
        o.restitution = object->getRestitution();
        const btRigidBody* rigid = btRigidBody::upcast(object);
        o.rigidBody = rigid != nullptr;
        o.inverseMass = rigid ? rigid->getInvMass() : 0.0;
        const auto record = records.find(o.name);
        if (rigid && record != records.end()) {
            if (o.inverseMass == 0.0 && record->second.inverseMass > 0.0 && !o.kinematic)
                logf(LogLevel::Info, path, ": object '", o.name, "': dynamic ",
                     o.shape ? o.shape->getName() : "", " body (Bullet's importer makes it static); mass ",
                     1.0 / record->second.inverseMass, " kg from the file");
            o.inverseMass = record->second.inverseMass;
            o.kinematic = (record->second.collisionFlags & btCollisionObject::CF_KINEMATIC_OBJECT) != 0;
            o.linearVelocity = record->second.linearVelocity;
            o.angularVelocity = record->second.angularVelocity;
        }
        seen.insert(o.name);
        objects.push_back(std::move(o));
    }
    for (const auto& [name, record] : records) {
        if (seen.count(name)) continue;
        const std::string context = path + ": object '" + name + "'";
        const auto* shape = static_cast<const btCollisionShapeData*>(record.shapeData);
        if (!shape || shape->m_shapeType != GIMPACT_SHAPE_PROXYTYPE)
            throw Error(context + ": Bullet's importer could not read it (shape type " +
                        (shape ? std::to_string(shape->m_shapeType) : std::string("none")) + ")");
        auto& gimpact =
            *const_cast<btGImpactMeshShapeData*>(reinterpret_cast<const btGImpactMeshShapeData*>(shape));
        const btTriangleIndexVertexArray* data = importer.createMeshInterface(gimpact.m_meshInterface);
        btVector3 scaling;
        scaling.deSerializeFloat(gimpact.m_localScaling);
        FileObject o;
        o.name = name;
        auto mesh = std::make_shared<TriangleMesh>(stridingMesh(*data, scaling, context));
        mesh->name = context;
        o.gimpactMesh = mesh;
        o.transform = record.transform;
        o.kinematic = (record.collisionFlags & btCollisionObject::CF_KINEMATIC_OBJECT) != 0;
        o.inverseMass = record.inverseMass;
        o.friction = record.friction;
        o.restitution = record.restitution;
        o.linearVelocity = record.linearVelocity;
        o.angularVelocity = record.angularVelocity;
        logf(LogLevel::Info, context, ": GImpact body (Bullet's importer drops it) read from its mesh data");
        objects.push_back(std::move(o));
    }
    return objects;
}

// The triangles of a striding mesh interface, scaled by `scaling`, with exactly coincident
// vertices merged (exporters often split vertices along seams).
TriangleMesh stridingMesh(const btStridingMeshInterface& data, const btVector3& scaling,
                          const std::string& context) {
    TriangleMesh mesh;
    std::map<std::array<double, 3>, int> index;
    const btVector3 s = data.getScaling() * scaling;
    for (int part = 0; part < data.getNumSubParts(); ++part) {
        const unsigned char *vertexBase = nullptr, *indexBase = nullptr;
        int vertexCount = 0, vertexStride = 0, indexStride = 0, faceCount = 0;
        PHY_ScalarType vertexType, indexType;
        data.getLockedReadOnlyVertexIndexBase(&vertexBase, vertexCount, vertexType, vertexStride, &indexBase,
                                              indexStride, faceCount, indexType, part);
        std::vector<int> merged(static_cast<size_t>(std::max(vertexCount, 0)));
        for (int v = 0; v < vertexCount; ++v) {
            const unsigned char* p = vertexBase + static_cast<size_t>(v) * vertexStride;
            std::array<double, 3> x{};
            for (int k = 0; k < 3; ++k)
                x[k] =
                    (vertexType == PHY_DOUBLE ? reinterpret_cast<const double*>(p)[k]
                                              : static_cast<double>(reinterpret_cast<const float*>(p)[k])) *
                    s[k];
            const auto [found, added] = index.emplace(x, static_cast<int>(mesh.vertices.size()));
            if (added) mesh.vertices.emplace_back(x[0], x[1], x[2]);
            merged[v] = found->second;
        }
        for (int f = 0; f < faceCount; ++f) {
            const unsigned char* p = indexBase + static_cast<size_t>(f) * indexStride;
            std::array<int, 3> t{};
            for (int k = 0; k < 3; ++k) {
                const long i = indexType == PHY_SHORT   ? reinterpret_cast<const unsigned short*>(p)[k]
                               : indexType == PHY_UCHAR ? p[k]
                                                        : reinterpret_cast<const int*>(p)[k];
                if (i < 0 || i >= vertexCount)
                    throw Error(context + ": triangle mesh index " + std::to_string(i) + " out of range (" +
                                std::to_string(vertexCount) + " vertices)");
                t[k] = merged[i];
            }
            mesh.triangles.push_back(t);
        }
        data.unLockReadOnlyVertexBase(part);
    }
    return mesh;
}

// The scene shape of a Bullet shape, and the pose of that shape's frame in the body's frame.
SceneShape sceneShapeOf(const btCollisionShape& shape, const std::string& context,
                        Eigen::Isometry3d& poseInBody) {
    SceneShape s;
    switch (shape.getShapeType()) {
        case BOX_SHAPE_PROXYTYPE:
            s.type = SceneShapeType::Box;
            s.halfExtents = toEigen(static_cast<const btBoxShape&>(shape).getHalfExtentsWithMargin());
            return s;
        case SPHERE_SHAPE_PROXYTYPE:
            s.type = SceneShapeType::Sphere;
            s.radius = static_cast<const btSphereShape&>(shape).getRadius();
            return s;
        case STATIC_PLANE_PROXYTYPE: {
            const auto& plane = static_cast<const btStaticPlaneShape&>(shape);
            s.type = SceneShapeType::Plane;
            s.normal = toEigen(plane.getPlaneNormal());
            s.offset = plane.getPlaneConstant();
            return s;
        }
        case CONVEX_HULL_SHAPE_PROXYTYPE: {
            const auto& hull = static_cast<const btConvexHullShape&>(shape);
            std::vector<Eigen::Vector3d> points;
            for (int i = 0; i < hull.getNumPoints(); ++i)
                points.push_back(toEigen(hull.getUnscaledPoints()[i] * hull.getLocalScaling()));
            s.type = SceneShapeType::Mesh;
            s.meshData = std::make_shared<TriangleMesh>(convexHullMesh(points, context));
            return s;
        }
        case TRIANGLE_MESH_SHAPE_PROXYTYPE:
        case CONVEX_TRIANGLEMESH_SHAPE_PROXYTYPE:
        case GIMPACT_SHAPE_PROXYTYPE:
        case SCALED_TRIANGLE_MESH_SHAPE_PROXYTYPE: {
            const btStridingMeshInterface* data = nullptr;
            btVector3 scaling = shape.getLocalScaling();
            if (shape.getShapeType() == TRIANGLE_MESH_SHAPE_PROXYTYPE)
                data = static_cast<const btTriangleMeshShape&>(shape).getMeshInterface();
            else if (shape.getShapeType() == CONVEX_TRIANGLEMESH_SHAPE_PROXYTYPE)
                data = static_cast<const btConvexTriangleMeshShape&>(shape).getMeshInterface();
            else if (shape.getShapeType() == GIMPACT_SHAPE_PROXYTYPE)
                data = static_cast<const btGImpactMeshShape&>(shape).getMeshInterface();
            else {
                const auto& scaled = static_cast<const btScaledBvhTriangleMeshShape&>(shape);
                data = scaled.getChildShape()->getMeshInterface();
                scaling = scaled.getLocalScaling() * scaled.getChildShape()->getLocalScaling();
            }
            if (!data) throw Error(context + ": triangle mesh shape without mesh data");
            s.type = SceneShapeType::Mesh;
            auto mesh = std::make_shared<TriangleMesh>(stridingMesh(*data, scaling, context));
            mesh->name = context;
            s.meshData = mesh;
            return s;
        }
        case COMPOUND_SHAPE_PROXYTYPE: {
            const auto& compound = static_cast<const btCompoundShape&>(shape);
            if (compound.getNumChildShapes() != 1)
                throw Error(context + ": compound shape with " +
                            std::to_string(compound.getNumChildShapes()) +
                            " children (only compounds with exactly one child are supported)");
            poseInBody = poseInBody * toEigen(compound.getChildTransform(0));
            return sceneShapeOf(*compound.getChildShape(0), context, poseInBody);
        }
        default:
            throw Error(
                context + ": collision shape '" + shape.getName() +
                "' is not supported (supported: box, sphere, static plane, convex hull, triangle mesh, "
                "GImpact mesh, compound with one child)");
    }
}

}  // namespace

Scene readFractureRbScene(const std::string& bulletFile, const std::string& csvFile) {
    const std::vector<FractureRbObject> rows =
        parseFractureRbCsv(readWholeFile(csvFile, "FractureRB parameter file"), csvFile);
    std::string bytes = readWholeFile(bulletFile, "Bullet file");
    const std::string notBullet =
        bulletFile + ": not a Bullet world file (.bullet, written by btDefaultSerializer)";
    if (bytes.size() < 12 || bytes.compare(0, 6, "BULLET") != 0) throw Error(notBullet);
    bParse::btBulletFile file(bytes.data(), static_cast<int>(bytes.size()));
    Importer importer;
    importer.setVerboseMode(0);
    {
        // The importer prints to stdout about the GImpact shapes it skips; the runner's stdout is
        // its summary, so that goes to /dev/null (the skipped bodies are rebuilt and logged).
        const SilencedStdout silence;
        if (!(file.getFlags() & bParse::FD_OK) || !importer.loadFileFromMemory(&file)) throw Error(notBullet);
    }

    Scene scene;
    scene.file = bulletFile;
    scene.name = std::filesystem::path(bulletFile).stem().string();
    scene.world.dt = 1.0 / 250.0;
    scene.world.steps = 1000;
    if (importer.gravity) scene.world.gravity = *importer.gravity;
    scene.effects.outputs.csv = scene.effects.outputs.png = true;  // with motion and gltf

    std::map<std::string, size_t> bodyByKey;
    for (const FileObject& object : fileObjects(importer, file, bulletFile)) {
        SceneBody body;
        body.name = object.name;
        if (std::any_of(body.name.begin(), body.name.end(),
                        [](unsigned char c) { return std::isspace(c) || !std::isprint(c); }))
            throw Error(bulletFile + ": the object name '" + shownToken(body.name) +
                        "' has spaces or control characters; rename it in the file");
        if (bodyByKey.count(body.name))
            throw Error(bulletFile + ": two objects are named '" + body.name + "'");
        const std::string context = bulletFile + ": object '" + body.name + "'";
        Eigen::Isometry3d shapeInBody = Eigen::Isometry3d::Identity();
        if (object.gimpactMesh) {
            body.shape.type = SceneShapeType::Mesh;
            body.shape.meshData = object.gimpactMesh;
        } else if (object.shape) {
            body.shape = sceneShapeOf(*object.shape, context, shapeInBody);
        } else {
            throw Error(context + ": no collision shape");
        }
        const Eigen::Isometry3d shapeInWorld = toEigen(object.transform) * shapeInBody;
        const bool isStatic = !object.kinematic && !(object.inverseMass > 0.0);
        if (body.shape.type == SceneShapeType::Plane) {
            if (!isStatic) throw Error(context + ": a plane must be static");
            body.shape.normal = shapeInWorld.linear() * body.shape.normal;
            body.shape.offset += body.shape.normal.dot(shapeInWorld.translation());
        } else {
            body.position = shapeInWorld.translation();
            body.orientation = Eigen::Quaterniond(shapeInWorld.linear()).normalized();
        }
        if (object.kinematic)
            body.motion = SceneMotion::Kinematic;
        else
            body.mass = isStatic ? 0.0 : 1.0 / object.inverseMass;
        if (!isStatic) {
            body.linearVelocity = object.linearVelocity;
            body.angularVelocity = object.angularVelocity;
        }
        body.friction = std::max(0.0, object.friction);
        body.restitution = std::clamp(object.restitution, 0.0, 1.0);
        if (body.friction != object.friction || body.restitution != object.restitution)
            logf(LogLevel::Info, context, ": friction ", object.friction, " and restitution ",
                 object.restitution, " clamped to >= 0 and [0, 1]");
        bodyByKey[body.name] = scene.bodies.size();
        scene.bodies.push_back(std::move(body));
    }
    if (scene.bodies.empty()) throw Error(bulletFile + ": no rigid bodies or collision objects in the file");

    std::set<std::string> finalNames;
    for (const SceneBody& b : scene.bodies) finalNames.insert(b.name);
    for (const FractureRbObject& row : rows) {
        const std::string where = csvFile + ":" + std::to_string(row.line);
        const auto found = bodyByKey.find(row.key);
        if (found == bodyByKey.end()) {
            std::string names;
            for (const auto& [name, index] : bodyByKey) names += (names.empty() ? "" : ", ") + name;
            throw Error(where + ": column 1 (object name): no object named '" + row.key + "' in " +
                        bulletFile + " (objects: " + names + ")");
        }
        SceneBody& body = scene.bodies[found->second];
        if (row.name != body.name) {
            if (!finalNames.insert(row.name).second)
                throw Error(where + ": column 2 (new name): the name '" + row.name + "' is already taken");
            finalNames.erase(body.name);
            body.name = row.name;
        }
        if (row.linearVelocity) {
            // Column 9 as FractureRB applies it: 2 forces any body kinematic, 1 puts a moving one to sleep.
            if (row.motion == SceneMotion::Kinematic) {
                if (body.shape.type == SceneShapeType::Plane)
                    throw Error(where + ": column 9 (state): object '" + row.key +
                                "' is a plane and cannot be kinematic");
                body.motion = SceneMotion::Kinematic;
                body.mass.reset();
            } else if (row.motion == SceneMotion::Sleeping) {
                if (body.isStatic())
                    logf(LogLevel::Info, where, ": column 9 (state): object '", row.key,
                         "' is static; state 1 ignored");
                else
                    body.motion = SceneMotion::Sleeping;
            }
            if (body.isStatic() && (row.linearVelocity->norm() > 0.0 || row.angularVelocity->norm() > 0.0))
                throw Error(where + ": columns 3-8 (velocities): object '" + row.key +
                            "' is static and cannot move (state 2 makes it kinematic)");
            body.linearVelocity = *row.linearVelocity;
            body.angularVelocity = *row.angularVelocity;
        }
        if (!row.breakable) continue;
        if (body.isStatic() || body.motion == SceneMotion::Kinematic) {
            logf(LogLevel::Info, where, ": object '", row.key,
                 "' is static or kinematic and stays unbreakable (as in FractureRB)");
            continue;
        }
        const FractureRbObject::Breakable& b = *row.breakable;
        body.material = b.material;
        body.mass.reset();  // FractureRB recomputes the mass from volume and density
        body.density = b.material.density();
        body.fracture.fracturable = true;
        body.fracture.method = b.method;
        body.fracture.voxelSize = b.voxelSize;
        body.fracture.crackElementSize = b.crackMeshSize;
        const int own = body.shape.type == SceneShapeType::Mesh
                            ? static_cast<int>(body.shape.meshData->triangles.size())
                        : body.shape.type == SceneShapeType::Box ? 12
                                                                 : body.fracture.bemTriangleTarget;
        body.fracture.bemTriangleTarget = b.remeshTarget > 3 ? b.remeshTarget : own;
        // FractureRB collides with the body's own mesh, so that is the collision resolution.
        body.fracture.collisionTriangleTarget = std::max(own, body.fracture.bemTriangleTarget);
        logf(LogLevel::Info, where, ": '", body.name, "' breaks: ", body.fracture.bemTriangleTarget,
             " BEM triangles, voxel ", b.voxelSize, " m, crack element size ", b.crackMeshSize, " m");
        if (b.materialModel != "default")
            logf(LogLevel::Warning, where, ": column 20 (material model): '", shownToken(b.materialModel),
                 "' is not supported; using the homogeneous values of columns 12-17");
        if (b.ignoreCrackSelfIntersection || b.maxCracks != -1 || b.samplingDensity != 1.0)
            logf(LogLevel::Info, where,
                 ": columns 19, 21, 23 (self-intersection, max cracks, sampling density) have no btFracture "
                 "equivalent and are ignored");
    }
    return scene;
}

}  // namespace btfracture
