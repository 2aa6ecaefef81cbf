/// \file
/// Constructive solid geometry: union, intersection and difference of closed solids, nested
/// to any depth, each operand any node (transformed, hierarchical, a mesh, another CSG node).
#pragma once

#include <memory>
#include <vector>

#include "core/instance.h"
#include "core/scene_graph.h"
#include "csg/crossing.h"

namespace rb {

/// The three Boolean operations on solids.
enum class CsgOp { Union, Intersection, Difference };

/// Whether a point is inside `op` applied to A and B, given whether it is inside A and B.
bool csgInside(CsgOp op, bool insideA, bool insideB);

/// Point the normal of crossing c (which points out of c's own operand) out of the result,
/// whose boundary c is: flip it where the result is entered while c's operand is left (the
/// subtracted surfaces of a difference), and mark c with the result's direction.
void orientToResult(Crossing& c, bool enteringResult);

/// Relative distance below which crossings of different operands count as one place
/// (coplanar faces): |t₁ − t₂| ≤ kCoincident · max(|t₁|, |t₂|).
inline constexpr double kCoincident = 1e-9;

/// Merge the crossings of A and B along one line into those of `op`(A, B): the interval
/// algebra. Both inputs and the output are in increasing t and start outside (t = −∞).
void combineCrossings(CsgOp op, const CrossingList& a, const CrossingList& b, CrossingList& out);

/// Every crossing of the whole line o + t·d (t over all reals) with the unit sphere.
void sphereCrossings(const Ray& ray, CrossingList& out);
/// Every crossing of the whole line with the unit cube [0,1]³.
void boxCrossings(const Ray& ray, CrossingList& out);
/// The crossings of a shape that lists its own (Shape::allHits, n of them in `hits`, sorted):
/// they alternate entering, leaving; an unpaired last one (an open surface grazed) is dropped,
/// and normals are turned to point out of the solid, as marchedCrossings does.
void listedCrossings(const Ray& ray, const std::array<ObjectHit, 2>& hits, int n,
                     CrossingList& out);
/// Every crossing of the whole line with any closed shape, found by asking it for its
/// closest hit again and again from just past the previous one (meshes, later chapters'
/// shapes). Crossings alternate entering, leaving from outside the shape's bounds; normals
/// are turned to point out of the solid.
void marchedCrossings(const Shape& shape, const Ray& ray, CrossingList& out);

/// One operand of a CSG node: a closed shape placed in the node's space, with its material.
struct CsgLeaf {
    /// How the leaf lists its crossings: exactly for the shapes it knows, else with the
    /// shape's own Shape::allHits (cylinders, cones), else by marching.
    enum class Kind { Empty, Sphere, Box, Csg, Other };
    Kind kind = Kind::Empty;  ///< Empty: an operand with no shape at all.
    const Shape* shape = nullptr;
    const Material* material = nullptr;  ///< Null: the CSG node's own.
    Mat4 fromCsg{1.0};                   ///< CSG space to the leaf's object space.
    Mat3 normalToCsg{1.0};               ///< Inverse transpose of the leaf's placement.
    AABB bounds;                         ///< In CSG space.

    /// The leaf `instance` (placed in CSG space by its objectToWorld).
    static CsgLeaf from(const Instance& instance);
    /// Every crossing of the whole line `ray` (in CSG space) with the leaf, normals in CSG space.
    void crossings(const Ray& ray, CrossingList& out) const;
};

/// A CSG node's shape: op(A, B) of two leaves, in the node's object space.
class CsgShape final : public Shape {
  public:
    /// op(a, b); `owned` keeps shapes the leaves point to alive (unions made of hierarchies).
    CsgShape(CsgOp op, CsgLeaf a, CsgLeaf b, std::vector<std::shared_ptr<const Shape>> owned = {});
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;
    AABB bounds() const override { return bounds_; }
    void materials(std::vector<const Material*>& out) const override;
    /// Every crossing of the whole line with the solid, in increasing t.
    void crossings(const Ray& ray, CrossingList& out) const;
    /// The operation.
    CsgOp op() const { return op_; }

  private:
    CsgOp op_;
    CsgLeaf a_, b_;
    AABB bounds_;
    std::vector<std::shared_ptr<const Shape>> owned_;
};

/// The CSG node's recipe (SceneNode::compound): its two children become operands A and B.
class CsgCompound final : public CompoundShape {
  public:
    explicit CsgCompound(CsgOp op) : op_(op) {}
    std::shared_ptr<const Shape> build(
        const std::vector<std::vector<Instance>>& operands) const override;
    const char* feature() const override { return "csg"; }
    std::string whyEmpty(const std::vector<bool>& childHasShapes) const override;

  private:
    CsgOp op_;
};

}  // namespace rb
