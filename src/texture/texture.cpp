#include "texture/texture.h"

#include "core/integrator.h"
#include "core/render_context.h"
#include "core/texture.h"

namespace rb {

// [lookup]
Material lookupTextures(const Hit& hit) {
    const Material& m = *hit.material;
    Material shading;
    shading.kd = m.kd;
    shading.ks = m.ks;
    shading.shininess = m.shininess;
    if (const Texture* kd = m.texture("kd")) shading.kd = kd->evaluate(hit);
    if (const Texture* ks = m.texture("ks")) shading.ks = ks->evaluate(hit);
    return shading;
}
// [lookup]

namespace {

// [install]
void installTextures(Pipeline& pipeline, Scene&, const RenderContext& context) {
    // Only a scene with a textured material looks anything up: any other pays nothing.
    for (const Instance& instance : context.instances)
        if (instance.material && !instance.material->textures.empty()) {
            pipeline.textureLookup = lookupTextures;
            return;
        }
}
// [install]

}  // namespace

Feature textureFeature() {
    return {"texture", 10,           "textures: UV mapping, images (bilinear, sRGB) and a checker",
            true,      bindTextures, installTextures};
}

}  // namespace rb
