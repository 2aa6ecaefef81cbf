// Chapter 12's Lua: the tone map for the renders requested after the call.
//
//   gr.tone_map{operator = 'global', key = 0.18, white = 'max', exposure = 0, srgb = true}
//   gr.tone_map{operator = 'local', key = 0.18, sharpness = 8, threshold = 0.05}
//   gr.tone_map{exposure = 1.5}          no operator: clip after 1.5 stops more light
//   gr.tone_map{operator = 'none'}       the course's output: clamp each channel
//   gr.option('tone_map', k)      the same one option at a time: k = 0 none, 1 global, 2 local
//   gr.option('tone_key', a)
//   gr.option('tone_white', L)    L > 0, or 0 (the image's largest), or -1 (none: L / (1 + L))
//   gr.option('exposure', ev)
//   gr.option('srgb', 0 | 1)
//   gr.option('tone_sharpness', phi)
//   gr.option('tone_threshold', epsilon)
//
// Seed 002 promises "Reinhard's tone mapping operator" but names no call for it; its scene
// uses gr.tone_map{operator = 'global'}.
#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/lua_scene.h"
#include "tone_map/tone_map.h"

namespace rb {

namespace {

/// The fields gr.tone_map accepts, for the unknown-field message.
constexpr const char* kFields = "operator, key, white, exposure, srgb, sharpness, threshold";

/// Store a scene option as gr.option would, naming gr.tone_map's field when it is out of range.
void setOption(lua_State* L, const char* field, const char* name, double value) {
    setSceneOption(L, name, value, std::string("gr.tone_map: field '") + field + "'");
}

/// A number field of the gr.tone_map table stored as option `name`, when present.
void numberField(lua_State* L, const char* field, const char* name) {
    if (lua_getfield(L, 1, field) != LUA_TNIL) {
        const double v = checkNumberAt(L, -1, std::string("gr.tone_map: field '") + field + "'");
        lua_pop(L, 1);
        setOption(L, field, name, v);
        return;
    }
    lua_pop(L, 1);
}

// [lua-tone-map]
/// gr.tone_map{operator=, key=, white=, exposure=, srgb=, sharpness=, threshold=}: raybook's
/// named form of the options.
int grToneMap(lua_State* L) {
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE)
        throw InputError(std::string("gr.tone_map expects one table {") + kFields + "}");
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (key != "operator" && key != "key" && key != "white" && key != "exposure" &&
            key != "srgb" && key != "sharpness" && key != "threshold") {
            lua_pop(L, 1);
            throw InputError("gr.tone_map: unknown field '" + key + "' (known: " + kFields + ")");
        }
    }
    // The operator, by name.
    const int opType = lua_getfield(L, 1, "operator");
    if (opType != LUA_TNIL) {
        const std::string op = opType == LUA_TSTRING ? lua_tostring(L, -1) : "";
        lua_pop(L, 1);
        int k = -1;
        for (int i = 0; i < 3; ++i)
            if (op == kToneOperatorNames[i]) k = i;
        if (k < 0)
            throw InputError("gr.tone_map: field 'operator' must be 'none', 'global' or 'local'" +
                             (opType == LUA_TSTRING ? ", got '" + op + "'" : std::string()));
        setOption(L, "operator", "tone_map", k);
    } else
        lua_pop(L, 1);
    // L_white: a number, 'max' or 'none'.
    const int whiteType = lua_getfield(L, 1, "white");
    if (whiteType == LUA_TSTRING) {
        const std::string white = lua_tostring(L, -1);
        lua_pop(L, 1);
        if (white != "max" && white != "none")
            throw InputError(
                "gr.tone_map: field 'white' must be a positive number, 'max' or "
                "'none', got '" +
                white + "'");
        setOption(L, "white", "tone_white", white == "max" ? 0.0 : -1.0);
    } else if (whiteType != LUA_TNIL) {
        const double v = checkNumberAt(L, -1, "gr.tone_map: field 'white'");
        lua_pop(L, 1);
        if (v <= 0.0)
            throw InputError(
                "gr.tone_map: field 'white' must be a positive number, 'max' or "
                "'none'");
        setOption(L, "white", "tone_white", v);
    } else
        lua_pop(L, 1);
    // sRGB: a boolean.
    const int srgbType = lua_getfield(L, 1, "srgb");
    if (srgbType != LUA_TNIL) {
        if (srgbType != LUA_TBOOLEAN) {
            lua_pop(L, 1);
            throw InputError("gr.tone_map: field 'srgb' must be true or false");
        }
        const bool on = lua_toboolean(L, -1);
        lua_pop(L, 1);
        setOption(L, "srgb", "srgb", on ? 1.0 : 0.0);
    } else
        lua_pop(L, 1);
    numberField(L, "key", "tone_key");
    numberField(L, "exposure", "exposure");
    numberField(L, "sharpness", "tone_sharpness");
    numberField(L, "threshold", "tone_threshold");
    return 0;
}
// [lua-tone-map]

}  // namespace

void bindToneMap(LuaBindings& lua) {
    lua.function("tone_map", luaGuard<grToneMap>);
    lua.option("tone_map", 12, 0, 2, true);
    lua.option("tone_key", 12, 1e-6, 100, false);
    lua.option("tone_white", 12, -1, 1e30, false);
    lua.option("exposure", 12, -30, 30, false);
    lua.option("srgb", 12, 0, 1, true);
    lua.option("tone_sharpness", 12, 0, 64, false);
    lua.option("tone_threshold", 12, 1e-6, 10, false);
}

}  // namespace rb
