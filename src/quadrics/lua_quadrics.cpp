// Chapter 15's Lua calls: cylinders and cones.
//
//   gr.cylinder(name)                        the capped unit cylinder (radius 1, y from −1 to 1)
//   gr.cyllinder(name)                       seed 001's spelling of the same
//   gr.cylinder{name=, open=}                raybook's form; open = true leaves out the caps
//   gr.cone(name)                            the capped unit cone (base radius 1 at y = −1,
//                                            apex at y = +1)
//   gr.cone{name=, open=, top_radius=}       raybook's form; 0 < top_radius ≤ 1 is a frustum
#include <cmath>
#include <initializer_list>
#include <string>

#include "core/error.h"
#include "quadrics/cone.h"
#include "quadrics/cylinder.h"
#include "quadrics/quadrics.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// What a cylinder or cone call asks for.
struct QuadricRequest {
    std::string name;
    bool open = false;
    double topRadius = 0.0;
};

/// Read the call's one argument: a name (the seeds' form) or a table of named fields (raybook's
/// form), accepting only the fields in `known`.
QuadricRequest readRequest(lua_State* L, const char* call, const char* defaultName,
                           std::initializer_list<const char*> known, const char* signature) {
    checkArgCount(L, call, 1, 1, signature);
    QuadricRequest request;
    if (lua_type(L, 1) != LUA_TTABLE) {
        request.name = checkString(L, 1, call, "name");
        return request;
    }
    request.name = defaultName;
    const std::string c = call;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        // Stack: key at −2, value at −1. Read both, then pop the value for lua_next.
        if (lua_type(L, -2) != LUA_TSTRING) {
            lua_pop(L, 2);
            throw InputError(c + ": the table's keys must be field names");
        }
        const std::string key = lua_tostring(L, -2);
        const int type = lua_type(L, -1);
        bool isKnown = false;
        std::string list;
        for (const char* k : known) {
            isKnown = isKnown || key == k;
            list += std::string(list.empty() ? "" : ", ") + k;
        }
        if (!isKnown) {
            lua_pop(L, 2);
            throw InputError(c + ": unknown field '" + key + "' (known: " + list + ")");
        }
        if (key == "name") {
            if (type != LUA_TSTRING) {
                lua_pop(L, 2);
                throw InputError(c + ": field 'name' must be a string");
            }
            request.name = lua_tostring(L, -1);
        } else if (key == "open") {
            if (type != LUA_TBOOLEAN) {
                lua_pop(L, 2);
                throw InputError(c + ": field 'open' must be true or false");
            }
            request.open = lua_toboolean(L, -1) != 0;
        } else {  // top_radius
            const double r = lua_tonumber(L, -1);
            if (type != LUA_TNUMBER || !std::isfinite(r) || r < 0.0 || r > 1.0) {
                lua_pop(L, 2);
                throw InputError(c + ": field 'top_radius' must be a number from 0 (a pointed " +
                                 "cone) to 1 (the base radius)");
            }
            request.topRadius = r;
        }
        lua_pop(L, 1);
    }
    return request;
}

constexpr char kCylinder[] = "gr.cylinder";
constexpr char kCyllinder[] = "gr.cyllinder";

// [lua-quadrics]
/// gr.cylinder / gr.cyllinder: a node holding the unit cylinder, capped unless open = true.
template <const char* Call>
int grCylinder(lua_State* L) {
    const QuadricRequest r = readRequest(L, Call, "cylinder", {"name", "open"},
                                         "(name) or {name = ..., open = true|false}");
    // Seed 001's spelling tells the era (its framework post-multiplied transforms).
    if (Call == kCyllinder) noteEraSign(L, Era::Legacy, "seed 001's gr.cyllinder");
    auto node = std::make_shared<SceneNode>();
    node->name = r.name;
    node->shape = std::make_shared<const Cylinder>(!r.open);
    pushNode(L, node);
    return 1;
}

/// gr.cone: a node holding the unit cone (or frustum), capped unless open = true.
int grCone(lua_State* L) {
    const QuadricRequest r =
        readRequest(L, "gr.cone", "cone", {"name", "open", "top_radius"},
                    "(name) or {name = ..., open = true|false, top_radius = 0..1}");
    // gr.cone(name) is seed 001's call and raybook's own first form: no sign of an era.
    auto node = std::make_shared<SceneNode>();
    node->name = r.name;
    node->shape = std::make_shared<const Cone>(r.topRadius, !r.open);
    pushNode(L, node);
    return 1;
}
// [lua-quadrics]

}  // namespace

void bindQuadrics(LuaBindings& lua) {
    lua.function("cylinder", luaGuard<grCylinder<kCylinder>>);
    lua.function("cyllinder", luaGuard<grCylinder<kCyllinder>>);
    lua.function("cone", luaGuard<grCone>);
}

}  // namespace rb
