// Chapter 17's Lua: media inside closed shapes, and fog.
//
//   m = gr.medium{sigma_a = 0.1, sigma_s = {0.5, 0.5, 0.6}, g = 0.3, density = 1}
//       sigma_a, sigma_s: absorption and scattering per unit length (a number or {r, g, b},
//                         ≥ 0; default 0 and 1)
//       g:                Henyey–Greenstein asymmetry in (−1, 1): 0 isotropic (default),
//                         > 0 forward
//       density:          a number ≥ 0 scaling both coefficients (default 1);
//                         {file = 'plume.nvdb', grid = 'density'}: a NanoVDB grid, in the
//                         node's space; {noise = frequency, octaves = 4, bias = 0, gain = 1,
//                         seed = 0}: chapter 11's noise, clamp(bias + gain·fBm, 0, 1)
//   node:set_medium(m)   the medium fills the inside of the node's closed shape. A node with
//                        a material of its own keeps its surface (a glass of milk); without
//                        one the shape only bounds the medium (a box of smoke).
//   gr.fog(m)            m fills all space outside the media of nodes, for the renders
//                        requested after the call; gr.fog(nil) clears it.
//   gr.option('media_bounces', n)   scatterings after the first (0: single scattering);
//                        --media-bounces wins
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "core/error.h"
#include "core/render_context.h"
#include "media/media.h"
#include "media/medium.h"
#include "media/vdb_density.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

constexpr const char* kMediumType = "rb.medium";

int collectMedium(lua_State* L) {
    static_cast<std::shared_ptr<const Medium>*>(lua_touserdata(L, 1))->~shared_ptr();
    return 0;
}

/// A coefficient field: a number or {r, g, b}, each finite and ≥ 0.
Colour checkCoefficient(lua_State* L, int index, const std::string& label) {
    Colour c;
    if (lua_type(L, index) == LUA_TTABLE) {
        const auto v = checkTupleAt(L, index, 3, label);
        c = Colour(v[0], v[1], v[2]);
    } else {
        c = Colour(checkNumberAt(L, index, label));
    }
    if (c.r < 0.0 || c.g < 0.0 || c.b < 0.0)
        throw InputError(label + " must be ≥ 0 (a coefficient per unit length), got " +
                         formatNumber(std::min({c.r, c.g, c.b})));
    return c;
}

/// Refuse fields of a table at `index` that are not in `known` (a typo would be ignored).
void checkFields(lua_State* L, int index, std::initializer_list<const char*> known,
                 const std::string& call) {
    lua_pushnil(L);
    while (lua_next(L, index) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "?";
        bool ok = false;
        std::string list;
        for (const char* k : known) {
            ok = ok || key == k;
            list += (list.empty() ? "" : ", ") + std::string(k);
        }
        if (!ok) {
            lua_pop(L, 1);
            throw InputError(call + ": unknown field '" + key + "' (known: " + list + ")");
        }
    }
}

/// An optional number field of the table at `index`, or fallback.
double numberField(lua_State* L, int index, const char* field, double fallback,
                   const std::string& call) {
    double v = fallback;
    if (lua_getfield(L, index, field) != LUA_TNIL)
        v = checkNumberAt(L, -1, call + ": field '" + field + "'");
    lua_pop(L, 1);
    return v;
}

/// The density table: a VDB grid or noise.
std::shared_ptr<const DensityField> checkDensityTable(lua_State* L, int index) {
    const std::string call = "gr.medium: field 'density'";
    index = lua_absindex(L, index);
    const bool file = lua_getfield(L, index, "file") != LUA_TNIL;
    lua_pop(L, 1);
    if (file) {
        checkFields(L, index, {"file", "grid"}, call);
        lua_getfield(L, index, "file");
        const std::string name = checkString(L, lua_gettop(L), call.c_str(), "file");
        lua_pop(L, 1);
        std::string grid = "density";
        if (lua_getfield(L, index, "grid") != LUA_TNIL)
            grid = checkString(L, lua_gettop(L), call.c_str(), "grid");
        lua_pop(L, 1);
        SceneBuilder& builder = sceneBuilder(L);
        const std::string path = findSceneFile(builder, name, "gr.medium");
        return loadVdbDensity(path, grid, &builder.options.memory);
    }
    if (lua_getfield(L, index, "noise") == LUA_TNIL) {
        lua_pop(L, 1);
        throw InputError(call +
                         " must be a number, {file = 'grid.nvdb', grid = 'density'} or "
                         "{noise = frequency, octaves =, bias =, gain =, seed =}");
    }
    lua_pop(L, 1);
    checkFields(L, index, {"noise", "octaves", "bias", "gain", "seed"}, call);
    const double frequency = numberField(L, index, "noise", 1.0, call);
    const double octaves = numberField(L, index, "octaves", 4.0, call);
    const double bias = numberField(L, index, "bias", 0.0, call);
    const double gain = numberField(L, index, "gain", 1.0, call);
    const double seed = numberField(L, index, "seed", 0.0, call);
    if (!(frequency > 0.0)) throw InputError(call + ": 'noise' (the frequency) must be > 0");
    if (!(octaves >= 1.0 && octaves <= 16.0 && octaves == std::floor(octaves)))
        throw InputError(call + ": 'octaves' must be a whole number from 1 to 16");
    if (!(seed >= 0.0 && seed <= 4294967295.0 && seed == std::floor(seed)))
        throw InputError(call + ": 'seed' must be a whole number from 0 to 2^32 − 1");
    return std::make_shared<NoiseDensity>(frequency, static_cast<int>(octaves), bias, gain,
                                          static_cast<std::uint32_t>(seed));
}

