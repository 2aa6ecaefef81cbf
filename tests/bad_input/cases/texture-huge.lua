-- needs-feature: texture
-- A PNG whose header claims 60000 x 60000 pixels (86 GB of texels): refused from the header,
-- before anything is decoded, against the memory budget.
-- rt-args: --max-memory 256M
-- expect: images/huge.png: the 60000x60000 texture image needs about
-- expect: --max-memory 256M
local t = gr.texture{image = 'images/huge.png'} --!
