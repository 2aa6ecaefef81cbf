-- needs-feature: media
-- gr.fog takes a medium (or nil to clear it); a number is refused, named as argument 1.
-- expect: gr.fog: argument 1 (medium) must be a medium (from gr.medium), got number
gr.fog(42) --!
