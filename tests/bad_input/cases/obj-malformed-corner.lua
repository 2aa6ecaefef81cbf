-- A face corner with too many slashes.
-- expect: malformed-corner.obj:4: corner '1/1/1/1' has too many '/'
local m = gr.mesh('m', 'objs/malformed-corner.obj') --!
