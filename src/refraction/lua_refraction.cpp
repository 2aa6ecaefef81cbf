// Chapter 5's Lua: the material fields `ior`, `transparency` and `schlick` for raybook's
// gr.material{...}, and seed 001's gr.transMat(kd, indexOfRefraction, transparency, scatter).
// Seed 000's "refract" keyword and seed 002's gr.fancy_material set the same fields (see
// src/reflection/lua_reflection.cpp).
#include <cstdio>

#include "core/error.h"
#include "refraction/refraction.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// "call: argument k (name) must be what, got v".
InputError badArgument(const char* call, int arg, const char* name, const char* what, double v) {
    char text[256];
    std::snprintf(text, sizeof text, "%s: argument %d (%s) must be %s, got %g", call, arg, name,
                  what, v);
    return InputError(text);
}

// [lua-transmat]
/// Seed 001's transparent material. It has no specular colour of its own; raybook gives it a
/// small white highlight (ks = 0.5, shininess 100), which shows on the opaque fraction
/// 1 − transparency.
int grTransMat(lua_State* L) {
    const char* call = "gr.transMat";
    noteEraSign(L, Era::Legacy, "seed 001's gr.transMat");
    checkArgCount(L, call, 4, 4, "(kd, indexOfRefraction, transparency, scatter)");
    auto m = std::make_shared<Material>();
    m->kd = checkVec3(L, 1, call, "kd");
    m->ks = Colour(0.5);
    m->shininess = 100.0;
    const double ior = checkNumber(L, 2, call, "indexOfRefraction");
    const double transparency = checkNumber(L, 3, call, "transparency");
    const double scatter = checkNumber(L, 4, call, "scatter");
    if (!(ior > 0.0)) throw badArgument(call, 2, "indexOfRefraction", "positive", ior);
    if (transparency < 0.0 || transparency > 1.0)
        throw badArgument(call, 3, "transparency", "in [0, 1]", transparency);
    if (scatter < 0.0) throw badArgument(call, 4, "scatter", "non-negative", scatter);
    setMaterialParam(L, *m, "ior", ior, call);
    setMaterialParam(L, *m, "transparency", transparency, call);
    // The scatter cone is chapter 7's glossiness; a build without it accepts only 0.
    if (scatter != 0.0) setMaterialParam(L, *m, "glossiness", scatter, call);
    pushMaterial(L, m);
    return 1;
}
// [lua-transmat]

}  // namespace

void bindRefraction(LuaBindings& lua) {
    lua.materialField("ior", 5);
    lua.materialField("transparency", 5);
    lua.materialField("schlick", 5);
    lua.function("transMat", luaGuard<grTransMat>);
}

}  // namespace rb
