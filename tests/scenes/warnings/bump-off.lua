-- A bumped material in a build whose chapter 11 is switched off: the scene loads, renders the
-- surface smooth, and says why.
-- rt-args: --features=all,-bump
-- expect-warning: bumps (set_bump or set_bump_map) are ignored
-- expect-warning: --features switched it off
local m = gr.material({0.7, 0.3, 0.2}, {0.5, 0.5, 0.5}, 30)
m:set_bump{pattern = 'noise', strength = 0.05, scale = 0.3}
root = gr.node('root')
local s = gr.sphere('s')
s:set_material(m)
root:add_child(s)
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
