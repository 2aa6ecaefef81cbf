// Chapter 6's Lua: lights with an area.
//
//   gr.light(position, colour, falloff)                              A4 point light (the core's)
//   gr.light(position, colour, falloff, {length, width}, normal, left)   seed 001's rectangle
//   gr.area_light{position=, colour=, falloff=, size={length, width}, normal=, left=, samples=}
//   gr.ball_light(position, colour, falloff, radius)                 seed 002's ball
//   gr.ball_light{position=, colour=, falloff=, radius=, samples=}
//   gr.option('light_samples', n)                  n × n samples on every area light (0: own)
//
// Every form makes the light userdata with the core's rb::pushLight, so gr.render takes them
// all in its list of lights.
#include <cmath>
#include <initializer_list>
#include <string>

#include "core/error.h"
#include "scene/lua_scene.h"
#include "soft_shadows/soft_shadows.h"

namespace rb {

namespace {

constexpr int kMaxSamplesPerAxis = 256;

/// Throw unless the falloff is non-negative and not all zero (A4's rule for gr.light).
void checkFalloff(const Vec3& falloff, const std::string& what) {
    if (falloff.x < 0 || falloff.y < 0 || falloff.z < 0 || !(falloff.x + falloff.y + falloff.z > 0))
        throw ArgumentError(what + " must be non-negative and not all zero");
}

/// Throw unless `normal` is non-zero and `left` is non-zero and not parallel to it. (The
/// panel then uses left's part orthogonal to the normal: Gram–Schmidt, the normal wins.)
/// `argument` is the normal's position among the call's arguments, 0 for a field.
void checkPanelFrame(const Vec3& normal, const Vec3& left, const std::string& call,
                     const std::string& normalName, const std::string& leftName, int argument = 0) {
    if (!(glm::length(normal) > 0.0))
        throw ArgumentError(call + ": " + normalName + " must be a non-zero vector", argument);
    const Vec3 n = glm::normalize(normal);
    const Vec3 inPlane = left - glm::dot(left, n) * n;
    const int leftArgument = argument ? argument + 1 : 0;
    if (!(glm::length(left) > 0.0))
        throw ArgumentError(call + ": " + leftName + " must be a non-zero vector", leftArgument);
    if (!(glm::length(inPlane) > 1e-6 * glm::length(left)))
        throw ArgumentError(call + ": " + leftName + " must not be parallel to the normal",
                            leftArgument);
}

/// Reads the named fields of a table argument, with messages that name the call and field.
class Fields {
  public:
    Fields(lua_State* L, int table, const char* call) : L_(L), table_(table), call_(call) {}

    /// Throw on a key that is not one of `known` (a typo would otherwise be ignored).
    void onlyKnown(std::initializer_list<const char*> known) const {
        lua_pushnil(L_);
        while (lua_next(L_, table_) != 0) {
            lua_pop(L_, 1);  // the value; keep the key for lua_next
            bool ok = false;
            std::string list;
            if (lua_type(L_, -1) == LUA_TSTRING) {
                const std::string key = lua_tostring(L_, -1);
                for (const char* k : known) ok = ok || key == k;
                if (!ok) {
                    for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
                    lua_pop(L_, 1);
                    throw ArgumentError(std::string(call_) + ": unknown field '" + key +
                                        "' (known: " + list + ")");
                }
            } else {
                lua_pop(L_, 1);
                throw ArgumentError(std::string(call_) + ": the table's keys must be field names");
            }
        }
    }
    /// True when the field is present.
    bool has(const char* name) const {
        const bool present = rawField(name) != LUA_TNIL;
        lua_pop(L_, 1);
        return present;
    }
    /// A required field holding a table of n finite numbers.
    std::vector<double> tuple(const char* name, int n) const {
        const std::string what = std::string(call_) + ": field '" + name + "' must be a table of " +
                                 std::to_string(n) + " numbers";
        const int type = rawField(name);
        if (type == LUA_TNIL) {
            lua_pop(L_, 1);
            throw ArgumentError(std::string(call_) + ": missing field '" + name + "'");
        }
        if (type != LUA_TTABLE || lua_rawlen(L_, -1) != static_cast<lua_Unsigned>(n)) {
            lua_pop(L_, 1);
            throw ArgumentError(what);
        }
        std::vector<double> values(n);
        for (int i = 1; i <= n; ++i) {
            const int t = lua_rawgeti(L_, -1, i);
            values[i - 1] = lua_tonumber(L_, -1);
            lua_pop(L_, 1);
            if (t != LUA_TNUMBER || !std::isfinite(values[i - 1])) {
                lua_pop(L_, 1);
                throw ArgumentError(what + " (finite), but element " + std::to_string(i) +
                                    " is not");
            }
        }
        lua_pop(L_, 1);
        return values;
    }
    /// A required field holding three numbers.
    Vec3 vec3(const char* name) const {
        const auto v = tuple(name, 3);
        return {v[0], v[1], v[2]};
    }
    /// A required field holding one finite number.
    double number(const char* name) const {
        const int type = rawField(name);
        const double v = lua_tonumber(L_, -1);
        lua_pop(L_, 1);
        if (type == LUA_TNIL)
            throw ArgumentError(std::string(call_) + ": missing field '" + name + "'");
        if (type != LUA_TNUMBER || !std::isfinite(v))
            throw ArgumentError(std::string(call_) + ": field '" + name +
                                "' must be a finite number");
        return v;
    }
    /// The optional field `samples`: a whole number of samples per axis, or fallback.
    int samples(int fallback) const {
        if (!has("samples")) return fallback;
        const double v = number("samples");
        if (v != std::floor(v) || v < 1 || v > kMaxSamplesPerAxis)
            throw ArgumentError(std::string(call_) +
                                ": field 'samples' (per axis) must be a whole " +
                                "number from 1 to " + std::to_string(kMaxSamplesPerAxis));
        return static_cast<int>(v);
    }

