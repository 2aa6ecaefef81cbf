-- The difference of two groups that were never given children: the result is empty, so the
-- picture is blank. rt renders it (an empty solid is legal) and says why it shows nothing.
-- expect-warning: the CSG node 'difference(a, b)' is empty, so it draws nothing
-- expect-warning: neither operand has a shape under it
root = gr.node('root')
local a = gr.node('a')
local b = gr.node('b')
root:add_child(gr.difference(a, b))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
