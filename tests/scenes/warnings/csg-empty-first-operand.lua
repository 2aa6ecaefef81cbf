-- A sphere subtracted from a group that was never given children: nothing is left to draw,
-- although the second operand has a shape.
-- expect-warning: the CSG node 'cut' is empty, so it draws nothing
-- expect-warning: its first operand, the solid subtracted from, has no shape under it
root = gr.node('root')
local block = gr.node('block')
root:add_child(gr.difference(block, gr.sphere('hole'), 'cut'))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
