// Chapter 8's Lua: antialiasing for the renders requested after the call.
//
//   gr.antialias{sampler = 'adaptive', threshold = 0.1, depth = 3}
//   gr.antialias{sampler = 'jittered', samples = 16}     16 rays per pixel, as 4 x 4 cells
//   gr.antialias{sampler = 'uniform', samples = 4}       2 x 2 sub-pixel centres
//   gr.antialias{sampler = 'random', samples = 10}       seed 000's "10x super-sampling"
//   gr.antialias{sampler = 'none'}                       one ray through each pixel centre
//   gr.option('aa_sampler', k)      the same one option at a time: k = 0 none, 1 random,
//   gr.option('aa_samples', n)      2 uniform, 3 jittered, 4 adaptive
//   gr.option('aa_threshold', t)
//   gr.option('aa_depth', d)
//
// Seed 001's gr.render(..., aa, ...) is read by the core into the render's options; aa = 1 is
// a 2 x 2 uniform supersample (see aaSettings). Seed 002 names no call for its adaptive
// supersampling; its scene uses gr.antialias{sampler = 'adaptive'}.
#include <cmath>
#include <string>

#include "adaptive_aa/adaptive_aa.h"
#include "core/error.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// A number field of the gr.antialias table, or NaN when absent.
double optionalField(lua_State* L, const char* name) {
    const int type = lua_getfield(L, 1, name);
    double v = std::nan("");
    if (type != LUA_TNIL)
        v = checkNumberAt(L, -1, std::string("gr.antialias: field '") + name + "'");
    lua_pop(L, 1);
    return v;
}

/// Store a scene option as gr.option would, checking it against the range gr.option allows.
void setOption(lua_State* L, const char* name, double value) {
    if (std::isnan(value)) return;
    SceneBuilder& builder = sceneBuilder(L);
    const auto& spec = builder.optionNames.at(name);
    if (value < spec.min || value > spec.max || (spec.integer && value != std::floor(value)))
        throw InputError(std::string("gr.antialias: field '") + name + "' must be " +
                         (spec.integer ? "a whole number" : "a number") + " from " +
                         std::to_string(static_cast<long long>(spec.min)) + " to " +
                         std::to_string(static_cast<long long>(spec.max)));
    builder.sceneOptions[name] = value;
}

// [lua-antialias]
/// gr.antialias{sampler=, samples=, threshold=, depth=}: raybook's named form of the options.
int grAntialias(lua_State* L) {
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE)
        throw InputError(
            "gr.antialias expects one table {sampler = 'none' | 'random' | "
            "'uniform' | 'jittered' | 'adaptive', samples =, threshold =, depth =}");
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (key != "sampler" && key != "samples" && key != "threshold" && key != "depth") {
            lua_pop(L, 1);
            throw InputError("gr.antialias: unknown field '" + key +
                             "' (known: sampler, samples, threshold, depth)");
        }
    }
    if (lua_getfield(L, 1, "sampler") != LUA_TSTRING) {
        lua_pop(L, 1);
        throw InputError(
            "gr.antialias: field 'sampler' must be 'none', 'random', 'uniform', "
            "'jittered' or 'adaptive'");
    }
    const std::string sampler = lua_tostring(L, -1);
    lua_pop(L, 1);
    int mode = -1;
    for (int k = 0; k < 5; ++k)
        if (sampler == kAaModeNames[k]) mode = k;
    if (mode < 0)
        throw InputError(
            "gr.antialias: field 'sampler' must be 'none', 'random', 'uniform', "
            "'jittered' or 'adaptive', got '" +
            sampler + "'");
    setOption(L, "aa_sampler", mode);
    setOption(L, "aa_samples", optionalField(L, "samples"));
    setOption(L, "aa_threshold", optionalField(L, "threshold"));
    setOption(L, "aa_depth", optionalField(L, "depth"));
    return 0;
}
// [lua-antialias]

}  // namespace

void bindAdaptiveAa(LuaBindings& lua) {
    lua.function("antialias", luaGuard<grAntialias>);
    lua.option("aa_sampler", 8, 0, 4, true);
    lua.option("aa_samples", 8, 1, 65536, true);
    lua.option("aa_threshold", 8, 0, 1e9, false);
    lua.option("aa_depth", 8, 0, kMaxAdaptiveDepth, true);
}

}  // namespace rb
