// Chapter 14 plugs in: CSG nodes are compound shapes that the core's flattening builds while
// the feature is on. Nothing is installed per render, so a scene without CSG pays nothing.
#include "csg/csg_feature.h"

#include "scene/lua_scene.h"

namespace rb {

void bindCsg(LuaBindings& lua);

Feature csgFeature() {
    return {"csg", 14,      "constructive solid geometry: union, intersection, difference",
            true,  bindCsg, nullptr};
}

}  // namespace rb
