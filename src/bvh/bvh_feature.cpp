// Chapter 3 plugs in: gr.mesh and the two-level BVH.
#include "bvh/bvh_aggregate.h"
#include "core/integrator.h"
#include "core/lua_scene.h"

namespace rb {

void bindMeshes(LuaBindings& lua);

namespace {
void installChapter03(Pipeline& p, Scene&, const RenderContext&) {
    p.buildAggregate = buildBVHAggregate;
}
}  // namespace

Feature bvhFeature() {
    return {"bvh", 3,          "OBJ meshes, watertight triangles, two-level binned-SAH BVH",
            false, bindMeshes, installChapter03};
}

}  // namespace rb
