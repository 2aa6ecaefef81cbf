// Chapter 1 plugs in: the A4 scene calls, headlight shading and brute-force intersection.
#include "core/integrator.h"
#include "scene/chapter_features.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {
void installChapter01(Pipeline& p, Scene&, const RenderContext&) {
    p.surface = shadeHeadlight;
    p.buildAggregate = buildLinearAggregate;
}
}  // namespace

Feature chapter01Feature() {
    return {"raycast", 1,      "rays, pinhole camera, spheres and boxes, images, OpenMP",
            false,     bindA4, installChapter01};
}

}  // namespace rb
