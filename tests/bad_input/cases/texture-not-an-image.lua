-- needs-feature: texture
-- A text file with an image's name.
-- expect: images/not-an-image.jpg: not an image stb_image can read
-- expect: expected PNG, JPEG
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
m:set_texture('kd', 'images/not-an-image.jpg') --!
