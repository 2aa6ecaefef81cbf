/// \file
/// The top level of the two-level BVH: a BVH over instances (chapter 3).
#pragma once

#include "bvh/bvh.h"
#include "core/aggregate.h"
#include "core/feature.h"

namespace rb {

/// Chapter 3: triangle meshes and the two-level BVH.
Feature bvhFeature();

/// Top levels of at most this many instances are binary trees whatever the layout asked for:
/// for a handful of instances, preparing the ray for a wide node costs more than the one-box
/// tests it replaces (chapter 3, "Two levels and instancing", has the measurements).
inline constexpr size_t kBinaryTopLevel = 8;

/// An instance whose world box has at least this many times the surface area of the box
/// around all the others is kept out of the tree and tested by every ray (a ground plane made
/// of a box 10⁵ wide): nearly every ray that reaches the scene enters its box anyway, and in
/// the tree its box would enclose, and so open, every node above it (chapter 3, "Two levels
/// and instancing").
inline constexpr double kLargeInstanceArea = 4.0;
/// At most this many instances are kept out of the tree.
inline constexpr size_t kMaxLargeInstances = 2;
/// When at most this many instances are left after the large ones, they get no tree: each is
/// tested behind its own box, as the large ones are (a mesh on a ground plane: chapter 3, "Two
/// levels and instancing").
inline constexpr size_t kFlatTopLevel = 2;

/// A BVH over instances' world bounds; each instance then uses its shape's own structure. The
/// tree has the layout asked for, unless there are at most `binaryUpTo` instances; the meshes'
/// trees are theirs (built when the scene is read). Large instances (kLargeInstanceArea) are
/// tested before the tree, outside it, and so are the others when at most `flatUpTo` are left
/// (then there is no tree).
class BVHAggregate final : public Aggregate {
  public:
    explicit BVHAggregate(const std::vector<Instance>& instances,
                          BVHLayout layout = bestWideLayout(), size_t binaryUpTo = kBinaryTopLevel,
                          size_t flatUpTo = kFlatTopLevel);
    bool intersect(const Ray& ray, double tMax, Hit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;
    /// Nodes and bytes of both levels, and bytes per triangle of the meshes.
    std::string statistics() const override;
    const BVH& bvh() const { return bvh_; }
    /// How many large instances are tested outside the tree (kLargeInstanceArea).
    size_t largeInstanceCount() const { return largeCount_; }
    /// How many instances are tested outside the tree: the large ones, and the few others
    /// when there is no tree (kFlatTopLevel).
    size_t outsideCount() const { return outside_.size(); }

  private:
    /// The closest hit among `instances` nearer than tClosest: shrinks tClosest and sets `best`
    /// and `closest`; of two at the same t, the one first in the scene wins, in any test order.
    bool closestAmong(const Instance* const* instances, std::uint32_t count, const Ray& ray,
                      double& tClosest, ObjectHit& best, const Instance*& closest) const;

    /// Instances outside the tree, tested first: the large ones, largest first, then the
    /// others when there are at most kFlatTopLevel of them.
    std::vector<const Instance*> outside_;
    size_t largeCount_ = 0;                 ///< How many of outside_ are large.
    std::vector<const Instance*> ordered_;  ///< The others, in BVH leaf order.
    BVH bvh_;
    BVHLayout asked_;  ///< The layout asked for (--bvh), which --stats names.
};

/// An AggregateBuilder for BVHAggregate with the widest layout this CPU runs (--bvh=wide).
std::unique_ptr<Aggregate> buildBVHAggregate(const std::vector<Instance>& instances);
/// An AggregateBuilder for BVHAggregate with the lesson's binary traversal (--bvh=binary).
std::unique_ptr<Aggregate> buildBinaryBVHAggregate(const std::vector<Instance>& instances);
/// An AggregateBuilder for BVHAggregate with four-wide SSE nodes (--bvh=wide4).
std::unique_ptr<Aggregate> buildWide4BVHAggregate(const std::vector<Instance>& instances);
/// An AggregateBuilder for BVHAggregate with eight-wide AVX2 nodes (--bvh=wide8).
std::unique_ptr<Aggregate> buildWide8BVHAggregate(const std::vector<Instance>& instances);

}  // namespace rb