// [lua-medium]
/// gr.medium{sigma_a =, sigma_s =, g =, density =}.
int grMedium(lua_State* L) {
    const char* usage = "gr.medium expects one table {sigma_a =, sigma_s =, g =, density =}";
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE) throw InputError(usage);
    checkFields(L, 1, {"sigma_a", "sigma_s", "g", "density"}, "gr.medium");
    auto medium = std::make_shared<Medium>();
    medium->where = luaCaller(L);
    medium->sigmaS = Colour(1.0);
    if (lua_getfield(L, 1, "sigma_a") != LUA_TNIL)
        medium->sigmaA = checkCoefficient(L, -1, "gr.medium: field 'sigma_a'");
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "sigma_s") != LUA_TNIL)
        medium->sigmaS = checkCoefficient(L, -1, "gr.medium: field 'sigma_s'");
    lua_pop(L, 1);
    medium->g = numberField(L, 1, "g", 0.0, "gr.medium");
    if (!(std::abs(medium->g) < 1.0))
        throw InputError("gr.medium: field 'g' must lie strictly between −1 and 1, got " +
                         formatNumber(medium->g));
    const int type = lua_getfield(L, 1, "density");
    if (type == LUA_TNIL || type == LUA_TNUMBER) {
        const double scale =
            type == LUA_TNIL ? 1.0 : checkNumberAt(L, -1, "gr.medium: field 'density'");
        if (!(scale >= 0.0))
            throw InputError("gr.medium: field 'density' must be ≥ 0, got " + formatNumber(scale));
        medium->sigmaA *= scale;
        medium->sigmaS *= scale;
        medium->density = std::make_shared<ConstantDensity>();
    } else if (type == LUA_TTABLE) {
        medium->density = checkDensityTable(L, -1);
    } else {
        throw InputError(std::string("gr.medium: field 'density' must be a number or a table, "
                                     "got ") +
                         luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    chargeMemory(L, sizeof(Medium));
    void* mem = lua_newuserdatauv(L, sizeof(std::shared_ptr<const Medium>), 0);
    new (mem) std::shared_ptr<const Medium>(std::move(medium));
    luaL_setmetatable(L, kMediumType);
    return 1;
}
// [lua-medium]

/// A medium argument (gr.medium's result) at stack index `arg`, numbered as the other calls'
/// arguments are: a method's self is argument 1.
std::shared_ptr<const Medium> checkMedium(lua_State* L, int arg, const char* call) {
    if (auto* p = static_cast<std::shared_ptr<const Medium>*>(luaL_testudata(L, arg, kMediumType)))
        return *p;
    throw InputError(std::string(call) + ": argument " + std::to_string(arg) +
                     " (medium) must be a medium (from gr.medium), got " + luaL_typename(L, arg));
}

/// node:set_medium(m).
int nodeSetMedium(lua_State* L) {
    const char* call = "node:set_medium";
    checkArgCount(L, call, 2, 2, "(medium)");
    auto node = checkNode(L, 1, call, "self");
    auto medium = checkMedium(L, 2, call);
    if (!node->shape && !node->compound) {
        // A group node holds a grid's smoke in the box of its voxels.
        const AABB box = medium->density->bounds();
        if (!isFinite(box.lo) || !isFinite(box.hi) || box.empty())
            throw InputError(std::string(call) + ": node '" + node->name +
                             "' has no shape; a medium fills a closed shape (a sphere, cube, "
                             "mesh or CSG node), a group node only a VDB grid's box, and gr.fog "
                             "fills all space");
        node->shape = sceneBuilder(L).unitCube;
        node->shapeTransform = glm::scale(glm::translate(Mat4(1.0), box.lo), box.hi - box.lo);
    }
    node->medium = std::move(medium);
    return 0;
}

/// gr.fog(m) or gr.fog(nil).
int grFog(lua_State* L) {
    checkArgCount(L, "gr.fog", 1, 1, "(medium) or (nil)");
    sceneBuilder(L).fog = lua_isnil(L, 1) ? nullptr : checkMedium(L, 1, "gr.fog");
    return 0;
}

}  // namespace

void bindMedia(LuaBindings& lua) {
    lua_State* L = lua.state();
    luaL_newmetatable(L, kMediumType);
    lua_pushcfunction(L, collectMedium);
    lua_setfield(L, -2, "__gc");
    lua_pop(L, 1);
    lua.function("medium", luaGuard<grMedium>);
    lua.function("fog", luaGuard<grFog>);
    lua.nodeMethod("set_medium", luaGuard<nodeSetMedium>);
    lua.option("media_bounces", 17, 0, 1e6, true);
}

}  // namespace rb
