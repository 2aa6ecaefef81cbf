#include "core/scene_graph.h"

#include "core/error.h"

namespace rb {

bool reaches(const SceneNode& from, const SceneNode* to) {
    if (&from == to) return true;
    for (const auto& child : from.children)
        if (reaches(*child, to)) return true;
    return false;
}

namespace {

// [flatten]
void flattenNode(const SceneNode& node, const Mat4& parentToWorld, const Material* inherited,
                 std::vector<Instance>& out, size_t& visits) {
    // A DAG can hold exponentially many paths; stop before that becomes a hang.
    if (++visits > kMaxInstances)
        throw InputError("the scene graph has more than " + std::to_string(kMaxInstances) +
                         " node paths (a DAG that doubles at every level?)");
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
        instance.setTransform(toWorld);
        out.push_back(instance);
    }
    for (const auto& child : node.children) flattenNode(*child, toWorld, material, out, visits);
}
// [flatten]

}  // namespace

std::vector<Instance> flatten(const SceneNode& root, const Material* fallback) {
    std::vector<Instance> instances;
    size_t visits = 0;
    flattenNode(root, Mat4(1.0), fallback, instances, visits);
    return instances;
}

}  // namespace rb
