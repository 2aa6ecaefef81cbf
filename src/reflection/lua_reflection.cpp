// Chapter 4's Lua: the material field `reflect`, and the seeds' material calls that carry a
// reflectivity: seed 000's gr.material(kd, ks, shin, "reflect", r, ...), seed 001's
// gr.phongMat and seed 002's gr.fancy_material. Parameters of later chapters (ior,
// transparency, glossiness) are set through setMaterialParam, which names the chapter a
// build lacks.
#include "core/error.h"
#include "reflection/reflection.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// kd, ks, shininess from arguments 1–3, as A4's gr.material reads them.
std::shared_ptr<Material> phongBase(lua_State* L, const char* call) {
    auto m = std::make_shared<Material>();
    m->kd = checkVec3(L, 1, call, "kd");
    m->ks = checkVec3(L, 2, call, "ks");
    m->shininess = checkNumber(L, 3, call, "shininess");
    return m;
}

/// Set a dialect parameter only when it is non-zero, so a chapter-4 build accepts seed
/// scenes whose unused parameters are 0.
void setIfNonZero(lua_State* L, Material& m, const char* name, double value, const char* call) {
    if (value != 0.0) setMaterialParam(L, m, name, value, call);
}

/// gr.material(kd, ks, shininess, r, ...): students' most common extension of A4 gives the
/// fourth argument as the reflectivity. raybook reads it so (a warning says so once); the
/// arguments after it mean too many different things to guess, so they are ignored.
int studentMaterial(lua_State* L) {
    const int n = lua_gettop(L);
    auto m = phongBase(L, "gr.material");
    const double r = checkNumber(L, 4, "gr.material", "reflectivity");
    if (r < 0.0 || r > 1.0)
        throw ArgumentError("gr.material: argument 4 (reflectivity) must be from 0 to 1", 4);
    setIfNonZero(L, *m, "reflect", r, "gr.material");
    sceneWarning(L, "gr.material numeric",
                 std::string("gr.material: read numeric argument 4 as the reflectivity (the ") +
                     "common student extension)" +
                     (n > 4 ? "; ignored arguments 5-" + std::to_string(n) : std::string()) +
                     "; a --dialect file can read them otherwise");
    pushMaterial(L, m);
    return 1;
}

// [lua-seed000-material]
/// gr.material with seed 000's keyword tail: "reflect", r | "refract", ior |
/// "glossy", fuzz, then optionally "reflect", r and "refract", ior.
int grMaterialSeed000(lua_State* L) {
    const int n = lua_gettop(L);
    if (n == 1 && lua_type(L, 1) == LUA_TTABLE) return materialTable(L);
    if (n <= 3) return a4Material(L);
    if (lua_type(L, 4) == LUA_TNUMBER) return studentMaterial(L);
    noteEraSign(L, Era::Modern, "seed 000's gr.material keywords");
    auto m = phongBase(L, "gr.material");
    for (int arg = 4; arg <= n; arg += 2) {
        const std::string key = checkString(L, arg, "gr.material", "keyword");
        if (arg + 1 > n)
            throw ArgumentError("gr.material: keyword \"" + key + "\" needs a number after it",
                                arg);
        const double v = checkNumber(L, arg + 1, "gr.material", key.c_str());
        if (key == "reflect") setMaterialParam(L, *m, "reflect", v, "gr.material");
        else if (key == "refract") {
            // Seed 000's refracting materials are clear: all light is transmitted. "refract",
            // 0 means no refraction, as "reflect", 0 means no mirror.
            if (v != 0.0) {
                setMaterialParam(L, *m, "ior", v, "gr.material");
                setMaterialParam(L, *m, "transparency", 1.0, "gr.material");
            }
        } else if (key == "glossy") setIfNonZero(L, *m, "glossiness", v, "gr.material");
        else
            throw ArgumentError("gr.material: unknown keyword \"" + key +
                                    "\" (expected \"reflect\", \"refract\" or \"glossy\")",
                                arg);
    }
    pushMaterial(L, m);
    return 1;
}
// [lua-seed000-material]

int grPhongMat(lua_State* L) {
    // Seed 001: gr.phongMat(kd, ks, shininess, reflectivity, glossiness).
    noteEraSign(L, Era::Legacy, "seed 001's gr.phongMat");
    checkArgCount(L, "gr.phongMat", 5, 5, "(kd, ks, shininess, reflectivity, glossiness)");
    auto m = phongBase(L, "gr.phongMat");
    setIfNonZero(L, *m, "reflect", checkNumber(L, 4, "gr.phongMat", "reflectivity"),
                 "gr.phongMat");
    setIfNonZero(L, *m, "glossiness", checkNumber(L, 5, "gr.phongMat", "glossiness"),
                 "gr.phongMat");
    pushMaterial(L, m);
    return 1;
}

int grFancyMaterial(lua_State* L) {
    // Seed 002: gr.fancy_material(kd, ks, shininess, reflectivity, ior, transparency,
    // glossiness).
    const char* call = "gr.fancy_material";
    noteEraSign(L, Era::Modern, "seed 002's gr.fancy_material");
    checkArgCount(L, call, 7, 7,
                  "(kd, ks, shininess, reflectivity, ior, transparency, glossiness)");
    auto m = phongBase(L, call);
    setIfNonZero(L, *m, "reflect", checkNumber(L, 4, call, "reflectivity"), call);
    const double ior = checkNumber(L, 5, call, "ior");
    const double transparency = checkNumber(L, 6, call, "transparency");
    if (transparency != 0.0) {
        setMaterialParam(L, *m, "ior", ior, call);
        setMaterialParam(L, *m, "transparency", transparency, call);
    }
    setIfNonZero(L, *m, "glossiness", checkNumber(L, 7, call, "glossiness"), call);
    pushMaterial(L, m);
    return 1;
}

}  // namespace

void bindReflection(LuaBindings& lua) {
    lua.materialField("reflect", 4);
    lua.function("material", luaGuard<grMaterialSeed000>);
    lua.function("phongMat", luaGuard<grPhongMat>);
    lua.function("fancy_material", luaGuard<grFancyMaterial>);
}

}  // namespace rb
