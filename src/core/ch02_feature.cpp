// Chapter 2 plugs in: Phong shading with point lights and hard shadows.
#include "core/chapter_features.h"
#include "core/phong.h"

namespace rb {

namespace {
void installChapter02(Pipeline& p, Scene&, const RenderContext&) {
    p.surface = shadePhong;
}
}  // namespace

Feature chapter02Feature() {
    return {"phong", 2,       "A4 scene graph, Phong shading, point lights, hard shadows",
            false,   nullptr, installChapter02};
}

}  // namespace rb
