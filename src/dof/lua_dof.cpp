// Chapter 13's Lua: a thin lens for the renders requested after the call.
//
//   gr.lens{aperture = 0.2, focus = 8, samples = 16, shape = 'disk'}
//       aperture: the disk's diameter (or the square's side), in scene units; 0 is a pinhole
//       focus:    the distance from the eye to the plane in focus (default |view|)
//       samples:  lens samples per pixel, paired with the pixel sampler's rays
//       shape:    'disk' (default) or 'square' (seed 001's)
//   gr.option('dof_aperture', a)    the same, one option at a time
//   gr.option('dof_focus', f)
//   gr.option('dof_samples', n)
//   gr.option('dof_shape', k)       0 disk, 1 square
//
// Seed 001's gr.render(..., aa, ss, dist, {aperture, focalLength, dof}) is read by the core
// into the render's options; lensSettings reads them. Seed 000 names no call: its focus
// distance |target - eye| is the default.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "dof/dof.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// Store a scene option as gr.option would, naming gr.lens's field when it is out of range.
void setOption(lua_State* L, const char* name, const char* field, double value) {
    setSceneOption(L, name, value, std::string("gr.lens: field '") + field + "'");
}

// [lua-lens]
/// gr.lens{aperture=, focus=, samples=, shape=}: raybook's named form of the lens options.
int grLens(lua_State* L) {
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE)
        throw InputError(
            "gr.lens expects one table {aperture =, focus =, samples =, shape = 'disk' | "
            "'square'}");
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (key != "aperture" && key != "focus" && key != "samples" && key != "shape") {
            lua_pop(L, 1);
            throw InputError("gr.lens: unknown field '" + key +
                             "' (known: aperture, focus, samples, shape)");
        }
    }
    // The numbers.
    const char* fields[][2] = {
        {"aperture", "dof_aperture"}, {"focus", "dof_focus"}, {"samples", "dof_samples"}};
    for (const auto& [field, option] : fields) {
        if (lua_getfield(L, 1, field) != LUA_TNIL) {
            const double v = checkNumberAt(L, -1, std::string("gr.lens: field '") + field + "'");
            setOption(L, option, field, v);
        }
        lua_pop(L, 1);
    }
    // The shape, by name.
    const int type = lua_getfield(L, 1, "shape");
    if (type != LUA_TNIL) {
        const std::string shape = type == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (shape != "disk" && shape != "square") {
            lua_pop(L, 1);
            throw InputError("gr.lens: field 'shape' must be 'disk' or 'square'");
        }
        setOption(L, "dof_shape", "shape", shape == "square" ? 1.0 : 0.0);
    }
    lua_pop(L, 1);
    return 0;
}
// [lua-lens]

}  // namespace

void bindDof(LuaBindings& lua) {
    lua.function("lens", luaGuard<grLens>);
    lua.option("dof_aperture", 13, 0, 1e9, false);
    lua.option("dof_focus", 13, 1e-9, 1e9, false);
    lua.option("dof_samples", 13, 1, kMaxLensSamples, true);
    lua.option("dof_shape", 13, 0, 1, true);
}

}  // namespace rb
