-- needs-feature: texture
-- A JPEG cut off half way through its entropy-coded data.
-- expect: images/truncated.jpg: the image is truncated or corrupt
-- expect: (the JPEG data ends, or is damaged, before its end marker)
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
gr.texture(m, 'images/truncated.jpg') --!
