-- An image of 100000x100000 pixels (10^10 pixels, 120 GB of film): refused up front.
-- expect: image size 100000x100000 is too large
local root = gr.sphere('s')
local light = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'out.png', 100000, 100000, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {light}) --!
