#include "core/scene_graph.h"

#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include "core/error.h"

namespace rb {

namespace {

bool reachesVisited(const SceneNode& from, const SceneNode* to,
                    std::unordered_set<const SceneNode*>& seen) {
    if (&from == to) return true;
    if (!seen.insert(&from).second) return false;  // explored already
    for (const auto& child : from.children)
        if (reachesVisited(*child, to, seen)) return true;
    return false;
}

/// The number of root-to-node paths under `node` (capped), each node counted once.
double countPaths(const SceneNode& node, std::unordered_map<const SceneNode*, double>& memo) {
    auto it = memo.find(&node);
    if (it != memo.end()) return it->second;
    double paths = 1.0;
    for (const auto& child : node.children) paths += countPaths(*child, memo);
    paths = std::min(paths, 1e300);
    memo[&node] = paths;
    return paths;
}

}  // namespace

bool reaches(const SceneNode& from, const SceneNode* to) {
    std::unordered_set<const SceneNode*> seen;
    return reachesVisited(from, to, seen);
}

namespace {

// [flatten]
void flattenNode(const SceneNode& node, const Mat4& parentToWorld, const Material* inherited,
                 std::vector<Instance>& out) {
    // Compose: the node's transform applies first, then everything above it.
    const Mat4 toWorld = parentToWorld * node.transform;
    const Material* material = node.material ? node.material.get() : inherited;
    if (node.shape) {
        const double det = glm::determinant(Mat3(toWorld));
        if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
            throw InputError("node '" + node.name + "' has a singular or non-finite transform");
        Instance instance;
        instance.shape = node.shape.get();
        instance.material = material;
        instance.name = node.name;
        instance.setTransform(toWorld * node.shapeTransform);
        out.push_back(instance);
    }
    for (const auto& child : node.children) flattenNode(*child, toWorld, material, out);
}
// [flatten]

}  // namespace

std::vector<Instance> flatten(const SceneNode& root, const Material* fallback) {
    std::vector<Instance> instances;
    // A DAG can hold exponentially many paths: count them first (linear time, memoised) and
    // refuse before allocating anything.
    std::unordered_map<const SceneNode*, double> memo;
    const double paths = countPaths(root, memo);
    if (paths > static_cast<double>(kMaxInstances)) {
        char count[32];
        std::snprintf(count, sizeof count, "%.3g", paths);
        throw InputError(std::string("the scene graph has ") + count +
                         " node paths, more than the limit of " + std::to_string(kMaxInstances) +
                         " (a DAG that doubles at every level?)");
    }
    flattenNode(root, Mat4(1.0), fallback, instances);
    return instances;
}

}  // namespace rb
