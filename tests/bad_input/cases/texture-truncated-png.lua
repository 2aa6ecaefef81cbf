-- needs-feature: texture
-- A PNG cut off half way through its compressed data.
-- expect: material:set_texture_map: 
-- expect: images/truncated.png: the image is truncated or corrupt
-- expect: (the file ends before its pixel data does)
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
m:set_texture_map('images/truncated.png') --!
