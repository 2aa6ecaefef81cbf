// Chapter 16's Lua: photon mapping for the renders requested after the call.
//
//   gr.photons{count = 20000, passes = 16, radius = 0.05, alpha = 2/3,
//              method = 'progressive', k = 0, caustics = true, indirect = false, gather = 32,
//              at_least = 0}
//       count:    photons emitted per pass, for each map
//       passes:   passes; each traces new photons and gathers with a smaller radius
//       radius:   the first pass's gather radius (default: from the pixel footprint)
//       alpha:    the radius shrinks as r²_{i+1} = r²_i (i + α)/(i + 1); in (0, 1)
//       method:   'progressive' (default) or 'classic' (Jensen's: one radius for every pass)
//       k:        gather only the k nearest photons within each pass's radius (0: all of them)
//       caustics: keep a caustic map (light focused by mirrors and glass)
//       indirect: keep an indirect map (colour bleeding); it replaces the ambient term
//       gather:   final gather rays for the indirect light at each visible point; 0 reads the
//                 indirect map there directly (blotchy, but cheaper)
//       at_least: where fewer photons than this lie within a gather's radius, the disk grows
//                 to hold this many (up to 3 radii): sparse light comes out smooth, not
//                 speckled (0, the default: every gather keeps its radius)
//   gr.photons{} switches photon mapping on with every default.
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/render_context.h"
#include "photon_map/photon_map.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// The fields gr.photons knows, with the scene option each sets.
constexpr const char* kNumberFields[][2] = {{"count", "photon_count"},
                                            {"passes", "photon_passes"},
                                            {"radius", "photon_radius"},
                                            {"k", "photon_nearest"},
                                            {"at_least", "photon_at_least"},
                                            {"gather", "photon_gather"}};
constexpr const char* kBoolFields[][2] = {{"caustics", "photon_caustics"},
                                          {"indirect", "photon_indirect"}};

// [lua-photons]
/// gr.photons{count=, passes=, radius=, alpha=, method=, k=, caustics=, indirect=, gather=,
/// at_least=}.
int grPhotons(lua_State* L) {
    const char* usage =
        "gr.photons expects one table {count =, passes =, radius =, alpha =, method = "
        "'progressive' | 'classic', k =, caustics = true | false, indirect = true | false, "
        "gather =, at_least =}";
    if (lua_gettop(L) != 1 || lua_type(L, 1) != LUA_TTABLE) throw InputError(usage);
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "?";
        const bool known = key == "alpha" || key == "method" || key == "count" || key == "passes" ||
                           key == "radius" || key == "k" || key == "caustics" ||
                           key == "indirect" || key == "gather" || key == "at_least";
        if (!known) {
            lua_pop(L, 1);
            throw InputError("gr.photons: unknown field '" + key +
                             "' (known: count, passes, radius, alpha, method, k, caustics, "
                             "indirect, gather, at_least)");
        }
    }
    for (const auto& [field, option] : kNumberFields) {
        if (lua_getfield(L, 1, field) != LUA_TNIL) {
            const std::string what = std::string("gr.photons: field '") + field + "'";
            setSceneOption(L, option, checkNumberAt(L, -1, what), what);
        }
        lua_pop(L, 1);
    }
    if (lua_getfield(L, 1, "alpha") != LUA_TNIL) {
        const double alpha = checkNumberAt(L, -1, "gr.photons: field 'alpha'");
        // α = 1 would never shrink the radius (use method = 'classic'), α = 0 would shrink it
        // to nothing after one pass.
        if (!(alpha > 0.0 && alpha < 1.0))
            throw InputError("gr.photons: field 'alpha' must lie strictly between 0 and 1, got " +
                             formatNumber(alpha));
        setSceneOption(L, "photon_alpha", alpha, "gr.photons: field 'alpha'");
    }
    lua_pop(L, 1);
    const int method = lua_getfield(L, 1, "method");
    if (method != LUA_TNIL) {
        const std::string name = method == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (name != "progressive" && name != "classic")
            throw InputError("gr.photons: field 'method' must be 'progressive' or 'classic'");
        setSceneOption(L, "photon_classic", name == "classic" ? 1.0 : 0.0, "gr.photons");
    }
    lua_pop(L, 1);
    for (const auto& [field, option] : kBoolFields) {
        const int type = lua_getfield(L, 1, field);
        if (type != LUA_TNIL && type != LUA_TBOOLEAN)
            throw InputError(std::string("gr.photons: field '") + field +
                             "' must be true or false");
        if (type == LUA_TBOOLEAN)
            setSceneOption(L, option, lua_toboolean(L, -1) ? 1.0 : 0.0, "gr.photons");
        lua_pop(L, 1);
    }
    setSceneOption(L, "photons", 1.0, "gr.photons");
    return 0;
}
// [lua-photons]

}  // namespace

void bindPhotonMap(LuaBindings& lua) {
    lua.function("photons", luaGuard<grPhotons>);
    lua.materialField("caustics", 16);
    lua.option("photons", 16, 0, 1, true);
    lua.option("photon_count", 16, 1, 1e12, true);
    lua.option("photon_passes", 16, 1, 100000, true);
    lua.option("photon_radius", 16, 1e-12, 1e12, false);
    lua.option("photon_alpha", 16, 1e-6, 1.0 - 1e-6, false);
    lua.option("photon_classic", 16, 0, 1, true);
    lua.option("photon_nearest", 16, 0, 1e6, true);
    lua.option("photon_caustics", 16, 0, 1, true);
    lua.option("photon_indirect", 16, 0, 1, true);
    lua.option("photon_gather", 16, 0, 65536, true);
    lua.option("photon_at_least", 16, 0, 1e6, true);
}

}  // namespace rb
