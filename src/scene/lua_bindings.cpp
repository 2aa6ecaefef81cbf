// The registry of Lua calls: what each chapter adds through LuaBindings (gr calls, node and
// material methods, material fields, gr.option names), and the checks that use it: a scene
// option's range, a material field some built chapter reads, the chapter a missing name needs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/feature.h"
#include "scene/lua_scene.h"
#include "scene/lua_types.h"

namespace rb {

void LuaBindings::function(const char* name, lua_CFunction f) {
    lua_getglobal(L_, "gr");
    lua_pushcfunction(L_, f);
    lua_setfield(L_, -2, name);
    lua_pop(L_, 1);
}

void LuaBindings::nodeMethod(const char* name, lua_CFunction f) {
    luaL_getmetatable(L_, kNodeType);
    lua_getfield(L_, -1, "__index");
    lua_pushcfunction(L_, f);
    lua_setfield(L_, -2, name);
    lua_pop(L_, 2);
}

void LuaBindings::materialMethod(const char* name, lua_CFunction f) {
    luaL_getmetatable(L_, kMaterialType);
    lua_getfield(L_, -1, "__index");
    lua_pushcfunction(L_, f);
    lua_setfield(L_, -2, name);
    lua_pop(L_, 2);
}

void LuaBindings::materialField(const char* name, int chapter) {
    sceneBuilder(L_).materialFields[name] = chapter;
}

void LuaBindings::option(const char* name, int chapter, double min, double max, bool integer) {
    sceneBuilder(L_).optionNames[name] = {chapter, min, max, integer};
}

void setSceneOption(lua_State* L, const std::string& name, double value, const std::string& what) {
    SceneBuilder& builder = sceneBuilder(L);
    const auto& spec = builder.optionNames.at(name);
    if (value < spec.min || value > spec.max || (spec.integer && value != std::floor(value))) {
        char range[96];
        std::snprintf(range, sizeof range, "%s from %g to %g",
                      spec.integer ? "a whole number" : "a number", spec.min, spec.max);
        throw ArgumentError(what + " must be " + range);
    }
    builder.sceneOptions[name] = value;
}

int missingChapter(lua_State* L, const std::string& name, std::string& title) {
    const int chapter = chapterProviding(name, title);
    // A chapter is missing when it is not built in, even below the newest one: chapters may
    // land out of order (a build with 1-8 and 15 lacks chapter 14).
    const std::vector<int>& built = sceneBuilder(L).builtChapters;
    return chapter && std::find(built.begin(), built.end(), chapter) == built.end() ? chapter : 0;
}

void setMaterialParam(lua_State* L, Material& m, const std::string& name, double value,
                      const char* call) {
    checkMaterialField(L, name, call);
    if (!std::isfinite(value))
        throw ArgumentError(std::string(call) + ": material field '" + name + "' must be finite");
    m.params[name] = value;
}

void checkMaterialField(lua_State* L, const std::string& name, const char* call) {
    const SceneBuilder& builder = sceneBuilder(L);
    if (!builder.materialFields.count(name)) {
        std::string title;
        const int chapter = missingChapter(L, name, title);
        if (chapter)
            throw ArgumentError(std::string(call) + ": material field '" + name +
                                "' needs chapter " + std::to_string(chapter) + " (" + title +
                                "), which this build does not have; " + chapterAdvice(chapter));
        std::string known = "kd, ks, shininess";
        for (const auto& [field, ch] : builder.materialFields) known += ", " + field;
        throw ArgumentError(std::string(call) + ": unknown material field '" + name +
                            "' (known: " + known + ")");
    }
}

}  // namespace rb
