-- needs-feature: texture
-- A folder where an image file was expected (named like one): it opens like a file on Linux
-- and reads as nothing, so stb_image would call it "not an image".
-- expect: gr.texture: 
-- expect: images/folder.png: is a directory, not an image file
-- reject: not an image stb_image can read
local t = gr.texture{image = 'images/folder.png'} --!
