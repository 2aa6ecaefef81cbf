// Chapter 3 plugs in: gr.mesh and the two-level BVH.
#include "bvh/bvh_aggregate.h"
#include "core/integrator.h"
#include "core/render_context.h"
#include "scene/lua_scene.h"

namespace rb {

void bindMeshes(LuaBindings& lua);

namespace {
void installChapter03(Pipeline& p, Scene&, const RenderContext& context) {
    switch (bvhLayoutNamed(context.cliOption("bvh"))) {
        case BVHLayout::Binary:
            p.buildAggregate = buildBinaryBVHAggregate;
            break;
        case BVHLayout::Wide4:
            p.buildAggregate = buildWide4BVHAggregate;
            break;
        case BVHLayout::Wide8:
            p.buildAggregate = buildWide8BVHAggregate;
            break;
    }
}
}  // namespace

Feature bvhFeature() {
    Feature f{"bvh", 3,          "OBJ meshes, watertight triangles, two-level binned-SAH BVH",
              false, bindMeshes, installChapter03};
    f.options = {{"bvh", "binary|wide|wide4|wide8",
                  "the BVH traversal: the lesson's binary tree, four-wide SSE nodes, eight-wide "
                  "AVX2 nodes, or the widest this CPU runs",
                  "wide"}};
    return f;
}

}  // namespace rb
