// Reading a gr call's arguments from Lua's stack: their count, numbers, strings, tuples,
// nodes and materials, each refused with an ArgumentError that names the call, the argument
// and what it should have been ("gr.nh_sphere: argument 3 (radius) must be a number, got nil").
#include <cmath>
#include <cstdio>
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

namespace {

/// The numbers of a list of 1 to 4 finite numbers at stack index `index` (false otherwise).
bool shortNumberList(lua_State* L, int index, std::vector<double>& values) {
    if (lua_type(L, index) != LUA_TTABLE) return false;
    const lua_Unsigned n = lua_rawlen(L, index);
    if (n < 1 || n > 4) return false;
    values.clear();
    for (lua_Unsigned i = 1; i <= n; ++i) {
        const bool number = lua_rawgeti(L, index, static_cast<lua_Integer>(i)) == LUA_TNUMBER;
        values.push_back(lua_tonumber(L, -1));
        lua_pop(L, 1);
        if (!number || !std::isfinite(values.back())) return false;
    }
    return true;
}

/// "0.5": a number as a scene writes it.
std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

/// "{0.5, 0.5}": numbers as a scene writes a table of them.
std::string listText(const std::vector<double>& values) {
    std::string text = "{";
    for (size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + numberText(values[i]);
    return text + "}";
}

/// True when `label` names a colour argument or field ("gr.material: argument 2 (ks)").
bool namesColour(const std::string& label) {
    for (const char* word : {"(kd)", "(ks)", "colour", "color", "ambient", "'kd'", "'ks'"})
        if (label.find(word) != std::string::npos) return true;
    return false;
}

/// Under --lenient, warn (once per argument) that `label` was read by a guess.
void warnGuess(lua_State* L, const std::string& label, const std::string& guess) {
    sceneWarning(L, label + " guess", label + ": --lenient read " + guess);
}

}  // namespace

double checkNumberAt(lua_State* L, int index, const std::string& label) {
    std::vector<double> list;
    if (lua_type(L, index) == LUA_TTABLE && sceneBuilder(L).options.lenient &&
        shortNumberList(L, index, list)) {
        // Another course's {exponent}: a table where a number belongs gives its number.
        double sum = 0.0;
        for (double v : list) sum += v;
        const double v = sum / static_cast<double>(list.size());
        warnGuess(L, label,
                  "the table " + listText(list) + " as the number " + numberText(v) +
                      (list.size() == 1 ? "" : ", their mean") +
                      " (a table where a number belongs)");
        return v;
    }
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
    if (n == 3 && sceneBuilder(L).options.lenient) {
        // Another course's grey (one number) or RGBA colour (four): the nearest triple.
        std::vector<double> list;
        const double v = lua_tonumber(L, index);
        if (lua_type(L, index) == LUA_TNUMBER && std::isfinite(v) && v >= 0.0 &&
            namesColour(label)) {
            warnGuess(L, label,
                      "the number " + numberText(v) + " as " + listText({v, v, v}) +
                          " (a number where 3 belong)");
            return {v, v, v};
        }
        if (shortNumberList(L, index, list) && list.size() == 4) {
            warnGuess(L, label,
                      listText(list) + " as its first 3 numbers " +
                          listText({list[0], list[1], list[2]}) +
                          " (an RGBA colour's alpha, or a "
                          "w, left out)");
            return {list[0], list[1], list[2]};
        }
    }
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
