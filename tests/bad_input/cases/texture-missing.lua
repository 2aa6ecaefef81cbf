-- needs-feature: texture
-- An image that is in none of the places searched: like a mesh, the message lists every one.
-- expect: gr.texture: cannot find 'no-such-wood.jpg'; looked in:
-- expect: /cases/no-such-wood.jpg
-- expect: --assets DIR
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
gr.texture(m, 'no-such-wood.jpg') --!
