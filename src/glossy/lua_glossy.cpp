// Chapter 7's Lua: the material field `glossiness` and the scene options `glossy_samples` and
// `glossy_sampler`. The seeds' calls that carry a glossiness (seed 000's "glossy", fuzz, seed
// 001's gr.phongMat and gr.transMat, seed 002's gr.fancy_material) are bound by chapters 4 and
// 5 and set this same field.
#include "glossy/glossy.h"
#include "scene/lua_scene.h"

namespace rb {

// [lua-glossy]
void bindGlossy(LuaBindings& lua) {
    // gr.material{..., reflect = 0.8, glossiness = 0.2}: the fuzz radius of the lobe.
    lua.materialField("glossiness", 7);
    // gr.option('glossy_samples', N): directions per glossy surface.
    lua.option("glossy_samples", 7);
    // gr.option('glossy_sampler', 0 | 1): the fuzz sphere or the Phong lobe.
    lua.option("glossy_sampler", 7);
}
// [lua-glossy]

}  // namespace rb