  private:
    /// Push field `name` without metamethods and return its type. A table's __index could run
    /// Lua code that raises an error, which would longjmp over this object's C++ strings.
    int rawField(const char* name) const {
        lua_pushstring(L_, name);
        return lua_rawget(L_, table_);
    }

    lua_State* L_;
    int table_;
    const char* call_;
};

/// position, colour and falloff (default {1, 0, 0}) of a named light table.
PointLight namedPointLight(const Fields& fields, const char* call) {
    PointLight light;
    light.position = fields.vec3("position");
    light.colour = fields.vec3("colour");
    if (fields.has("falloff")) {
        light.falloff = fields.vec3("falloff");
        checkFalloff(light.falloff, std::string(call) + ": field 'falloff'");
    }
    return light;
}

// [lua-seed001-light]
/// The rest of seed 001's gr.light(position, colour, falloff, {length, width}, normal, left):
/// the core has already made the point light (argument 7); give it a rectangular shape.
int seed001RectangleLight(lua_State* L) {
    const char* call = "gr.light";
    PointLight light = checkLight(L, 7, call, "the point light");
    const auto size = checkTuple(L, 4, 2, call, "{length, width}");
    if (size[0] < 0 || size[1] < 0)
        throw ArgumentError("gr.light: argument 4 ({length, width}) must not be negative", 4);
    const Vec3 normal = checkVec3(L, 5, call, "normal");
    const Vec3 left = checkVec3(L, 6, call, "left");
    checkPanelFrame(normal, left, call, "argument 5 (normal)", "argument 6 (left)", 5);
    // Only a light read whole is a sign of seed 001 (under --lenient the arguments after the
    // third may mean something else, and be left out).
    noteEraSign(L, Era::Legacy, "seed 001's 6-argument gr.light");
    light.shape = std::make_shared<RectangleLight>(size[0], size[1], normal, left);
    pushLight(L, light);
    return 1;
}
// [lua-seed001-light]

int lightArgCountError(lua_State* L) {
    throw ArgumentError(
        "gr.light expects 3 arguments (position, colour, {c0,c1,c2}) or 6 "
        "(..., {length, width}, normal, left), got " +
        std::to_string(lua_gettop(L)));
}

/// gr.light with A4's 3 arguments or seed 001's 6. The core's gr.light is upvalue 1: it
/// builds (and checks) the point light from the first three arguments in both forms. This
/// function keeps no C++ object alive across the Lua calls, so a Lua error may pass through.
int grLight(lua_State* L) {
    int n = lua_gettop(L);
    if (n < 3) return luaGuard<lightArgCountError>(L);
    if (n != 3 && n != 6) {
        // Extra arguments the course framework would ignore: keep the form they extend.
        const int keep = n < 6 ? 3 : 6;
        sceneWarning(L, "gr.light extra",
                     "gr.light: ignored " + std::to_string(n - keep) + " extra argument" +
                         (n - keep == 1 ? "" : "s") + " after its " + std::to_string(keep) +
                         (keep == 3 ? " (position, colour, {c0,c1,c2})"
                                    : " (..., {length, width}, normal, left)") +
                         ", as the course framework does");
        lua_settop(L, keep);
        n = keep;
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    for (int i = 1; i <= 3; ++i) lua_pushvalue(L, i);
    const int status = lua_pcall(L, 3, 1, 0);
    if (status != LUA_OK) {
        // The core's message names the script's line already; add it if not.
        if (status == LUA_ERRRUN) addScriptWhere(L);
        return lua_error(L);
    }
    if (n == 3) return 1;
    return luaGuard<seed001RectangleLight>(L);
}

// [lua-area-light]
/// gr.area_light{position=, colour=, falloff=, size={length, width}, normal=, left=,
/// samples=}: raybook's named form of the rectangular light.
int grAreaLight(lua_State* L) {
    const char* call = "gr.area_light";
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE)
        throw ArgumentError(
            "gr.area_light expects one table {position=, colour=, falloff=, "
            "size={length, width}, normal=, left=, samples=}");
    const Fields fields(L, 1, call);
    fields.onlyKnown({"position", "colour", "falloff", "size", "normal", "left", "samples"});
    PointLight light = namedPointLight(fields, call);
    const auto size = fields.tuple("size", 2);
    if (size[0] < 0 || size[1] < 0)
        throw ArgumentError("gr.area_light: field 'size' must not be negative");
    const Vec3 normal = fields.vec3("normal");
    const Vec3 left = fields.vec3("left");
    checkPanelFrame(normal, left, call, "field 'normal'", "field 'left'");
    light.shape = std::make_shared<RectangleLight>(
        size[0], size[1], normal, left, fields.samples(AreaLightShape::kDefaultSamplesPerAxis));
    pushLight(L, light);
    return 1;
}
// [lua-area-light]

/// gr.ball_light(position, colour, falloff, radius) (seed 002) or
/// gr.ball_light{position=, colour=, falloff=, radius=, samples=}.
int grBallLight(lua_State* L) {
    const char* call = "gr.ball_light";
    noteEraSign(L, Era::Modern, "seed 002's gr.ball_light");
    PointLight light;
    double radius = 0.0;
    int samples = AreaLightShape::kDefaultSamplesPerAxis;
    if (lua_gettop(L) == 1 && lua_type(L, 1) == LUA_TTABLE) {
        const Fields fields(L, 1, call);
        fields.onlyKnown({"position", "colour", "falloff", "radius", "samples"});
        light = namedPointLight(fields, call);
        radius = fields.number("radius");
        samples = fields.samples(samples);
        if (radius < 0) throw ArgumentError("gr.ball_light: field 'radius' must not be negative");
    } else {
        checkArgCount(L, call, 4, 4, "(position, colour, {c0,c1,c2}, radius) or {...}");
        light.position = checkVec3(L, 1, call, "position");
        light.colour = checkVec3(L, 2, call, "colour");
        light.falloff = checkVec3(L, 3, call, "falloff");
        checkFalloff(light.falloff, "gr.ball_light: argument 3 (falloff)");
        radius = checkNumber(L, 4, call, "radius");
        if (radius < 0)
            throw ArgumentError("gr.ball_light: argument 4 (radius) must not be negative", 4);
    }
    light.shape = std::make_shared<BallLight>(radius, samples);
    pushLight(L, light);
    return 1;
}

}  // namespace

void bindSoftShadows(LuaBindings& lua) {
    lua_State* L = lua.state();
    // Replace gr.light by a version that keeps the core's as upvalue 1.
    lua_getglobal(L, "gr");
    lua_getfield(L, -1, "light");
    lua_pushcclosure(L, grLight, 1);
    lua_setfield(L, -2, "light");
    lua_pop(L, 1);
    lua.function("area_light", luaGuard<grAreaLight>);
    lua.function("ball_light", luaGuard<grBallLight>);
    lua.option("light_samples", 6);
}

}  // namespace rb
