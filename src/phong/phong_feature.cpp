// Chapter 2 plugs in: Phong shading with point lights and hard shadows.
#include "phong/phong.h"
#include "phong/phong.h"

namespace rb {

namespace {
void installChapter02(Pipeline& p, Scene&, const RenderContext&) {
    p.surface = shadePhong;
}
}  // namespace

Feature phongFeature() {
    return {"phong", 2,       "A4 scene graph, Phong shading, point lights, hard shadows",
            false,   nullptr, installChapter02};
}

}  // namespace rb
