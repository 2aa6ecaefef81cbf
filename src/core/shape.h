/// \file
/// Shape: the extension point for geometry. A shape lives in its own object space.
#pragma once

#include <array>
#include <vector>

#include "core/aabb.h"
#include "core/hit.h"

namespace rb {

class Mesh;

/// Geometry in object space. Chapters add kinds (mesh, CSG, cylinder, cone) by deriving.
class Shape {
  public:
    virtual ~Shape() = default;
    /// The closest hit with t in (0, tMax), written to hit; false when there is none.
    virtual bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const = 0;
    /// Any hit with t in (0, tMax): the shadow-ray query. Defaults to intersect().
    virtual bool occluded(const Ray& ray, double tMax) const {
        ObjectHit unused;
        return intersect(ray, tMax, unused);
    }
    /// Every crossing of the ray's whole line (any t, also t ≤ 0) as object-space hits sorted
    /// by t, for a shape a line crosses at most twice; returns how many, or −1 when the shape
    /// does not list them. Chapter 14's CSG lists an operand's crossings with it (chapter 15's
    /// cylinders and cones) and marches through other shapes with intersect().
    virtual int allHits(const Ray& ray, std::array<ObjectHit, 2>& out) const {
        (void)ray;
        (void)out;
        return -1;
    }
    /// True when no line crosses the surface more than twice (a sphere, a box): chapter 17
    /// stops looking for a medium boundary's crossings once a ray has left it.
    virtual bool convex() const { return false; }
    /// How deep object-space point p lies inside the shape: a distance within which no point
    /// of its surface lies (0 outside, or where the shape cannot say). Chapter 17's walks
    /// through a dense medium need no intersection for a flight shorter than this.
    virtual double depthInside(const Vec3& p) const {
        (void)p;
        return 0.0;
    }
    /// The shape's own surface coordinates at object-space point p on part `primitive` (the
    /// uv its hits carry), with the derivatives dp/du and dp/dv; false when it has none of its
    /// own. Chapter 10's 'surface' mapping reads them for shapes it does not know (chapter 15's
    /// cylinders and cones); the core's shapes and meshes it maps itself.
    virtual bool surfaceCoordinates(const Vec3& p, std::uint32_t primitive, Vec2& uv, Vec3& dpdu,
                                    Vec3& dpdv) const {
        (void)p, (void)primitive, (void)uv, (void)dpdu, (void)dpdv;
        return false;
    }
    /// Object-space bounds.
    virtual AABB bounds() const = 0;
    /// Append the materials the shape carries itself (chapter 14's CSG operands); most
    /// shapes carry none and take their instance's.
    virtual void materials(std::vector<const Material*>& out) const { (void)out; }
    /// The feature (chapter module) that provides this kind of shape, or null for the core's.
    /// When that feature is switched off, the scene's instances of the shape are not drawn.
    virtual const char* feature() const { return nullptr; }
    /// The triangle mesh this shape intersects (itself, or the one it wraps), for --stats;
    /// null for the other shapes.
    virtual const Mesh* triangleMesh() const { return nullptr; }
};

}  // namespace rb
