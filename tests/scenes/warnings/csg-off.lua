-- A CSG node in a build whose chapter 14 is switched off: the scene loads, its operands are
-- drawn whole as a plain group, and rt says why.
-- rt-args: --features=all,-csg
-- expect-warning: CSG nodes (gr.union, gr.intersection, gr.difference, node:csg) are drawn as plain groups
-- expect-warning: --features switched it off
root = gr.node('root')
root:add_child(gr.difference(gr.sphere('a'), gr.nh_sphere('b', {1, 0, 0}, 0.5)))
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
