-- The scene names its image out.ppm: rt writes PNG data there, as the course framework does.
-- rt-no-output-override
-- expect-warning: 'out.ppm' does not end in .png
root = gr.node('root')
root:add_child(gr.sphere('s'))
gr.render(root, 'out.ppm', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})}) --!
