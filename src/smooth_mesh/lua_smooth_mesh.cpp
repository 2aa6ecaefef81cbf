// Chapter 9's Lua calls.
//
//   gr.smooth_mesh(name, 'file.obj')                     the file's vn, computed where missing
//   gr.smooth_mesh(name, 'file.obj', {normals = 'computed', crease = 30, terminator = false})
//   gr.smooth_mesh(name, vertices, faces [, {crease =, terminator =}])   gr.mesh's table form
//   gr.obj_mesh(name, 'file.obj'), gr.obj_mesh('file.obj')   seed 002: smooth, the defaults
//
// normals: 'file' (default) or 'computed' (ignore the file's vn); crease: degrees, 0 to 180,
// default 60; terminator: start shadow rays off the flat facet (default true).
// gr.mesh stays faceted, as the course's A4 renders meshes.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bvh/lua_mesh.h"
#include "core/error.h"
#include "scene/lua_scene.h"
#include "smooth_mesh/smooth_mesh.h"

namespace rb {

namespace {

/// gr.smooth_mesh's option table at stack index `index`, checked field by field.
SmoothMeshOptions readOptions(lua_State* L, int index) {
    SmoothMeshOptions options;
    if (lua_type(L, index) != LUA_TTABLE)
        throw InputError("gr.smooth_mesh: argument " + std::to_string(index) +
                         " must be a table {normals = 'file' | 'computed', crease = degrees, "
                         "terminator = true | false}");
    lua_pushnil(L);
    while (lua_next(L, index) != 0) {
        const std::string key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "";
        if (key == "normals") {
            const std::string value = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
            if (value == "file")
                options.normals = NormalSource::File;
            else if (value == "computed")
                options.normals = NormalSource::Computed;
            else
                throw InputError("gr.smooth_mesh: field 'normals' must be 'file' or 'computed'");
        } else if (key == "crease") {
            const double crease = checkNumberAt(L, -1, "gr.smooth_mesh: field 'crease'");
            if (!(crease >= 0.0 && crease <= 180.0))
                throw InputError(
                    "gr.smooth_mesh: field 'crease' must be an angle in degrees "
                    "from 0 to 180");
            options.creaseDegrees = crease;
        } else if (key == "terminator") {
            if (lua_type(L, -1) != LUA_TBOOLEAN)
                throw InputError("gr.smooth_mesh: field 'terminator' must be true or false");
            options.terminatorFix = lua_toboolean(L, -1) != 0;
        } else {
            throw InputError("gr.smooth_mesh: unknown field '" + key +
                             "' (known: normals, crease, terminator)");
        }
        lua_pop(L, 1);
    }
    return options;
}

/// The smooth mesh of `file` with `options`, loaded once per scene and shared. The faceted
/// Mesh underneath is shared with gr.mesh calls on the same file.
std::shared_ptr<const Shape> smoothMeshFromFile(lua_State* L, const std::string& file,
                                                const SmoothMeshOptions& options,
                                                const char* call) {
    SceneBuilder& builder = sceneBuilder(L);
    const std::string path = findSceneFile(builder, file, call);
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical(path, ec).string();
    char settings[96];
    std::snprintf(settings, sizeof settings, "|smooth|%d|%.17g|%d",
                  static_cast<int>(options.normals), options.creaseDegrees,
                  options.terminatorFix ? 1 : 0);
    const std::string smoothKey = key + settings;
    if (auto it = builder.meshCache.find(smoothKey); it != builder.meshCache.end())
        return it->second;
    // Time the two phases for --stats, as gr.mesh does.
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const ObjData data = loadObj(path, builder.options.memory);
    const auto t1 = Clock::now();
    std::shared_ptr<const Mesh> mesh;
    if (auto it = builder.meshCache.find(key); it != builder.meshCache.end())
        mesh = std::dynamic_pointer_cast<const Mesh>(it->second);
    if (!mesh) {
        mesh = std::make_shared<Mesh>(data, path, bvhLayout(builder.options));
        builder.meshCache[key] = mesh;
    }
    auto smooth = std::make_shared<SmoothMesh>(mesh, data, options);
    builder.times.meshLoad += std::chrono::duration<double>(t1 - t0).count();
    builder.times.meshBvh += std::chrono::duration<double>(Clock::now() - t1).count();
    builder.meshCache[smoothKey] = smooth;
    return smooth;
}

// [lua-smooth-mesh]
int grSmoothMesh(lua_State* L) {
    checkArgCount(L, "gr.smooth_mesh", 2, 4,
                  "(name, 'file.obj' [, options]) or (name, vertices, faces [, options])");
    auto node = std::make_shared<SceneNode>();
    node->name = checkString(L, 1, "gr.smooth_mesh", "name");
    if (lua_type(L, 2) == LUA_TTABLE) {
        // gr.mesh's table form: vertices and 0-based polygons (a mesh a scene builds itself).
        if (lua_type(L, 3) != LUA_TTABLE)
            throw InputError("gr.smooth_mesh: argument 3 (faces) must be a table of index lists");
        const SmoothMeshOptions options =
            lua_gettop(L) == 4 ? readOptions(L, 4) : SmoothMeshOptions{};
        const ObjData data = objFromLuaTables(L, "gr.smooth_mesh");
        auto mesh = std::make_shared<Mesh>(data, sceneBuilder(L).scenePath);
        node->shape = std::make_shared<SmoothMesh>(mesh, data, options);
    } else {
        if (lua_gettop(L) == 4)
            throw InputError("gr.smooth_mesh: with a file, the options are argument 3");
        const std::string file = checkString(L, 2, "gr.smooth_mesh", "file");
        const SmoothMeshOptions options =
            lua_gettop(L) == 3 ? readOptions(L, 3) : SmoothMeshOptions{};
        node->shape = smoothMeshFromFile(L, file, options, "gr.smooth_mesh");
    }
    pushNode(L, node);
    return 1;
}
// [lua-smooth-mesh]

/// Seed 002's gr.obj_mesh(name, file) and gr.obj_mesh(file): its smooth Phong-shaded mesh.
int grObjMesh(lua_State* L) {
    checkArgCount(L, "gr.obj_mesh", 1, 2, "(name, 'file.obj')");
    auto node = std::make_shared<SceneNode>();
    const int fileArg = lua_gettop(L);
    node->name = checkString(L, 1, "gr.obj_mesh", "name");
    noteEraSign(L, Era::Modern, "seed 002's gr.obj_mesh");
    node->shape = smoothMeshFromFile(L, checkString(L, fileArg, "gr.obj_mesh", "file"),
                                     SmoothMeshOptions{}, "gr.obj_mesh");
    pushNode(L, node);
    return 1;
}

}  // namespace

/// Chapter 9's Lua calls; gr.obj_mesh replaces chapter 3's faceted one.
void bindSmoothMesh(LuaBindings& lua) {
    lua.function("smooth_mesh", luaGuard<grSmoothMesh>);
    lua.function("obj_mesh", luaGuard<grObjMesh>);
}

}  // namespace rb
