#include "smooth_mesh/smooth_mesh.h"

#include <cmath>

#include "core/error.h"
#include "core/render_context.h"
#include "phong/phong.h"

namespace rb {

void bindSmoothMesh(LuaBindings& lua);

// [barycentrics]
std::array<double, 3> barycentrics(const Vec3& p, const std::array<Vec3, 3>& v) {
    // Each coordinate is the area of the sub-triangle opposite its corner over the whole
    // area, signed by the winding normal: p = p0 + b1 (p1 - p0) + b2 (p2 - p0).
    const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], toP = p - v[0];
    const Vec3 n = glm::cross(e1, e2);
    const double area2 = glm::dot(n, n);
    if (!(area2 > 0.0) || !std::isfinite(area2)) return {1.0, 0.0, 0.0};
    const double b1 = glm::dot(glm::cross(toP, e2), n) / area2;
    const double b2 = glm::dot(glm::cross(e1, toP), n) / area2;
    return {1.0 - b1 - b2, b1, b2};
}
// [barycentrics]

// [interpolate-normal]
Vec3 interpolateNormal(const std::array<double, 3>& b, const std::array<Vec3, 3>& n,
                       const Vec3& ng) {
    // [exercise-interpolate-normal]
    // Exercise 9.1, interpolating the corner normals: read ch09-interpolation.
    // Blank: return ng;
    const Vec3 sum = b[0] * n[0] + b[1] * n[1] + b[2] * n[2];
    const double length = glm::length(sum);
    // Catch corner normals that cancel: their sum has no direction to speak of.
    if (!(length > 1e-9) || !std::isfinite(length)) return ng;
    return sum / length;
    // [exercise-interpolate-normal]
}
// [interpolate-normal]

// [adapt-normal]
Vec3 adaptShadingNormal(const Vec3& wo, const Vec3& ng, const Vec3& ns) {
    // [exercise-adapt-normal]
    // Exercise 9.3, keeping mirror rays above the surface: read ch09-geometry.
    // Blank: return ns;
    // The mirror image of wo about ns, and its elevation above the flat surface.
    const Vec3 r = 2.0 * glm::dot(wo, ns) * ns - wo;
    const double sinMin = std::sin(kMinReflectionElevation);
    if (glm::dot(r, ng) >= sinMin) return ns;
    // Keep r's heading along the surface and lift it to the minimum elevation.
    const Vec3 along = r - glm::dot(r, ng) * ng;
    const double length = glm::length(along);
    if (!(length > 0.0)) return ng;  // r straight into the surface: no heading to keep
    const Vec3 lifted = std::cos(kMinReflectionElevation) * (along / length) + sinMin * ng;
    // The normal that mirrors wo into `lifted` is their half vector. Both lie above the
    // surface, so the sum cannot vanish.
    return glm::normalize(wo + lifted);
    // [exercise-adapt-normal]
}
// [adapt-normal]

// [terminator-offset]
Vec3 terminatorOffset(const Vec3& p, const std::array<double, 3>& b, const std::array<Vec3, 3>& v,
                      const std::array<Vec3, 3>& n) {
    // [exercise-terminator]
    // Exercise 9.4, the shadow terminator: read ch09-terminator.
    // Blank: return Vec3(0.0);
    Vec3 curved(0.0);
    for (int k = 0; k < 3; ++k) {
        // p's height over the tangent plane of corner k (the plane its normal describes).
        const double height = glm::dot(p - v[k], n[k]);
        // Project p onto that plane, but only upwards: where the surface is concave the flat
        // facet already lies above it, and lowering the origin would put it inside.
        const Vec3 onPlane = height < 0.0 ? p - height * n[k] : p;
        curved += b[k] * onPlane;
    }
    return curved - p;
    // [exercise-terminator]
}
// [terminator-offset]

SmoothMesh::SmoothMesh(std::shared_ptr<const Mesh> mesh, const ObjData& data,
                       const SmoothMeshOptions& options)
    : mesh_(std::move(mesh)),
      normals_(cornerNormals(data, options.normals, options.creaseDegrees)),
      options_(options) {
    corners_.reserve(data.triangles.size());
    for (const auto& c : data.triangles)
        corners_.push_back(
            {data.positions[c[0].v], data.positions[c[1].v], data.positions[c[2].v]});
}

// [smooth-normals-apply]
void SmoothNormals::apply(const Ray& ray, Hit& hit) const {
    const Instance* instance = hit.instance;
    const auto* mesh = instance ? dynamic_cast<const SmoothMesh*>(instance->shape) : nullptr;
    if (!mesh) return;
    // The hit in object space, where the corners and their normals live; computed from the
    // object-space ray, as the triangle test computed it.
    const Vec3 o = transformPoint(instance->worldToObject, ray.o);
    const Vec3 d = transformVector(instance->worldToObject, ray.d);
    const Vec3 p = o + hit.t * d;
    const auto& v = mesh->corners(hit.primitive);
    const std::array<double, 3> b = barycentrics(p, v);
    // Turn the corner normals (stored on the winding's side) to the side the ray comes from.
    const Vec3 ngObject = faceNormal(v[0], v[1], v[2]);
    const double side = glm::dot(d, ngObject) < 0.0 ? 1.0 : -1.0;
    const auto& stored = mesh->normals(hit.primitive);
    const std::array<Vec3, 3> n{side * stored[0], side * stored[1], side * stored[2]};
    const Vec3 nsObject = interpolateNormal(b, n, side * ngObject);
    // To world space, then keep the mirror ray above the flat surface.
    const Vec3 wo = -glm::normalize(ray.d);
    const Vec3 ng = faceForward(hit.ng, wo);
    Vec3 ns = glm::normalize(instance->normalToWorld * nsObject);
    if (!(glm::dot(ns, ng) > 0.0)) ns = ng;  // a shear so strong it tipped ns over: stay flat
    hit.ns = adaptShadingNormal(wo, ng, ns);
    // Start shadow rays from the curved surface, not the flat facet.
    const bool fix = terminator_ == Terminator::Always ||
                     (terminator_ == Terminator::PerMesh && mesh->options().terminatorFix);
    if (fix) hit.shadowOffset = Mat3(instance->objectToWorld) * terminatorOffset(p, b, v, n);
}
// [smooth-normals-apply]

namespace {

// [smooth-install]
void installSmoothMesh(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // --terminator=offset|none overrides every mesh's own choice.
    const std::string option = context.cliOption("terminator");
    SmoothNormals::Terminator terminator = SmoothNormals::Terminator::PerMesh;
    if (option == "offset")
        terminator = SmoothNormals::Terminator::Always;
    else if (option == "none")
        terminator = SmoothNormals::Terminator::Never;
    else if (!option.empty())
        throw InputError("--terminator: expected 'offset' or 'none', got '" + option + "'");
    // A scene without smooth meshes pays nothing: no shading-normal step at all.
    for (const Instance& i : context.instances)
        if (dynamic_cast<const SmoothMesh*>(i.shape)) {
            pipeline.normals.push_back(std::make_shared<SmoothNormals>(terminator));
            return;
        }
}
// [smooth-install]

}  // namespace

Feature smoothMeshFeature() {
    return {"smooth_mesh",
            9,
            "smooth meshes: interpolated vertex normals, crease angle, terminator fix",
            true,
            bindSmoothMesh,
            installSmoothMesh,
            {{"terminator", "offset|none",
              "where smooth meshes' shadow rays start: the curved surface, or the flat facet",
              "each mesh's own (gr.smooth_mesh's terminator), else offset"}}};
}

}  // namespace rb
