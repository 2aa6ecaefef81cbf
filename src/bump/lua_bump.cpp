// Chapter 11's Lua: bumps on materials.
//
//   m:set_bump{pattern = 'ripples', strength = 0.004, wavelength = 0.1, centre = {0, 0, 0}}
//   m:set_bump{pattern = 'ripples', strength = 0.004, wavelength = 0.1, centres = {{..}, {..}}}
//   m:set_bump{pattern = 'noise', strength = 0.02, scale = 0.5, octaves = 4, seed = 0}
//   m:set_bump{pattern = 'ramp', strength = 1, slope = {0.5, 0, 0}}
//   m:set_bump{pattern = 'image', file = 'heights.png', strength = 0.01, step = 1,
//              mapping = 'surface' | 'planar' | 'spherical' | 'cylindrical', scale = {su, sv}}
//   m:set_bump_map('heights.png')         seed 002: the image at the default strength 0.01
//   any procedural one with step = s: the finite-difference step in object units (default:
//   1/1000 of the wavelength, the finest noise cell, or 1 for a ramp); for an image, step is
//   in texels (default 1)
//
// The strength is the displacement, in the object's own units, of one unit of height; 0 turns
// the bump off, a negative strength turns bumps into dents.
#include <cmath>
#include <set>
#include <string>

#include "bump/bump.h"
#include "bump/height_map.h"
#include "bump/procedural_heights.h"
#include "core/error.h"
#include "scene/lua_scene.h"
#include "texture/lua_texture.h"

