-- needs-feature: texture
-- A PNG whose header claims 0 x 64 pixels.
-- expect: images/zero-width.png: the image is empty (0x64)
local t = gr.texture{image = 'images/zero-width.png'} --!
