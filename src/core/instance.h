/// \file
/// Instance: one shape placed in the world by the product of the transforms above it.
#pragma once

#include <string>

#include "core/hit.h"
#include "core/material.h"
#include "core/shape.h"

namespace rb {

struct Medium;

/// A shape under a world transform, with its material: one leaf of the flattened scene graph.
/// The same shape may appear in many instances (A4 instancing).
struct Instance {
    const Shape* shape = nullptr;
    const Material* material = nullptr;
    Mat4 objectToWorld{1.0};
    Mat4 worldToObject{1.0};
    Mat3 normalToWorld{1.0};  ///< Inverse transpose of objectToWorld's linear part.
    AABB worldBounds;
    std::string name;
    /// Chapter 17: the medium inside this closed shape (node:set_medium), or null.
    const Medium* medium = nullptr;
    /// The instance only bounds its medium (its node has no material of its own): it is no
    /// surface, and chapter 17 takes it out of the scene's instances.
    bool mediumBoundaryOnly = false;
    /// Chapter 17: the index of the medium node above this one (the medium this one nests
    /// in, which it replaces inside), or -1; and this medium node's own index.
    int mediumParent = -1, mediumIndex = -1;
    /// Chapter 17: the node's placement of its shape alone (SceneNode::shapeTransform), so the
    /// medium's density lives in the node's space, not the shape's; null for other instances.
    const Mat4* mediumPlacement = nullptr;

    /// Set the transform and everything derived from it.
    void setTransform(const Mat4& m);

    // [instance-intersect]
    /// Closest hit with t in (0, tMax): the ray goes into object space unnormalised, so the
    /// object-space t is the world-space t.
    bool intersect(const Ray& worldRay, double tMax, ObjectHit& hit) const {
        const Ray objectRay{transformPoint(worldToObject, worldRay.o),
                            transformVector(worldToObject, worldRay.d)};
        return shape->intersect(objectRay, tMax, hit);
    }
    // [instance-intersect]
    /// Any hit with t in (0, tMax).
    bool occluded(const Ray& worldRay, double tMax) const {
        const Ray objectRay{transformPoint(worldToObject, worldRay.o),
                            transformVector(worldToObject, worldRay.d)};
        return shape->occluded(objectRay, tMax);
    }
    /// Turn an object-space hit into a world-space Hit.
    Hit toWorld(const Ray& worldRay, const ObjectHit& oh) const;
};

}  // namespace rb
