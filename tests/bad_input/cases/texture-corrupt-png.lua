-- needs-feature: texture
-- A PNG whose compressed data is overwritten with garbage (the header is intact).
-- expect: gr.texture: 
-- expect: images/corrupt.png: the image is truncated or corrupt
local t = gr.texture{image = 'images/corrupt.png'} --!
