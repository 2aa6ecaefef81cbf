// Chapter 3 plugs in: gr.mesh and the two-level BVH.
#include "bvh/bvh_aggregate.h"
#include "core/integrator.h"
#include "core/render_context.h"
#include "scene/lua_scene.h"

namespace rb {

void bindMeshes(LuaBindings& lua);

namespace {
void installChapter03(Pipeline& p, Scene&, const RenderContext& context) {
    p.buildAggregate = bvhLayoutNamed(context.cliOption("bvh")) == BVHLayout::Binary
                           ? buildBinaryBVHAggregate
                           : buildBVHAggregate;
}
}  // namespace

Feature bvhFeature() {
    Feature f{"bvh", 3,          "OBJ meshes, watertight triangles, two-level binned-SAH BVH",
              false, bindMeshes, installChapter03};
    f.options = {{"bvh", "binary|wide",
                  "the BVH traversal: the lesson's binary tree, or four-wide SIMD nodes", "wide"}};
    return f;
}

}  // namespace rb
