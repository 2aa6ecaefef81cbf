#include "core/scene_graph.h"

#include <algorithm>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include "core/error.h"

namespace rb {

namespace {

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

SceneNode::~SceneNode() {
    // Take over the children whose last owner this is, level by level, with an explicit list:
    // each node then dies with no children of its own left to destroy recursively.
    std::vector<std::shared_ptr<SceneNode>> pending = std::move(children);
    while (!pending.empty()) {
        std::shared_ptr<SceneNode> node = std::move(pending.back());
        pending.pop_back();
        if (node.use_count() == 1)
            for (auto& child : node->children) pending.push_back(std::move(child));
    }
}

bool reaches(const SceneNode& from, const SceneNode* to, size_t* visited) {
    // Depth-first with an explicit stack: a recursive walk would overflow on a deep chain.
    std::unordered_set<const SceneNode*> seen;
    std::vector<const SceneNode*> stack = {&from};
    bool found = false;
    while (!stack.empty() && !found) {
        const SceneNode* node = stack.back();
        stack.pop_back();
        found = node == to;
        if (!seen.insert(node).second) continue;  // explored already
        for (const auto& child : node->children) stack.push_back(child.get());
    }
    if (visited) *visited = seen.size();
    return found;
}

size_t graphDepth(const SceneNode& root) {
    // Post-order with an explicit stack of (node, next child); each node's height once.
    std::unordered_map<const SceneNode*, size_t> height;
    std::vector<std::pair<const SceneNode*, size_t>> stack = {{&root, 0}};
    while (!stack.empty()) {
        const SceneNode* node = stack.back().first;
        const size_t next = stack.back().second++;
        if (next < node->children.size()) {
            const SceneNode* child = node->children[next].get();
            if (!height.count(child)) stack.push_back({child, 0});
            continue;
        }
        size_t levels = 1;
        for (const auto& child : node->children)
            levels = std::max(levels, 1 + height.at(child.get()));
        height[node] = levels;
        stack.pop_back();
    }
    return height.at(&root);
}

void checkGraphDepth(const SceneNode& root) {
    const size_t depth = graphDepth(root);
    if (depth > kMaxGraphDepth)
        throw InputError("the scene graph under '" + root.name + "' is " + std::to_string(depth) +
                         " levels deep, more than the limit of " + std::to_string(kMaxGraphDepth) +
                         " (a chain of nodes built in a loop?)");
}

namespace {

/// Where compound nodes go while flattening: the shapes built, and the features that are on.
struct CompoundContext {
    std::vector<std::shared_ptr<const Shape>>* built;
    const std::set<std::string>& featuresOn;
    std::map<std::string, size_t>* leftOut;  ///< Operands left out, by feature, or null.
    int* media;                              ///< Medium nodes met so far (chapter 17).
};

// [flatten]
void flattenNode(const SceneNode& node, const Mat4& parentToWorld, const Material* inherited,
                 const CompoundContext& compounds, std::vector<Instance>& out,
                 int mediumAbove = -1) {
    // Compose: the node's transform applies first, then everything above it.
    const Mat4 toWorld = parentToWorld * node.transform;
    const Material* material = node.material ? node.material.get() : inherited;
    // A compound node (CSG) turns its children into one shape, placed in the node's space.
    std::shared_ptr<const Shape> compoundShape;
    if (node.compound && compounds.built && compounds.featuresOn.count(node.compound->feature())) {
        std::vector<std::vector<Instance>> operands(node.children.size());
        for (size_t k = 0; k < node.children.size(); ++k) {
            flattenNode(*node.children[k], Mat4(1.0), material, compounds, operands[k]);
            // An operand whose shape's chapter is switched off is left out, as it would be
            // outside the compound (a cylinder under --features=all,-quadrics).
            std::erase_if(operands[k], [&](const Instance& i) {
                const char* feature = i.shape->feature();
                if (!feature || compounds.featuresOn.count(feature)) return false;
                if (compounds.leftOut) ++(*compounds.leftOut)[feature];
                return true;
            });
        }
        compoundShape = node.compound->build(operands);
        compounds.built->push_back(compoundShape);
    }
    const Shape* shape = compoundShape ? compoundShape.get() : node.shape.get();
    if (shape) {
        const double det = glm::determinant(Mat3(toWorld));
        if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
            throw InputError("node '" + node.name + "' has a singular or non-finite transform");
        Instance instance;
        instance.shape = shape;
        instance.material = material;
        instance.name = node.name;
        instance.setTransform(toWorld * node.shapeTransform);
        // A medium node (chapter 17) bounds its medium; the media under it nest in it.
        if (node.medium) {
            instance.medium = node.medium.get();
            instance.mediumBoundaryOnly = !node.material;
            instance.mediumPlacement = &node.shapeTransform;
            instance.mediumParent = mediumAbove;
            instance.mediumIndex = mediumAbove = (*compounds.media)++;
        }
        out.push_back(instance);
    }
    if (compoundShape) return;
    for (const auto& child : node.children)
        flattenNode(*child, toWorld, material, compounds, out, mediumAbove);
}
// [flatten]

}  // namespace

std::vector<Instance> flatten(const SceneNode& root, const Material* fallback,
                              std::vector<std::shared_ptr<const Shape>>* built,
                              const std::set<std::string>& featuresOn,
                              std::map<std::string, size_t>* leftOut) {
    std::vector<Instance> instances;
    // Both walks below recurse once per level.
    checkGraphDepth(root);
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
    int media = 0;
    flattenNode(root, Mat4(1.0), fallback, CompoundContext{built, featuresOn, leftOut, &media},
                instances);
    return instances;
}

}  // namespace rb
