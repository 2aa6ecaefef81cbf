-- skip-if-feature: photon_map
-- gr.photons belongs to chapter 16: a build without it names the chapter.
-- expect: gr.photons needs chapter 16 (photon_map)
gr.photons{indirect = true} --!
