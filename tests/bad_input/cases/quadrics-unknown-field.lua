-- A field gr.cone does not know (a typo of top_radius).
-- expect: gr.cone: unknown field 'topradius' (known: name, open, top_radius)
local k = gr.cone{name = 'k', topradius = 0.5} --!
