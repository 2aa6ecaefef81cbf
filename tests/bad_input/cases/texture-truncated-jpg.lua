-- needs-feature: texture
-- A JPEG cut off half way through its entropy-coded data.
-- expect: images/truncated.jpg: the image is truncated or corrupt
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
gr.texture(m, 'images/truncated.jpg') --!
