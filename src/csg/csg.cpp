#include "csg/csg.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/box.h"
#include "core/sphere.h"

namespace rb {

// [csg-rule]
bool csgInside(CsgOp op, bool insideA, bool insideB) {
    // [exercise-csg-rule]
    // Exercise 14.1, the membership rule of each operation: read ch14-membership.
    // Blank: return insideA;
    switch (op) {
        case CsgOp::Union:
            return insideA || insideB;
        case CsgOp::Intersection:
            return insideA && insideB;
        case CsgOp::Difference:
            return insideA && !insideB;
    }
    return false;
    // [exercise-csg-rule]
}
// [csg-rule]

// [csg-orient]
void orientToResult(Crossing& c, bool enteringResult) {
    // [exercise-csg-normal-flip]
    // Exercise 14.3, the normals of subtracted surfaces: read ch14-normals.
    // Blank: c.entering = enteringResult;
    // Where the result is entered as the operand is left (B's surface in A − B), the operand's
    // outward normal points into the result: turn it round.
    if (c.entering != enteringResult) c.hit.n = -c.hit.n;
    c.entering = enteringResult;
    // [exercise-csg-normal-flip]
}
// [csg-orient]

// [csg-combine]
void combineCrossings(CsgOp op, const CrossingList& a, const CrossingList& b, CrossingList& out) {
    out.clear();
    // [exercise-csg-combine]
    // Exercise 14.4, merging two lists of crossings into the result's: read ch14-intervals.
    // Blank: for (size_t i = 0; i < a.size(); ++i) out.push(a[i]);
    // Walk both lists in t order from t = −∞, where the line is outside both solids.
    bool insideA = false, insideB = false, inside = false;
    size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        // The next place along the line, and every crossing within rounding of it: coplanar
        // faces of A and B change both states at once, and only the net change is a surface.
        const double t = std::min(i < a.size() ? a[i].hit.t : b[j].hit.t,
                                  j < b.size() ? b[j].hit.t : a[i].hit.t);
        const double tolerance = kCoincident * std::abs(t);
        const bool wasInside = inside, wasInsideA = insideA;
        const Crossing* candidates[2] = {nullptr, nullptr};  // the first of A and of B here
        for (; i < a.size() && a[i].hit.t <= t + tolerance; ++i) {
            insideA = a[i].entering;
            if (!candidates[0]) candidates[0] = &a[i];
        }
        for (; j < b.size() && b[j].hit.t <= t + tolerance; ++j) {
            insideB = b[j].entering;
            if (!candidates[1]) candidates[1] = &b[j];
        }
        inside = csgInside(op, insideA, insideB);
        if (inside == wasInside) continue;  // an inner surface: not on the result's boundary
        // The surface here is A's wherever A's state changes: on a tie A's wins, and B's is
        // kept only where B alone changes the result (ch14-ties).
        const Crossing* surface = insideA != wasInsideA ? candidates[0] : candidates[1];
        Crossing c = *surface;
        orientToResult(c, inside);
        out.push(c);
    }
    // [exercise-csg-combine]
}
// [csg-combine]

// [csg-sphere-crossings]
void sphereCrossings(const Ray& ray, CrossingList& out) {
    // [exercise-csg-sphere-crossings]
    // Exercise 14.2, both crossings of the unit sphere: read ch14-intervals.
    // Blank: (void)ray; (void)out;
    if (isDegenerateDirection(ray.d)) return;
    // The quadratic |o + t·d|² = 1 of the unit sphere, as in chapter 1, keeping both roots.
    const double a = glm::dot(ray.d, ray.d);
    const double h = glm::dot(ray.o, ray.d);
    const double c = glm::dot(ray.o, ray.o) - 1.0;
    const Vec3 f = ray.o - (h / a) * ray.d;
    double t0, t1;
    // A tangent line (t0 = t1) touches the solid without entering it.
    if (!solveQuadraticHalfB(a, h, c, f, t0, t1) || !(t0 < t1)) return;
    for (int k = 0; k < 2; ++k) {
        Crossing x;
        x.hit.t = k == 0 ? t0 : t1;
        x.hit.n = ray.o + x.hit.t * ray.d;  // the point is its own outward normal
        x.entering = k == 0;
        out.push(x);
    }
    // [exercise-csg-sphere-crossings]
}
// [csg-sphere-crossings]

