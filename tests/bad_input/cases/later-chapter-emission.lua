-- skip-if-feature: path_tracing
-- Emission is chapter 18's: an earlier binary names the chapter that reads it.
-- expect: needs chapter 18
local lamp = gr.material{kd = {1, 1, 1}, emission = {1, 1, 1}} --!
