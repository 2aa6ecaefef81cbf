-- A sphere made but never added to the root: the picture can only be empty.
-- expect-warning: did you add_child?
root = gr.node('root')
s = gr.sphere('s')
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