namespace rb {

namespace {

constexpr const char* kSetBump = "material:set_bump";

/// Field `name` of the table at index 1 as a number, or `fallback` when absent.
double numberField(lua_State* L, const char* name, double fallback, bool required = false) {
    const int type = lua_getfield(L, 2, name);
    double v = fallback;
    if (type == LUA_TNIL && required) {
        lua_pop(L, 1);
        throw InputError(std::string(kSetBump) + ": field '" + name + "' is required");
    }
    if (type != LUA_TNIL)
        v = checkNumberAt(L, -1, std::string(kSetBump) + ": field '" + name + "'");
    lua_pop(L, 1);
    return v;
}

/// Field `name` as a point {x, y, z}; `present` tells whether it was there.
Vec3 pointField(lua_State* L, const char* name, bool& present) {
    present = lua_getfield(L, 2, name) != LUA_TNIL;
    Vec3 p(0.0);
    if (present) {
        const auto v = checkTupleAt(L, -1, 3, std::string(kSetBump) + ": field '" + name + "'");
        p = Vec3(v[0], v[1], v[2]);
    }
    lua_pop(L, 1);
    return p;
}

/// The ripple centres: `centre = {x, y, z}` or `centres = {{x, y, z}, ...}` (default: the
/// object's origin).
std::vector<Vec3> rippleCentres(lua_State* L) {
    bool one = false;
    const Vec3 centre = pointField(L, "centre", one);
    std::vector<Vec3> centres;
    const int type = lua_getfield(L, 2, "centres");
    if (type != LUA_TNIL) {
        const std::string label = std::string(kSetBump) + ": field 'centres'";
        if (one) {
            lua_pop(L, 1);
            throw InputError(std::string(kSetBump) + ": give 'centre' or 'centres', not both");
        }
        const lua_Unsigned n = type == LUA_TTABLE ? lua_rawlen(L, -1) : 0;
        if (n == 0 || n > 1024) {
            lua_pop(L, 1);
            throw InputError(label + " must be a list of 1 to 1024 points {x, y, z}");
        }
        for (lua_Unsigned i = 1; i <= n; ++i) {
            lua_rawgeti(L, -1, static_cast<lua_Integer>(i));
            const auto v = checkTupleAt(L, -1, 3, label + " element " + std::to_string(i));
            centres.emplace_back(v[0], v[1], v[2]);
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    if (centres.empty()) centres.push_back(centre);
    return centres;
}

// [lua-set-bump]
/// material:set_bump{pattern = 'ripples' | 'noise' | 'ramp', strength = a, ...}: raybook's
/// bump, with the pattern's own fields (see the top of this file).
int materialSetBump(lua_State* L) {
    auto material = checkMaterial(L, 1, kSetBump, "material");
    if (lua_gettop(L) != 2 || lua_type(L, 2) != LUA_TTABLE)
        throw InputError(std::string(kSetBump) +
                         " expects one table {pattern = 'ripples' | 'noise' | 'ramp' | 'image', "
                         "strength = ..., ...}");
    // Read the pattern, then refuse any field it does not know: a typo would go unnoticed.
    if (lua_getfield(L, 2, "pattern") != LUA_TSTRING) {
        lua_pop(L, 1);
        throw InputError(std::string(kSetBump) +
                         ": field 'pattern' must be 'ripples', 'noise', 'ramp' or 'image'");
    }
    const std::string pattern = lua_tostring(L, -1);
    lua_pop(L, 1);
    std::set<std::string> known = {"pattern", "strength", "step"};
    if (pattern == "ripples")
        known.insert({"wavelength", "centre", "centres"});
    else if (pattern == "noise")
        known.insert({"scale", "octaves", "seed"});
    else if (pattern == "ramp")
        known.insert("slope");
    else if (pattern == "image")
        known.insert({"file", "mapping", "scale"});
    else
        throw InputError(std::string(kSetBump) + ": unknown pattern '" + pattern +
                         "' (expected 'ripples', 'noise', 'ramp' or 'image')");
    lua_pushnil(L);
    while (lua_next(L, 2) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (!known.count(key)) {
            lua_pop(L, 1);
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw InputError(std::string(kSetBump) + ": unknown field '" + key + "' for pattern '" +
                             pattern + "' (known: " + list + ")");
        }
    }
    const double strength = numberField(L, "strength", 0.0, true);
    const double step = numberField(L, "step", 0.0);
    if (lua_getfield(L, 2, "step") != LUA_TNIL && !(step > 0.0)) {
        lua_pop(L, 1);
        throw InputError(std::string(kSetBump) + ": field 'step' must be positive");
    }
    lua_pop(L, 1);
    if (pattern == "image") {
        if (lua_getfield(L, 2, "file") != LUA_TSTRING) {
            lua_pop(L, 1);
            throw InputError(std::string(kSetBump) + ": field 'file' must be an image file name");
        }
        const std::string file = lua_tostring(L, -1);
        lua_pop(L, 1);
        // Where (u, v) comes from: chapter 10's mappings, by the names gr.texture uses.
        UVMapping mapping = UVMapping::Surface;
        if (lua_getfield(L, 2, "mapping") != LUA_TNIL) {
            const std::string name = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
            const char* names[] = {"surface", "planar", "spherical", "cylindrical"};
            int k = 0;
            while (k < 4 && name != names[k]) ++k;
            if (k == 4) {
                lua_pop(L, 1);
                throw InputError(std::string(kSetBump) +
                                 ": field 'mapping' must be 'surface', 'planar', 'spherical' "
                                 "or 'cylindrical'");
            }
            mapping = static_cast<UVMapping>(k);
        }
        lua_pop(L, 1);
        // How often the image repeats along u and v.
        Vec2 scale(1.0);
        if (lua_getfield(L, 2, "scale") != LUA_TNIL) {
            const auto v = checkTupleAt(L, -1, 2, std::string(kSetBump) + ": field 'scale'");
            scale = Vec2(v[0], v[1]);
        }
        lua_pop(L, 1);
        if (scale.x == 0.0 || scale.y == 0.0)
            throw InputError(std::string(kSetBump) + ": field 'scale' must not be 0");
        material->bump = std::make_shared<HeightMapBump>(
            std::make_shared<HeightImage>(*sceneImage(L, file, kSetBump)), strength,
            step > 0.0 ? step : 1.0, mapping, scale);
        return 0;
    }
    std::shared_ptr<const HeightField> field;
    if (pattern == "ripples") {
        const double lambda = numberField(L, "wavelength", 0.0, true);
        if (!(lambda > 0.0))
            throw InputError(std::string(kSetBump) + ": field 'wavelength' must be positive");
        field = std::make_shared<RippleHeight>(rippleCentres(L), lambda);
    } else if (pattern == "noise") {
        const double scale = numberField(L, "scale", 1.0);
        const double octaves = numberField(L, "octaves", 4.0);
        const double seed = numberField(L, "seed", 0.0);
        if (!(scale > 0.0))
            throw InputError(std::string(kSetBump) + ": field 'scale' must be positive");
        if (octaves != std::floor(octaves) || octaves < 1 || octaves > 8)
            throw InputError(std::string(kSetBump) +
                             ": field 'octaves' must be a whole number from 1 to 8");
        if (seed != std::floor(seed) || seed < 0 || seed > 4294967295.0)
            throw InputError(std::string(kSetBump) +
                             ": field 'seed' must be a whole number from 0 to 4294967295");
        field = std::make_shared<NoiseHeight>(scale, static_cast<int>(octaves),
                                              static_cast<std::uint32_t>(seed));
    } else {
        bool present = false;
        const Vec3 slope = pointField(L, "slope", present);
        if (!present) throw InputError(std::string(kSetBump) + ": field 'slope' is required");
        field = std::make_shared<RampHeight>(slope);
    }
    material->bump = std::make_shared<Bump>(field, strength, step);
    return 0;
}
// [lua-set-bump]

// [lua-set-bump-map]
/// material:set_bump_map(file): seed 002's height map, at kDefaultHeightMapStrength.
int materialSetBumpMap(lua_State* L) {
    const char* call = "material:set_bump_map";
    noteEraSign(L, Era::Modern, "seed 002's set_bump_map");
    auto material = checkMaterial(L, 1, call, "material");
    if (lua_gettop(L) != 2)  // self and the file
        throw InputError(std::string(call) + " expects 1 argument (file), got " +
                         std::to_string(lua_gettop(L) - 1));
    const std::string file = checkString(L, 2, call, "file");
    material->bump = std::make_shared<HeightMapBump>(
        std::make_shared<HeightImage>(*sceneImage(L, file, call)), kDefaultHeightMapStrength, 1.0);
    return 0;
}
// [lua-set-bump-map]

}  // namespace

void bindBump(LuaBindings& lua) {
    lua.materialMethod("set_bump", luaGuard<materialSetBump>);
    lua.materialMethod("set_bump_map", luaGuard<materialSetBumpMap>);
}

}  // namespace rb
