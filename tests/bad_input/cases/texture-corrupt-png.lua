-- needs-feature: texture
-- A PNG whose compressed data is overwritten with garbage (the header is intact).
-- expect: gr.texture: 
-- expect: images/corrupt.png: the image is truncated or corrupt
-- expect: (its compressed pixel data is damaged)
local t = gr.texture{image = 'images/corrupt.png'} --!
