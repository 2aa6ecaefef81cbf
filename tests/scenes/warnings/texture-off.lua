-- A textured material in a build whose chapter 10 is switched off: the scene loads, renders
-- with the material's own colour, and says why.
-- rt-args: --features=all,-texture
-- expect-warning: the scene's textures (gr.texture, set_texture or set_texture_map) are ignored
-- expect-warning: --features switched it off
local m = gr.material({0.7, 0.7, 0.7}, {0, 0, 0}, 1)
m:set_texture(gr.texture{checker = {{1, 1, 1}, {0, 0, 0}}, scale = {8, 8}})
root = gr.node('root')
local s = gr.sphere('s')
s:set_material(m)
root:add_child(s)
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
