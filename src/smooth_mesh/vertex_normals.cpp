#include "smooth_mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rb {

Vec3 faceNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 n = glm::cross(p1 - p0, p2 - p0);
    const double length = glm::length(n);
    // Catch degenerate faces: zero (or non-finite) area has no direction.
    if (!(length > 0.0) || !std::isfinite(length)) return Vec3(0.0);
    return n / length;
}

double cornerAngle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 a = p1 - p0, b = p2 - p0;
    // atan2 of |a × b| and a · b is accurate for small and near-π angles alike (acos of the
    // normalised dot product is not).
    const double sinPart = glm::length(glm::cross(a, b)), cosPart = glm::dot(a, b);
    if (!(sinPart > 0.0)) return 0.0;
    return std::atan2(sinPart, cosPart);
}

namespace {

/// The file's normal for a corner, if it has a usable one (finite, non-zero length).
bool fileNormal(const ObjData& data, const ObjCorner& corner, Vec3& n) {
    if (corner.vn < 0) return false;
    const Vec3 v = data.normals[corner.vn];
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    n = v / length;
    return true;
}

}  // namespace

// [angle-weighted]
Vec3 angleWeightedNormal(const std::vector<FaceAtVertex>& faces, const Vec3& ng, double cosCrease) {
    // [exercise-angle-weighted]
    // Exercise 9.2, the angle-weighted vertex normal: read ch09-vertex-normals.
    // Blank: return ng;
    Vec3 sum(0.0);
    for (const FaceAtVertex& face : faces) {
        const Vec3 n = glm::dot(face.n, ng) < 0.0 ? -face.n : face.n;
        // Across a crease the faces keep their own normals: a cube stays a cube.
        if (glm::dot(n, ng) < cosCrease) continue;
        sum += face.angle * n;
    }
    const double length = glm::length(sum);
    return length > 0.0 && std::isfinite(length) ? sum / length : ng;
    // [exercise-angle-weighted]
}
// [angle-weighted]

// [vertex-normals]
std::vector<std::array<Vec3, 3>> cornerNormals(const ObjData& data, NormalSource source,
                                               double creaseDegrees) {
    const size_t count = data.triangles.size();
    // Each face's unit normal and its angle at each corner.
    std::vector<Vec3> faceN(count);
    std::vector<std::array<double, 3>> angles(count);
    for (size_t f = 0; f < count; ++f) {
        const auto& c = data.triangles[f];
        const Vec3 p[3] = {data.positions[c[0].v], data.positions[c[1].v], data.positions[c[2].v]};
        faceN[f] = faceNormal(p[0], p[1], p[2]);
        for (int k = 0; k < 3; ++k)
            angles[f][k] = cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
    }
    // One vertex per distinct position: files often repeat a position (a seam, a texture
    // split), and its faces should still be averaged together.
    std::vector<size_t> vertexOf(data.positions.size());
    {
        std::map<std::array<double, 3>, size_t> first;
        for (size_t i = 0; i < data.positions.size(); ++i) {
            const Vec3& p = data.positions[i];
            vertexOf[i] = first.emplace(std::array<double, 3>{p.x, p.y, p.z}, i).first->second;
        }
    }
    // The faces around each vertex, with their angles there.
    std::vector<std::vector<FaceAtVertex>> around(data.positions.size());
    for (size_t f = 0; f < count; ++f)
        for (int k = 0; k < 3; ++k)
            if (faceN[f] != Vec3(0.0))
                around[vertexOf[data.triangles[f][k].v]].push_back(
                    FaceAtVertex{faceN[f], angles[f][k]});
    const double cosCrease = std::cos(glm::radians(std::clamp(creaseDegrees, 0.0, 180.0)));
    std::vector<std::array<Vec3, 3>> normals(count);
    for (size_t f = 0; f < count; ++f) {
        const Vec3 ng = faceN[f];
        if (ng == Vec3(0.0)) continue;  // degenerate: dropped by the mesh, never shaded
        for (int k = 0; k < 3; ++k) {
            Vec3 n;
            if (source == NormalSource::File && fileNormal(data, data.triangles[f][k], n)) {
                // Take the file's normal on this face's side: course meshes wind both ways.
                normals[f][k] = glm::dot(n, ng) < 0.0 ? -n : n;
                continue;
            }
            normals[f][k] =
                angleWeightedNormal(around[vertexOf[data.triangles[f][k].v]], ng, cosCrease);
        }
    }
    return normals;
}
// [vertex-normals]

}  // namespace rb
