-- needs-feature: media
-- A phase function with |g| = 1 is a delta, not a lobe: refused, naming the field.
-- expect: field 'g' must lie strictly between
local m = gr.medium{sigma_s = 1, g = 1} --!