void boxCrossings(const Ray& ray, CrossingList& out) {
    if (isDegenerateDirection(ray.d)) return;
    // Chapter 1's slab test over the whole line: the latest entry and the earliest exit.
    double tEnter = -std::numeric_limits<double>::infinity();
    double tExit = std::numeric_limits<double>::infinity();
    int enterAxis = -1, exitAxis = -1;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.o[axis], d = ray.d[axis];
        if (d == 0.0) {
            if (o < 0.0 || o > 1.0) return;  // parallel to the slab and outside it
            continue;
        }
        double tNear = (0.0 - o) / d, tFar = (1.0 - o) / d;
        if (tNear > tFar) std::swap(tNear, tFar);
        if (tNear > tEnter) tEnter = tNear, enterAxis = axis;
        if (tFar < tExit) tExit = tFar, exitAxis = axis;
    }
    // An empty or single-point interval (an edge or a corner grazed) is no solid.
    if (!(tEnter < tExit) || enterAxis < 0 || exitAxis < 0) return;
    const double ts[2] = {tEnter, tExit};
    const int axes[2] = {enterAxis, exitAxis};
    for (int k = 0; k < 2; ++k) {
        Crossing x;
        const Vec3 p = ray.o + ts[k] * ray.d;
        x.hit.t = ts[k];
        x.hit.n = Vec3(0.0);
        x.hit.n[axes[k]] = p[axes[k]] > 0.5 ? 1.0 : -1.0;
        x.hit.uv = Vec2(p[(axes[k] + 1) % 3], p[(axes[k] + 2) % 3]);
        x.hit.primitive = static_cast<std::uint32_t>(axes[k]);
        x.entering = k == 0;
        out.push(x);
    }
}

namespace {

/// The part [t0, t1] of the whole line inside box b; false when the line misses it.
bool lineThroughBox(const AABB& b, const Ray& ray, double& t0, double& t1) {
    t0 = -std::numeric_limits<double>::infinity();
    t1 = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.o[axis], d = ray.d[axis];
        if (d == 0.0) {
            if (o < b.lo[axis] || o > b.hi[axis]) return false;
            continue;
        }
        double tNear = (b.lo[axis] - o) / d, tFar = (b.hi[axis] - o) / d;
        if (tNear > tFar) std::swap(tNear, tFar);
        t0 = std::max(t0, tNear);
        t1 = std::min(t1, tFar);
    }
    return t0 <= t1 && std::isfinite(t0) && std::isfinite(t1);
}

/// The most crossings marching looks for along one line (a mesh is rarely this folded).
constexpr int kMaxMarchedCrossings = 1024;

}  // namespace

void listedCrossings(const Ray& ray, const std::array<ObjectHit, 2>& hits, int n,
                     CrossingList& out) {
    bool inside = false;
    for (int k = 0; k < n; ++k) {
        // As in marching: parity says in or out, and the normal points out of the solid.
        inside = !inside;
        Crossing x{hits[k], inside};
        if ((glm::dot(x.hit.n, ray.d) < 0.0) != inside) x.hit.n = -x.hit.n;
        out.push(x);
    }
    if (inside) out.pop();
}

