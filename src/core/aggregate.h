/// \file
/// Aggregate: the extension point that finds the closest instance along a ray.
/// Chapter 1 tests every instance (LinearAggregate); chapter 3 adds a BVH.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/instance.h"

namespace rb {

/// A set of instances that answers closest-hit and any-hit queries.
class Aggregate {
  public:
    virtual ~Aggregate() = default;
    /// The closest hit with t in (0, tMax); false if none.
    virtual bool intersect(const Ray& ray, double tMax, Hit& hit) const = 0;
    /// True if anything lies along the ray with t in (0, tMax): the shadow query.
    virtual bool occluded(const Ray& ray, double tMax) const = 0;
    /// One line for --stats about the structure (empty when there is nothing to say).
    virtual std::string statistics() const { return ""; }
};

/// Builds an aggregate over a list of instances (which outlive it).
using AggregateBuilder = std::unique_ptr<Aggregate> (*)(const std::vector<Instance>& instances);

/// Brute force: test every instance. The reference that faster aggregates are tested against.
class LinearAggregate final : public Aggregate {
  public:
    explicit LinearAggregate(const std::vector<Instance>& instances) : instances_(instances) {}
    bool intersect(const Ray& ray, double tMax, Hit& hit) const override;
    bool occluded(const Ray& ray, double tMax) const override;

  private:
    const std::vector<Instance>& instances_;
};

/// An AggregateBuilder for LinearAggregate.
std::unique_ptr<Aggregate> buildLinearAggregate(const std::vector<Instance>& instances);

}  // namespace rb
