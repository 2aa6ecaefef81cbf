-- skip-if-feature: media
-- gr.medium belongs to chapter 17: a build without it names the chapter.
-- expect: gr.medium needs chapter 17 (media)
local fog = gr.medium{sigma_s = 0.1} --!