void marchedCrossings(const Shape& shape, const Ray& ray, CrossingList& out) {
    if (isDegenerateDirection(ray.d)) return;
    // Start just before the line enters the shape's bounds, where it is surely outside.
    double tEnter, tExit;
    if (!lineThroughBox(shape.bounds(), ray, tEnter, tExit)) return;
    const double margin = 1e-6 * (tExit - tEnter) + 1e-300;
    // After each hit, start again a little past it: far enough that rounding cannot find the
    // same surface again (a triangle edge reported by both neighbours counts once), near
    // enough to keep any real neighbouring surface.
    const double step =
        kOffsetScale * std::max({std::abs(tEnter), std::abs(tExit), tExit - tEnter});
    double t = tEnter - margin;
    bool inside = false;
    for (int k = 0; k < kMaxMarchedCrossings; ++k) {
        const Ray from{ray.o + t * ray.d, ray.d};
        ObjectHit h;
        if (!shape.intersect(from, tExit + margin - t, h)) break;
        // Crossings of a closed surface alternate: the parity says in or out, whichever way
        // the surface happens to be wound.
        inside = !inside;
        Crossing x{h, inside};
        x.hit.t = t + h.t;
        if ((glm::dot(x.hit.n, ray.d) < 0.0) != inside) x.hit.n = -x.hit.n;
        out.push(x);
        t = x.hit.t + step;
    }
    // An odd count means an open surface or a silhouette grazed once: drop the unpaired one.
    if (inside) out.pop();
}

CsgLeaf CsgLeaf::from(const Instance& instance) {
    CsgLeaf leaf;
    leaf.shape = instance.shape;
    leaf.material = instance.material;
    leaf.fromCsg = instance.worldToObject;
    leaf.normalToCsg = instance.normalToWorld;
    leaf.bounds = instance.worldBounds;
    // Choose how to list crossings once, here, not on every ray.
    if (dynamic_cast<const Sphere*>(leaf.shape))
        leaf.kind = Kind::Sphere;
    else if (dynamic_cast<const Box*>(leaf.shape))
        leaf.kind = Kind::Box;
    else if (dynamic_cast<const CsgShape*>(leaf.shape))
        leaf.kind = Kind::Csg;
    else
        leaf.kind = Kind::Other;
    return leaf;
}

void CsgLeaf::crossings(const Ray& ray, CrossingList& out) const {
    out.clear();
    if (kind == Kind::Empty) return;
    // Skip the work when the line misses the leaf's bounds.
    double t0, t1;
    if (!lineThroughBox(bounds, ray, t0, t1)) return;
    // Into the leaf's space unnormalised, so t stays the same.
    const Ray local{transformPoint(fromCsg, ray.o), transformVector(fromCsg, ray.d)};
    switch (kind) {
        case Kind::Sphere:
            sphereCrossings(local, out);
            break;
        case Kind::Box:
            boxCrossings(local, out);
            break;
        case Kind::Csg:
            static_cast<const CsgShape*>(shape)->crossings(local, out);
            break;
        case Kind::Other: {
            // A shape that lists its crossings (a cylinder or cone) is asked once; any other
            // is marched through with its closest hit.
            std::array<ObjectHit, 2> hits;
            const int n = isDegenerateDirection(local.d) ? 0 : shape->allHits(local, hits);
            if (n >= 0)
                listedCrossings(local, hits, n, out);
            else
                marchedCrossings(*shape, local, out);
            break;
        }
        case Kind::Empty:
            break;
    }
    // Normals back to CSG space; the leaf's material where the part has none of its own.
    for (size_t i = 0; i < out.size(); ++i) {
        Crossing& c = out[i];
        c.hit.n = normalToCsg * c.hit.n;
        if (!c.hit.material) c.hit.material = material;
    }
}

CsgShape::CsgShape(CsgOp op, CsgLeaf a, CsgLeaf b, std::vector<std::shared_ptr<const Shape>> owned)
    : op_(op), a_(std::move(a)), b_(std::move(b)), owned_(std::move(owned)) {
    // The result lies inside A ∪ B, inside A ∩ B, or inside A.
    const AABB boundsA = a_.kind == CsgLeaf::Kind::Empty ? AABB{} : a_.bounds;
    const AABB boundsB = b_.kind == CsgLeaf::Kind::Empty ? AABB{} : b_.bounds;
    switch (op_) {
        case CsgOp::Union:
            bounds_ = boundsA;
            bounds_.extend(boundsB);
            break;
        case CsgOp::Intersection:
            bounds_ = AABB{glm::max(boundsA.lo, boundsB.lo), glm::min(boundsA.hi, boundsB.hi)};
            break;
        case CsgOp::Difference:
            bounds_ = boundsA;
            break;
    }
    // An empty result still needs finite bounds for the BVH: a point no ray can hit.
    if (bounds_.lo.x > bounds_.hi.x || bounds_.lo.y > bounds_.hi.y || bounds_.lo.z > bounds_.hi.z)
        bounds_ = AABB{Vec3(0.0), Vec3(0.0)};
}

