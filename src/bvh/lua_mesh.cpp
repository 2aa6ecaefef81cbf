// Chapter 3's Lua calls: gr.mesh(name, 'file.obj') and the legacy table form
// gr.mesh(name, {{x,y,z}...}, {{i,j,k,...}...}) with 0-based indices; seed 002's gr.obj_mesh.
#include "bvh/lua_mesh.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bvh/mesh.h"
#include "core/error.h"
#include "scene/lua_scene.h"

namespace rb {

namespace {

/// The mesh in `file`, loaded once per scene and shared by every node that names it.
std::shared_ptr<const Shape> meshFromFile(lua_State* L, const std::string& file, const char* call) {
    SceneBuilder& builder = sceneBuilder(L);
    const std::string path = findSceneFile(builder, file, call);
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical(path, ec).string();
    auto it = builder.meshCache.find(key);
    if (it != builder.meshCache.end()) return it->second;
    // Time the two phases for --stats.
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const ObjData data = loadObj(path, builder.options.memory);
    const auto t1 = Clock::now();
    auto mesh = std::make_shared<Mesh>(data, path, bvhLayout(builder.options));
    builder.times.meshLoad += std::chrono::duration<double>(t1 - t0).count();
    builder.times.meshBvh += std::chrono::duration<double>(Clock::now() - t1).count();
    builder.meshCache[key] = mesh;
    return mesh;
}

}  // namespace

BVHLayout bvhLayout(const SceneLoadOptions& options) {
    const auto it = options.featureOptions.find("bvh");
    return bvhLayoutNamed(it == options.featureOptions.end() ? "" : it->second);
}

ObjData objFromLuaTables(lua_State* L, const char* call) {
    ObjData data;
    if (lua_type(L, 3) != LUA_TTABLE)
        throw InputError(std::string(call) + ": argument 3 (faces) must be a table of index lists");
    const lua_Unsigned nv = lua_rawlen(L, 2);
    for (lua_Unsigned i = 1; i <= nv; ++i) {
        lua_rawgeti(L, 2, static_cast<lua_Integer>(i));
        const int top = lua_gettop(L);
        double xyz[3] = {0, 0, 0};
        bool ok = lua_type(L, top) == LUA_TTABLE && lua_rawlen(L, top) == 3;
        for (int k = 0; ok && k < 3; ++k) {
            ok = lua_rawgeti(L, top, k + 1) == LUA_TNUMBER;
            xyz[k] = lua_tonumber(L, -1);
            lua_pop(L, 1);
            ok = ok && std::isfinite(xyz[k]);
        }
        lua_pop(L, 1);
        if (!ok)
            throw InputError(std::string(call) + ": argument 2 (vertices): vertex " +
                             std::to_string(i) + " must be a table of 3 finite numbers");
        data.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    const lua_Unsigned nf = lua_rawlen(L, 3);
    for (lua_Unsigned f = 1; f <= nf; ++f) {
        lua_rawgeti(L, 3, static_cast<lua_Integer>(f));
        const int top = lua_gettop(L);
        const lua_Unsigned n = lua_type(L, top) == LUA_TTABLE ? lua_rawlen(L, top) : 0;
        std::vector<int> idx;
        for (lua_Unsigned k = 1; k <= n; ++k) {
            lua_rawgeti(L, top, static_cast<lua_Integer>(k));
            const double v = lua_tonumber(L, -1);
            const bool isNumber = lua_type(L, -1) == LUA_TNUMBER;
            lua_pop(L, 1);
            if (!isNumber || v != std::floor(v) || v < 0 || v >= static_cast<double>(nv)) {
                lua_pop(L, 1);
                throw InputError(std::string(call) + ": face " + std::to_string(f) +
                                 " has an index that is not a vertex (0-based, below " +
                                 std::to_string(nv) + ")");
            }
            idx.push_back(static_cast<int>(v));
        }
        lua_pop(L, 1);
        if (idx.size() < 3)
            throw InputError(std::string(call) + ": face " + std::to_string(f) +
                             " needs at least 3 indices");
        // Fan-triangulate the polygon.
        for (size_t k = 1; k + 1 < idx.size(); ++k)
            data.triangles.push_back({ObjCorner{idx[0]}, ObjCorner{idx[k]}, ObjCorner{idx[k + 1]}});
    }
    return data;
}

namespace {

/// Legacy meshes: vertices and 0-based polygons as Lua tables.
std::shared_ptr<const Shape> meshFromTables(lua_State* L, const char* call) {
    const SceneBuilder& builder = sceneBuilder(L);
    return std::make_shared<Mesh>(objFromLuaTables(L, call), builder.scenePath,
                                  bvhLayout(builder.options));
}

// [lua-mesh]
int grMesh(lua_State* L) {
    checkArgCount(L, "gr.mesh", 2, 3, "(name, 'file.obj') or (name, vertices, faces)");
    auto node = std::make_shared<SceneNode>();
    node->name = checkString(L, 1, "gr.mesh", "name");
    if (lua_type(L, 2) == LUA_TTABLE) {
        // Only the pre-2015 framework built meshes from Lua tables.
        noteEraSign(L, Era::Legacy, "gr.mesh with Lua tables");
        node->shape = meshFromTables(L, "gr.mesh");
    } else if (lua_gettop(L) == 2) {
        noteEraSign(L, Era::Modern, "gr.mesh with an .obj file");
        node->shape = meshFromFile(L, checkString(L, 2, "gr.mesh", "file"), "gr.mesh");
    } else
        throw InputError("gr.mesh: with 3 arguments, argument 2 (vertices) must be a table");
    pushNode(L, node);
    return 1;
}
// [lua-mesh]

int grObjMesh(lua_State* L) {
    // Seed 002 documents both gr.obj_mesh(file) and gr.obj_mesh(name, file).
    checkArgCount(L, "gr.obj_mesh", 1, 2, "(name, 'file.obj')");
    auto node = std::make_shared<SceneNode>();
    const int fileArg = lua_gettop(L);
    node->name = checkString(L, 1, "gr.obj_mesh", "name");
    noteEraSign(L, Era::Modern, "seed 002's gr.obj_mesh");
    node->shape = meshFromFile(L, checkString(L, fileArg, "gr.obj_mesh", "file"), "gr.obj_mesh");
    pushNode(L, node);
    return 1;
}

}  // namespace

/// Chapter 3's Lua calls.
void bindMeshes(LuaBindings& lua) {
    lua.function("mesh", luaGuard<grMesh>);
    lua.function("obj_mesh", luaGuard<grObjMesh>);
}

}  // namespace rb
