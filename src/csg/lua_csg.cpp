// Chapter 14's Lua calls: gr.union, gr.intersection and gr.difference, which return new
// nodes, and seed 001's nodeA:csg(nodeB, 'u'|'n'|'d'), which turns nodeA into the result.
#include "core/error.h"
#include "csg/csg.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// A new CSG node op(a, b): its two children are the operands, whole subgraphs each.
std::shared_ptr<SceneNode> csgNode(CsgOp op, std::string name, std::shared_ptr<SceneNode> a,
                                   std::shared_ptr<SceneNode> b) {
    auto node = std::make_shared<SceneNode>();
    node->name = std::move(name);
    node->compound = std::make_shared<const CsgCompound>(op);
    node->children = {std::move(a), std::move(b)};
    return node;
}

/// gr.union(a, b [, name]) and its two siblings.
template <CsgOp Op>
int grCsg(lua_State* L) {
    static constexpr const char* kCalls[] = {"gr.union", "gr.intersection", "gr.difference"};
    static constexpr const char* kWords[] = {"union", "intersection", "difference"};
    const char* call = kCalls[static_cast<int>(Op)];
    checkArgCount(L, call, 2, 3, "(a, b [, name])");
    auto a = checkNode(L, 1, call, "a");
    auto b = checkNode(L, 2, call, "b");
    std::string name = lua_gettop(L) >= 3 ? checkString(L, 3, call, "name")
                                          : std::string(kWords[static_cast<int>(Op)]) + "(" +
                                                a->name + ", " + b->name + ")";
    pushNode(L, csgNode(Op, std::move(name), std::move(a), std::move(b)));
    return 1;
}

/// Seed 001's operation letters, and raybook's words for them.
CsgOp parseOperation(const std::string& s) {
    if (s == "u" || s == "union") return CsgOp::Union;
    if (s == "n" || s == "intersection") return CsgOp::Intersection;
    if (s == "d" || s == "difference") return CsgOp::Difference;
    throw InputError(
        "node:csg: argument 2 (operation) must be 'u' (union), 'n' (intersection) "
        "or 'd' (difference), got '" +
        s + "'");
}

// [lua-csg-method]
/// nodeA:csg(nodeB, op): nodeA keeps its name, place in the graph and material, and becomes
/// op(A, B). Its former self (shape, transform, children) becomes operand A; nodeB, with its
/// whole subgraph, becomes operand B, placed like a sibling of A. Transforms written before
/// the call move one operand; transforms of nodeA written after it move the result.
int nodeCsg(lua_State* L) {
    checkArgCount(L, "node:csg", 3, 3, "(other, 'u'|'n'|'d')");
    auto self = checkNode(L, 1, "node:csg", "self");
    auto other = checkNode(L, 2, "node:csg", "other");
    const CsgOp op = parseOperation(checkString(L, 3, "node:csg", "operation"));
    if (other == self || reaches(*other, self.get()))
        throw InputError("node:csg: '" + other->name + "' contains '" + self->name +
                         "', so combining them would make a cycle in the scene graph");
    // Operand A: a copy of the node as it is; the node itself starts afresh as the result.
    auto a = std::make_shared<SceneNode>(*self);
    a->name = self->name + " (operand A)";
    auto result = csgNode(op, self->name, std::move(a), std::move(other));
    self->shape.reset();
    self->transform = Mat4(1.0);
    self->shapeTransform = Mat4(1.0);
    // Its transforms so far place operand A, not the result: the era's idiom starts afresh.
    restartPlacement(L, self.get());
    self->compound = result->compound;
    self->children = std::move(result->children);
    return 0;
}
// [lua-csg-method]

}  // namespace

/// Chapter 14's Lua calls.
void bindCsg(LuaBindings& lua) {
    lua.function("union", luaGuard<grCsg<CsgOp::Union>>);
    lua.function("intersection", luaGuard<grCsg<CsgOp::Intersection>>);
    lua.function("difference", luaGuard<grCsg<CsgOp::Difference>>);
    lua.nodeMethod("csg", luaGuard<nodeCsg>);
}

}  // namespace rb
