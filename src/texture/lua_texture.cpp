// Chapter 10's Lua calls: textures, and the seeds' ways of putting an image on a material.
//
//   local wood = gr.texture{image = 'wood.png', wrap = 'repeat', filter = 'bilinear',
//                           mapping = 'surface', scale = {2, 2}, offset = {0, 0}}
//   local tiles = gr.texture{checker = {{0.9, 0.9, 0.9}, {0.2, 0.2, 0.2}}, scale = {8, 8}}
//   mat:set_texture(wood)            the texture replaces kd
//   mat:set_texture('ks', tiles)     ... or the named slot ('kd' or 'ks')
//   mat:set_texture('kd', 'wood.png')   a file name makes an image texture with the defaults
//   gr.texture(mat, 'wood.jpg')      seed 000: the image replaces mat's kd
//   mat:set_texture_map('wood.jpg')  seed 002: the same
//
// Image files are searched for like meshes (working directory, scene folder, --assets) and
// each is loaded once per scene, shared by every texture that names it.
#include "texture/lua_texture.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "scene/lua_scene.h"
#include "texture/surface_texture.h"
#include "texture/texture.h"

namespace rb {

namespace {

constexpr const char* kTextureType = "rb.texture";
constexpr const char* kImageType = "rb.texture_image";
constexpr const char* kImageCache = "rb.texture_images";  ///< Registry: path -> image.

template <class T>
int collect(lua_State* L) {
    static_cast<std::shared_ptr<T>*>(lua_touserdata(L, 1))->~shared_ptr<T>();
    return 0;
}

template <class T>
void pushShared(lua_State* L, std::shared_ptr<T> p, const char* type) {
    void* mem = lua_newuserdatauv(L, sizeof(std::shared_ptr<T>), 0);
    new (mem) std::shared_ptr<T>(std::move(p));
    luaL_setmetatable(L, type);
}

}  // namespace

// [image-cache]
std::shared_ptr<const TextureImage> sceneImage(lua_State* L, const std::string& file,
                                               const std::string& call) {
    // The registry keeps every image by its canonical path, so two textures (or two calls)
    // naming one file share its texels.
    SceneBuilder& builder = sceneBuilder(L);
    const std::string path = findSceneFile(builder, file, call);
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical(path, ec).string();
    lua_getfield(L, LUA_REGISTRYINDEX, kImageCache);
    lua_getfield(L, -1, key.c_str());
    if (auto* cached =
            static_cast<std::shared_ptr<const TextureImage>*>(luaL_testudata(L, -1, kImageType))) {
        auto image = *cached;
        lua_pop(L, 2);
        return image;
    }
    lua_pop(L, 1);
    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const TextureImage> image;
    try {
        image = loadTextureImage(path, builder.options.memory);
    } catch (const InputError& e) {
        lua_pop(L, 1);
        throw InputError(call + ": " + e.what());
    }
    builder.times.meshLoad +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    pushShared(L, image, kImageType);
    lua_setfield(L, -2, key.c_str());
    lua_pop(L, 1);
    return image;
}
// [image-cache]

namespace {

/// An image texture with the defaults: repeat, bilinear, the shape's own (u, v).
std::shared_ptr<const Texture> defaultImageTexture(lua_State* L, const std::string& file,
                                                   const std::string& call) {
    return std::make_shared<ImageTexture>(sceneImage(L, file, call));
}

/// A string field of the gr.texture table that must be one of `choices`; -1 when absent.
int choiceField(lua_State* L, const char* name, std::initializer_list<const char*> choices) {
    const int type = lua_getfield(L, 1, name);
    if (type == LUA_TNIL) {
        lua_pop(L, 1);
        return -1;
    }
    std::string list;
    int k = 0, found = -1;
    const std::string value = type == LUA_TSTRING ? lua_tostring(L, -1) : "";
    lua_pop(L, 1);
    for (const char* c : choices) {
        list += std::string(list.empty() ? "'" : ", '") + c + "'";
        if (value == c) found = k;
        ++k;
    }
    if (found < 0)
        throw ArgumentError(std::string("gr.texture: field '") + name + "' must be one of " + list);
    return found;
}

/// A {a, b} field of the gr.texture table, or fallback when absent.
Vec2 pairField(lua_State* L, const char* name, const Vec2& fallback) {
    if (lua_getfield(L, 1, name) == LUA_TNIL) {
        lua_pop(L, 1);
        return fallback;
    }
    const auto v =
        checkTupleAt(L, lua_gettop(L), 2, std::string("gr.texture: field '") + name + "'");
    lua_pop(L, 1);
    return Vec2(v[0], v[1]);
}

// [lua-texture]
/// gr.texture{image = 'file' | checker = {even, odd}, wrap =, filter =, mapping =, scale =,
/// offset =}: raybook's own form, returning a texture for mat:set_texture.
int textureTable(lua_State* L) {
    // Only known fields: a typo would otherwise be ignored.
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        lua_pop(L, 1);
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "?";
        if (key != "image" && key != "checker" && key != "wrap" && key != "filter" &&
            key != "mapping" && key != "scale" && key != "offset") {
            lua_pop(L, 1);
            throw ArgumentError("gr.texture: unknown field '" + key +
                                "' (known: image, checker, wrap, filter, mapping, scale, offset)");
        }
    }
    const bool hasImage = lua_getfield(L, 1, "image") != LUA_TNIL;
    const bool hasChecker = lua_getfield(L, 1, "checker") != LUA_TNIL;
    if (hasImage == hasChecker) {
        lua_pop(L, 2);
        throw ArgumentError(
            "gr.texture: give exactly one of image = 'file.png' or checker = {{r,g,b}, {r,g,b}}");
    }
    std::shared_ptr<SurfaceTexture> texture;
    if (hasImage) {
        if (lua_type(L, -2) != LUA_TSTRING) {
            lua_pop(L, 2);
            throw ArgumentError("gr.texture: field 'image' must be a file name");
        }
        const std::string file = lua_tostring(L, -2);
        lua_pop(L, 2);
        auto image = std::make_shared<ImageTexture>(sceneImage(L, file, "gr.texture"));
        const int wrap = choiceField(L, "wrap", {"repeat", "clamp"});
        if (wrap >= 0) image->wrap = wrap == 0 ? Wrap::Repeat : Wrap::Clamp;
        image->bilinear = choiceField(L, "filter", {"bilinear", "nearest"}) != 1;
        texture = image;
    } else {
        const int top = lua_gettop(L);
        bool ok = lua_type(L, top) == LUA_TTABLE && lua_rawlen(L, top) == 2;
        Colour colours[2];
        for (int k = 0; ok && k < 2; ++k) {
            lua_rawgeti(L, top, k + 1);
            const auto c =
                checkTupleAt(L, lua_gettop(L), 3,
                             "gr.texture: field 'checker', colour " + std::to_string(k + 1));
            colours[k] = Colour(c[0], c[1], c[2]);
            lua_pop(L, 1);
        }
        lua_pop(L, 2);
        if (!ok)
            throw ArgumentError(
                "gr.texture: field 'checker' must be two colours {{r,g,b}, {r,g,b}}");
        if (choiceField(L, "wrap", {"repeat", "clamp"}) >= 0 ||
            choiceField(L, "filter", {"bilinear", "nearest"}) >= 0)
            throw ArgumentError("gr.texture: 'wrap' and 'filter' apply to images, not the checker");
        texture = std::make_shared<CheckerTexture>(colours[0], colours[1]);
    }
    const int mapping =
        choiceField(L, "mapping", {"surface", "planar", "spherical", "cylindrical"});
    if (mapping >= 0) texture->mapping = static_cast<UVMapping>(mapping);
    texture->scale = pairField(L, "scale", Vec2(1.0));
    texture->offset = pairField(L, "offset", Vec2(0.0));
    chargeMemory(L, sizeof(ImageTexture));
    pushShared<const Texture>(L, texture, kTextureType);
    return 1;
}
// [lua-texture]

/// gr.texture: raybook's table form, or seed 000's gr.texture(material, 'file.jpg').
int grTexture(lua_State* L) {
    if (lua_gettop(L) == 1 && lua_type(L, 1) == LUA_TTABLE) return textureTable(L);
    checkArgCount(L, "gr.texture", 2, 2, "{image = 'file', ...} or (material, 'file.jpg')");
    noteEraSign(L, Era::Modern, "seed 000's gr.texture");
    auto material = checkMaterial(L, 1, "gr.texture", "material");
    const std::string file = checkString(L, 2, "gr.texture", "file");
    material->textures["kd"] = defaultImageTexture(L, file, "gr.texture");
    return 0;
}

}  // namespace

