// Chapter 18's Lua: the integrator for the renders requested after the call, and emitting
// surfaces.
//
//   gr.integrator('path')          path tracing (chapter 18) with every default
//   gr.integrator('whitted')       A4's recursive ray tracing (the default without the call)
//   gr.integrator{method = 'path', max_depth = 64, roulette = 3}
//       max_depth: bounces a path may take at most
//       roulette:  the bounce from which Russian roulette may end a path
//   gr.material{kd = {...}, emission = {r, g, b}}   a surface that emits radiance (r, g, b)
#include <string>

#include "core/error.h"
#include "path_tracing/path_tracing.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// 1 for 'path', 0 for 'whitted'; anything else is refused, naming the call.
double methodCode(const std::string& name) {
    if (name == "path") return 1.0;
    if (name == "whitted") return 0.0;
    throw ArgumentError("gr.integrator: method must be 'path' or 'whitted', got '" + name + "'", 1);
}

// [lua-integrator]
/// gr.integrator('path' | 'whitted') or gr.integrator{method =, max_depth =, roulette =}.
int grIntegrator(lua_State* L) {
    const char* usage =
        "gr.integrator expects 'path', 'whitted' or one table {method = 'path' | 'whitted', "
        "max_depth = N, roulette = N}";
    if (lua_gettop(L) != 1) throw ArgumentError(usage);
    if (lua_type(L, 1) == LUA_TSTRING) {
        setSceneOption(L, "integrator_path", methodCode(lua_tostring(L, 1)), "gr.integrator");
        return 0;
    }
    if (lua_type(L, 1) != LUA_TTABLE) throw ArgumentError(usage, 1);
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "?";
        if (key != "method" && key != "max_depth" && key != "roulette") {
            lua_pop(L, 1);
            throw ArgumentError("gr.integrator: unknown field '" + key +
                                "' (known: method, max_depth, roulette)");
        }
    }
    const int method = lua_getfield(L, 1, "method");
    const std::string name = method == LUA_TSTRING ? lua_tostring(L, -1) : "path";
    lua_pop(L, 1);
    if (method != LUA_TNIL && method != LUA_TSTRING)
        throw ArgumentError("gr.integrator: field 'method' must be 'path' or 'whitted'");
    setSceneOption(L, "integrator_path", methodCode(name), "gr.integrator");
    const char* numbers[][2] = {{"max_depth", "path_depth"}, {"roulette", "path_roulette"}};
    for (const auto& [field, option] : numbers) {
        if (lua_getfield(L, 1, field) != LUA_TNIL) {
            const std::string what = std::string("gr.integrator: field '") + field + "'";
            setSceneOption(L, option, checkNumberAt(L, -1, what), what);
        }
        lua_pop(L, 1);
    }
    return 0;
}
// [lua-integrator]

}  // namespace

void bindPathTracing(LuaBindings& lua) {
    lua.function("integrator", luaGuard<grIntegrator>);
    lua.materialField("emission", 18);
    lua.option("integrator_path", 18, 0, 1, true);
    lua.option("path_depth", 18, 1, 1e6, true);
    lua.option("path_roulette", 18, 0, 1e6, true);
}

}  // namespace rb
