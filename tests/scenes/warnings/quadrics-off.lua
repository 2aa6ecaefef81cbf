-- A cylinder and a cone in a build whose chapter 15 is switched off: the scene loads, renders
-- the sphere alone, and says how many shapes it left out and why.
-- rt-args: --features=all,-quadrics
-- expect-warning: 2 shapes of the 'quadrics' feature not drawn
-- expect-warning: --features switched it off
root = gr.node('root')
root:add_child(gr.sphere('s'))
local c = gr.cylinder('c')
c:translate(2.5, 0, 0)
root:add_child(c)
local k = gr.cone{name = 'k'}
k:translate(-2.5, 0, 0)
root:add_child(k)
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