std::shared_ptr<const Texture> checkTexture(lua_State* L, int arg, const char* call) {
    if (auto* p =
            static_cast<std::shared_ptr<const Texture>*>(luaL_testudata(L, arg, kTextureType)))
        return *p;
    if (lua_type(L, arg) == LUA_TSTRING) return defaultImageTexture(L, lua_tostring(L, arg), call);
    throw ArgumentError(std::string(call) + ": argument " + std::to_string(arg - 1) +
                            " must be a texture (from gr.texture) or an image file name, got " +
                            luaL_typename(L, arg),
                        arg);
}

namespace {

/// mat:set_texture(texture) or mat:set_texture(slot, texture), slot 'kd' or 'ks'.
int materialSetTexture(lua_State* L) {
    const char* call = "material:set_texture";
    checkArgCount(L, call, 2, 3, "(texture) or ('kd' | 'ks', texture)");
    auto material = checkMaterial(L, 1, call, "self");
    std::string slot = "kd";
    if (lua_gettop(L) == 3) {
        slot = checkString(L, 2, call, "slot");
        if (slot != "kd" && slot != "ks")
            throw ArgumentError(std::string(call) + ": slot '" + slot + "' must be 'kd' or 'ks'",
                                2);
    }
    material->textures[slot] = checkTexture(L, lua_gettop(L), call);
    return 0;
}

/// Seed 002's mat:set_texture_map('file'): the image replaces kd.
int materialSetTextureMap(lua_State* L) {
    const char* call = "material:set_texture_map";
    checkArgCount(L, call, 2, 2, "('file.png')");
    auto material = checkMaterial(L, 1, call, "self");
    material->textures["kd"] = defaultImageTexture(L, checkString(L, 2, call, "file"), call);
    return 0;
}

}  // namespace

void bindTextures(LuaBindings& lua) {
    lua_State* L = lua.state();
    // The userdata types this chapter adds, and the per-scene image cache.
    luaL_newmetatable(L, kTextureType);
    lua_pushcfunction(L, collect<const Texture>);
    lua_setfield(L, -2, "__gc");
    lua_pop(L, 1);
    luaL_newmetatable(L, kImageType);
    lua_pushcfunction(L, collect<const TextureImage>);
    lua_setfield(L, -2, "__gc");
    lua_pop(L, 1);
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, kImageCache);
    lua.function("texture", luaGuard<grTexture>);
    lua.materialMethod("set_texture", luaGuard<materialSetTexture>);
    lua.materialMethod("set_texture_map", luaGuard<materialSetTextureMap>);
}

}  // namespace rb
