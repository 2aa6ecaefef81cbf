#include "texture/uv_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bvh/mesh.h"
#include "core/box.h"
#include "core/instance.h"
#include "core/sphere.h"
#include "smooth_mesh/smooth_mesh.h"

namespace rb {

// [sphere-uv]
SurfaceUV sphereUV(const Vec3& d) {
    // [exercise-sphere-uv]
    // Exercise 10.1, the sphere's (u, v): read ch10-sphere.
    // Blank: return SurfaceUV{};
    constexpr double pi = std::numbers::pi;
    // φ about +y from +x towards −z, folded into [0, 2π); θ from the south pole.
    double phi = std::atan2(-d.z, d.x);
    if (phi < 0.0) phi += 2.0 * pi;
    const double cosTheta = std::clamp(-d.y, -1.0, 1.0);
    const double theta = std::acos(cosTheta);
    SurfaceUV s;
    s.uv = Vec2(phi / (2.0 * pi), theta / pi);
    // d = (sinθ cosφ, −cosθ, −sinθ sinφ): differentiate by φ = 2πu and θ = πv.
    const double sinTheta = std::sqrt(d.x * d.x + d.z * d.z);
    const double cosPhi = sinTheta > 0.0 ? d.x / sinTheta : 1.0;
    const double sinPhi = sinTheta > 0.0 ? -d.z / sinTheta : 0.0;
    s.dpdu = 2.0 * pi * Vec3(d.z, 0.0, -d.x);
    s.dpdv = pi * Vec3(cosTheta * cosPhi, sinTheta, -cosTheta * sinPhi);
    return s;
    // [exercise-sphere-uv]
}
// [sphere-uv]

// [box-uv]
SurfaceUV boxFaceUV(const Vec3& p, int axis) {
    const bool positive = p[axis] > 0.5;
    SurfaceUV s;
    // Each face as seen from outside: u to the right, v up.
    switch (axis) {
        case 0:  // ±x faces, y up
            s.uv = Vec2(positive ? 1.0 - p.z : p.z, p.y);
            s.dpdu = Vec3(0.0, 0.0, positive ? -1.0 : 1.0);
            s.dpdv = Vec3(0.0, 1.0, 0.0);
            break;
        case 1:  // the top seen with −z up, the bottom with +z up
            s.uv = Vec2(p.x, positive ? 1.0 - p.z : p.z);
            s.dpdu = Vec3(1.0, 0.0, 0.0);
            s.dpdv = Vec3(0.0, 0.0, positive ? -1.0 : 1.0);
            break;
        default:  // ±z faces, y up
            s.uv = Vec2(positive ? p.x : 1.0 - p.x, p.y);
            s.dpdu = Vec3(positive ? 1.0 : -1.0, 0.0, 0.0);
            s.dpdv = Vec3(0.0, 1.0, 0.0);
            break;
    }
    return s;
}
// [box-uv]

SurfaceUV planarUV(const Vec3& p) {
    return SurfaceUV{Vec2(p.x, -p.z), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, -1.0)};
}

SurfaceUV cylindricalUV(const Vec3& p) {
    constexpr double pi = std::numbers::pi;
    double phi = std::atan2(-p.z, p.x);
    if (phi < 0.0) phi += 2.0 * pi;
    // p = (r cosφ, y, −r sinφ): dp/du = 2π·(z, 0, −x), dp/dv = (0, 1, 0).
    return SurfaceUV{Vec2(phi / (2.0 * pi), p.y), 2.0 * pi * Vec3(p.z, 0.0, -p.x),
                     Vec3(0.0, 1.0, 0.0)};
}

// [mesh-uv]
SurfaceUV meshUV(const Mesh& mesh, std::uint32_t triangle, const Vec2& barycentric, const Vec3& p) {
    const TriangleTexcoords* t = mesh.texcoords(triangle);
    if (!t) return planarUV(p);
    // [exercise-mesh-uv]
    // Exercise 10.2, interpolating `vt`: read ch10-mesh.
    // Blank: return planarUV(p);
    const double b1 = barycentric.x, b2 = barycentric.y, b0 = 1.0 - b1 - b2;
    return SurfaceUV{b0 * t->uv[0] + b1 * t->uv[1] + b2 * t->uv[2], t->dpdu, t->dpdv};
    // [exercise-mesh-uv]
}
// [mesh-uv]

SurfaceUV surfaceUV(const Hit& hit, UVMapping mapping) {
    if (!hit.instance) return SurfaceUV{hit.uv};
    const Instance& instance = *hit.instance;
    const Vec3 p = transformPoint(instance.worldToObject, hit.p);
    SurfaceUV s;
    const Shape* shape = instance.shape;
    if (mapping == UVMapping::Planar) {
        s = planarUV(p);
    } else if (mapping == UVMapping::Cylindrical) {
        s = cylindricalUV(p);
    } else if (mapping == UVMapping::Spherical || dynamic_cast<const Sphere*>(shape)) {
        // The direction from the centre; on the unit sphere dp/du and dp/dv scale by |p| = 1.
        const double r = glm::length(p);
        s = r > 0.0 ? sphereUV(p / r) : SurfaceUV{};
        s.dpdu *= r;
        s.dpdv *= r;
    } else if (dynamic_cast<const Box*>(shape)) {
        s = boxFaceUV(p, static_cast<int>(std::min<std::uint32_t>(hit.primitive, 2)));
    } else if (const auto* mesh = dynamic_cast<const Mesh*>(shape)) {
        s = meshUV(*mesh, hit.primitive, hit.uv, p);
    } else if (const auto* smooth = dynamic_cast<const SmoothMesh*>(shape)) {
        // Chapter 9's smooth mesh wraps a Mesh: the same triangles, the same `vt`.
        s = meshUV(smooth->mesh(), hit.primitive, hit.uv, p);
    } else if (!shape->surfaceCoordinates(p, hit.primitive, s.uv, s.dpdu, s.dpdv)) {
        // A shape with no coordinates of its own (a CSG node) is projected.
        s = planarUV(p);
    }
    // Tangent vectors transform with the object's linear part.
    const Mat3 linear(instance.objectToWorld);
    s.dpdu = linear * s.dpdu;
    s.dpdv = linear * s.dpdv;
    return s;
}

}  // namespace rb
