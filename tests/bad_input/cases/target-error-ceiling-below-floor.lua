-- A scene whose sample ceiling is below its floor.
-- expect: is below the floor (--min-spp 32)
local root = gr.sphere('s')
gr.option('target_error', 0.02)
gr.option('min_spp', 32)
gr.option('max_spp', 16)
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