void CsgShape::crossings(const Ray& ray, CrossingList& out) const {
    out.clear();
    CrossingList a, b;
    a_.crossings(ray, a);
    // Nothing of A leaves nothing of A ∩ B and A − B.
    if (a.empty() && op_ != CsgOp::Union) return;
    b_.crossings(ray, b);
    combineCrossings(op_, a, b, out);
}

bool CsgShape::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    CrossingList all;
    crossings(ray, all);
    // The first crossing of the result ahead of the origin.
    for (size_t i = 0; i < all.size(); ++i) {
        if (all[i].hit.t <= 0.0) continue;
        if (all[i].hit.t >= tMax) return false;
        hit = all[i].hit;
        return true;
    }
    return false;
}

bool CsgShape::occluded(const Ray& ray, double tMax) const {
    // The result is one solid: only its own boundary casts shadows.
    ObjectHit unused;
    return intersect(ray, tMax, unused);
}

void CsgShape::materials(std::vector<const Material*>& out) const {
    for (const CsgLeaf* leaf : {&a_, &b_}) {
        if (leaf->material) out.push_back(leaf->material);
        if (leaf->shape) leaf->shape->materials(out);
    }
}

namespace {

/// One operand from a child's leaves: the leaf itself, or the union of several (a
/// hierarchical operand), built as a balanced tree so its depth grows as log₂ of its leaves.
CsgLeaf operandLeaf(const std::vector<Instance>& leaves, size_t begin, size_t end,
                    std::vector<std::shared_ptr<const Shape>>& owned) {
    if (begin == end) return CsgLeaf{};
    if (end - begin == 1) return CsgLeaf::from(leaves[begin]);
    const size_t middle = begin + (end - begin) / 2;
    CsgLeaf left = operandLeaf(leaves, begin, middle, owned);
    CsgLeaf right = operandLeaf(leaves, middle, end, owned);
    auto part = std::make_shared<const CsgShape>(CsgOp::Union, left, right);
    owned.push_back(part);
    // The union sits in CSG space already; its leaves keep their own materials.
    CsgLeaf leaf;
    leaf.kind = CsgLeaf::Kind::Csg;
    leaf.shape = part.get();
    leaf.bounds = part->bounds();
    return leaf;
}

}  // namespace

std::shared_ptr<const Shape> CsgCompound::build(
    const std::vector<std::vector<Instance>>& operands) const {
    std::vector<std::shared_ptr<const Shape>> owned;
    const std::vector<Instance> none;
    const auto& a = operands.size() > 0 ? operands[0] : none;
    const auto& b = operands.size() > 1 ? operands[1] : none;
    CsgLeaf leafA = operandLeaf(a, 0, a.size(), owned);
    CsgLeaf leafB = operandLeaf(b, 0, b.size(), owned);
    return std::make_shared<const CsgShape>(op_, std::move(leafA), std::move(leafB),
                                            std::move(owned));
}

std::string CsgCompound::whyEmpty(const std::vector<bool>& childHasShapes) const {
    const bool a = childHasShapes.size() > 0 && childHasShapes[0];
    const bool b = childHasShapes.size() > 1 && childHasShapes[1];
    // A ∪ B needs one solid, A ∩ B both, A − B its first.
    if (!a && !b) return "neither operand has a shape under it";
    if (op_ == CsgOp::Intersection && !a) return "its first operand has no shape under it";
    if (op_ == CsgOp::Intersection && !b) return "its second operand has no shape under it";
    if (op_ == CsgOp::Difference && !a)
        return "its first operand, the solid subtracted from, has no shape under it";
    return "";
}

}  // namespace rb
