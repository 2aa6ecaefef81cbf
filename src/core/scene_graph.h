/// \file
/// The A4 scene graph: nodes with transforms and children (a DAG), and its flattening.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/instance.h"
#include "core/light.h"

namespace rb {

struct Medium;

/// Makes one shape out of a node's children (chapter 14's CSG): the extension point for
/// shapes whose parts are whole subgraphs. Flattening gives it each child's leaves, placed in
/// the node's own space, and the node becomes one instance of the shape it returns.
class CompoundShape {
  public:
    virtual ~CompoundShape() = default;
    /// The shape made of the children; operands[k] holds child k's leaves.
    virtual std::shared_ptr<const Shape> build(
        const std::vector<std::vector<Instance>>& operands) const = 0;
    /// The feature that provides it: when that feature is off, the node is a plain group.
    virtual const char* feature() const = 0;
    /// Why the shape is surely empty, given which children have shapes under them ("" when it
    /// need not be): a render warning, since an empty solid draws nothing without an error.
    virtual std::string whyEmpty(const std::vector<bool>& childHasShapes) const {
        (void)childHasShapes;
        return "";
    }
};

/// A node of the scene graph. A group (gr.node, gr.joint) only transforms its children; a
/// geometry node also holds a shape and a material. One node may have several parents.
struct SceneNode {
    std::string name;
    Mat4 transform{1.0};  ///< Local-to-parent transform.
    /// Placement of the shape alone, applied before `transform` and not to the children:
    /// gr.nh_sphere's centre and radius, gr.nh_box's corner and size.
    Mat4 shapeTransform{1.0};
    std::shared_ptr<const Shape> shape;        ///< Null for group nodes.
    std::shared_ptr<const Material> material;  ///< Null until set_material.
    std::vector<std::shared_ptr<SceneNode>> children;
    /// Non-null for a node whose children are the parts of one shape (a CSG node).
    std::shared_ptr<const CompoundShape> compound;
    /// Chapter 17's node:set_medium: the medium filling the inside of this node's closed
    /// shape, or null. Without a material of its own the shape only bounds the medium.
    std::shared_ptr<const Medium> medium;

    /// Releases the children without recursing once per level, so that dropping a chain of a
    /// million nested nodes cannot overflow the stack.
    ~SceneNode();
    SceneNode() = default;
    SceneNode(const SceneNode&) = default;             ///< gr.render's snapshot copies nodes.
    SceneNode& operator=(const SceneNode&) = default;  ///< As the copy.
};

/// True when `to` can be reached from `from` along child links (used to refuse cycles).
/// Visits each node once, so it stays linear however much the DAG shares; `visited`, when
/// given, receives how many nodes it looked at (the caller charges that work to the script).
bool reaches(const SceneNode& from, const SceneNode* to, size_t* visited = nullptr);

/// The most levels a scene graph may have (root to deepest leaf): flattening and copying it
/// recurse once per level. Real scenes stay far below; a chain built in a loop does not.
inline constexpr size_t kMaxGraphDepth = 1000;

/// The number of levels under root (1 for a leaf), without recursion; visits each node once.
size_t graphDepth(const SceneNode& root);

/// Throw InputError when the graph under root is deeper than kMaxGraphDepth.
void checkGraphDepth(const SceneNode& root);

/// The most instances (and node paths) a scene may flatten to, so that a DAG that doubles
/// at every level fails cleanly instead of exhausting memory: 2 million instances take
/// about 1 GB.
inline constexpr size_t kMaxInstances = 2'000'000;

/// Flatten the graph under root into world-space instances. Transforms compose as
/// parent · child. A node without a material inherits the nearest ancestor's; with none at
/// all it gets `fallback`. Throws InputError on a singular transform or too many instances.
/// A compound node whose feature is in `featuresOn` becomes one instance of the shape its
/// children make, kept alive in `built`; without `built`, or with the feature off, it is a
/// plain group. An operand of a built compound whose shape's feature is not in `featuresOn` is
/// left out of it, and counted by feature in `leftOut` (when given).
std::vector<Instance> flatten(const SceneNode& root, const Material* fallback,
                              std::vector<std::shared_ptr<const Shape>>* built = nullptr,
                              const std::set<std::string>& featuresOn = {},
                              std::map<std::string, size_t>* leftOut = nullptr);

/// One gr.render call: everything needed to render one image.
struct RenderJob {
    std::shared_ptr<SceneNode> root;
    std::string output;  ///< PNG path, relative to the working directory.
    int width = 0, height = 0;
    CameraSpec camera;
    Colour ambient{0.0};
    std::vector<PointLight> lights;
    std::string where;                      ///< "scene.lua:42", for messages about this job.
    std::map<std::string, double> options;  ///< Dialect extras (seed 001's aa, ss, dist, ...).
    std::shared_ptr<const Medium> fog;      ///< Chapter 17's gr.fog: fills all space, or null.
};

/// A render request after the script ran: the job plus the world it renders.
struct LoadedRender {
    RenderJob job;
    std::shared_ptr<const SceneNode> snapshot;              ///< The graph as it was at gr.render.
    std::vector<Instance> instances;                        ///< Flattened from the snapshot.
    std::shared_ptr<const Material> fallback;               ///< For instances without a material.
    std::vector<std::shared_ptr<const Shape>> builtShapes;  ///< Made while flattening (CSG).
    /// Compound operands left out because their feature is off, by feature.
    std::map<std::string, size_t> leftOutOperands;
};

}  // namespace rb
