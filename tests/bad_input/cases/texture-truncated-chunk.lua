-- needs-feature: texture
-- A PNG cut off inside the header of its first IDAT chunk (40 bytes: the signature, IHDR and
-- "IDA"): stb_image's reason is the chunk type it misread, "IDA"; the message says what that means.
-- expect: images/truncated-chunk.png: the image is truncated or corrupt (the file ends, or is damaged, inside a PNG chunk)
-- reject: (IDA)
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
m:set_texture('kd', 'images/truncated-chunk.png') --!
