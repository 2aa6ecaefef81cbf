-- Extra trailing arguments, which the course framework's bindings ignore: each is a warning
-- naming the call, once per call kind, and the scene renders as the framework would.
-- expect-warning: gr.sphere: ignored 2 extra arguments after (name), as the course framework does (2 times)
-- expect-warning: gr.nh_box: ignored 2 extra arguments
-- expect-warning: node:translate: ignored 1 extra argument
root = gr.node('root')
s = gr.sphere('s', {0, 0, 0}, 1) --!
root:add_child(s)
t = gr.sphere('t', {0, 0, 0}, 1)
b = gr.nh_box('b', {-3, -1, -1}, 1, 2, 3)
root:add_child(b)
s:translate(0, 0, 0, 1)
gr.render(root, 'out.png', 32, 24, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
