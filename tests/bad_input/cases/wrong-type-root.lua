-- gr.render given a light as its root: the message should say what was given (a light), and
-- not suggest the colon syntax, which has nothing to do with a gr.* call.
-- expect: gr.render: argument 1 (root) must be a scene node
-- expect: light
-- reject: call methods with a colon
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(light, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
