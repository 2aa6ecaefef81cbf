// Reading a gr call's arguments from Lua's stack: their count, numbers, strings, tuples,
// nodes and materials, each refused with an ArgumentError that names the call, the argument
// and what it should have been ("gr.nh_sphere: argument 3 (radius) must be a number, got nil").
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/lua_scene.h"
#include "scene/lua_types.h"

namespace rb {

namespace {
/// What a message calls the value at `arg`: "a scene node", "a material", "a light", or Lua's
/// type name.
const char* typeName(lua_State* L, int arg) {
    if (luaL_testudata(L, arg, kNodeType)) return "a scene node";
    if (luaL_testudata(L, arg, kMaterialType)) return "a material";
    if (luaL_testudata(L, arg, "rb.light")) return "a light";
    return lua_typename(L, lua_type(L, arg));
}
}  // namespace

void checkArgCount(lua_State* L, const char* call, int min, int max, const char* signature) {
    const int n = lua_gettop(L);
    if (n > max && n >= min) {
        // The course framework reads the arguments it knows and ignores the rest.
        const int extra = n - max;
        sceneWarning(L, std::string(call) + " extra",
                     std::string(call) + ": ignored " + std::to_string(extra) + " extra argument" +
                         (extra == 1 ? "" : "s") + " after " + signature +
                         ", as the course framework does");
        lua_settop(L, max);
        return;
    }
    if (n < min || n > max)
        throw ArgumentError(std::string(call) + " expects " +
                            (min == max ? std::to_string(min)
                                        : std::to_string(min) + " to " + std::to_string(max)) +
                            " argument" + (max == 1 ? "" : "s") + " " + signature + ", got " +
                            std::to_string(n));
}

namespace {
/// "gr.nh_sphere: argument 3 (radius)": how a message names positional argument `arg`.
std::string argumentLabel(const char* call, int arg, const char* argName) {
    return std::string(call) + ": argument " + std::to_string(arg) + " (" + argName + ")";
}
}  // namespace

double checkNumberAt(lua_State* L, int index, const std::string& label) {
    if (lua_type(L, index) != LUA_TNUMBER)
        throw ArgumentError(label + " must be a number, got " + typeName(L, index), index);
    const double v = lua_tonumber(L, index);
    if (!std::isfinite(v))
        throw ArgumentError(label + " must be finite, got " + (std::isnan(v) ? "nan" : "inf"),
                            index);
    return v;
}

double checkNumber(lua_State* L, int arg, const char* call, const char* argName) {
    return checkNumberAt(L, arg, argumentLabel(call, arg, argName));
}

std::string checkString(lua_State* L, int arg, const char* call, const char* argName) {
    if (lua_type(L, arg) != LUA_TSTRING)
        throw ArgumentError(
            argumentLabel(call, arg, argName) + " must be a string, got " + typeName(L, arg), arg);
    size_t len = 0;
    const char* s = lua_tolstring(L, arg, &len);
    return std::string(s, len);
}

std::vector<double> checkTupleAt(lua_State* L, int index, int n, const std::string& label) {
    const std::string what = label + " must be a table of " + std::to_string(n) + " numbers";
    if (lua_type(L, index) != LUA_TTABLE)
        throw ArgumentError(what + ", got " + typeName(L, index), index);
    const lua_Unsigned len = lua_rawlen(L, index);
    if (len != static_cast<lua_Unsigned>(n))
        throw ArgumentError(what + ", got a table of " + std::to_string(len), index);
    std::vector<double> values(n);
    for (int i = 1; i <= n; ++i) {
        const int type = lua_rawgeti(L, index, i);
        const double v = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (type != LUA_TNUMBER)
            throw ArgumentError(
                what + ", but element " + std::to_string(i) + " is a " + lua_typename(L, type),
                index);
        if (!std::isfinite(v))
            throw ArgumentError(what + ", but element " + std::to_string(i) + " is " +
                                    (std::isnan(v) ? "nan" : "inf"),
                                index);
        values[i - 1] = v;
    }
    return values;
}

std::vector<double> checkTuple(lua_State* L, int arg, int n, const char* call,
                               const char* argName) {
    return checkTupleAt(L, arg, n, argumentLabel(call, arg, argName));
}

Vec3 checkVec3(lua_State* L, int arg, const char* call, const char* argName) {
    const std::vector<double> v = checkTuple(L, arg, 3, call, argName);
    return {v[0], v[1], v[2]};
}

std::shared_ptr<SceneNode> checkNode(lua_State* L, int arg, const char* call, const char* argName) {
    void* p = luaL_testudata(L, arg, kNodeType);
    if (!p)
        throw ArgumentError(std::string(call) + ": argument " + std::to_string(arg) + " (" +
                                argName + ") must be a scene node, got " + typeName(L, arg) +
                                (arg == 1 && std::strchr(call, ':')
                                     ? " (call methods with a colon: node:method(...))"
                                     : ""),
                            arg);
    return *static_cast<std::shared_ptr<SceneNode>*>(p);
}

std::shared_ptr<Material> checkMaterial(lua_State* L, int arg, const char* call,
                                        const char* argName) {
    void* p = luaL_testudata(L, arg, kMaterialType);
    if (!p)
        throw ArgumentError(std::string(call) + ": argument " + std::to_string(arg) + " (" +
                                argName + ") must be a material, got " + typeName(L, arg),
                            arg);
    return *static_cast<std::shared_ptr<Material>*>(p);
}

}  // namespace rb
