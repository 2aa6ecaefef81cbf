-- A mesh file that is in none of the places searched: the message lists every one of them, in
-- order (the working directory, then the scene's folder).
-- expect: gr.mesh: cannot find 'no-such-mesh.obj'; looked in: 
-- expect: /work/obj-missing/no-such-mesh.obj, 
-- expect: /cases/no-such-mesh.obj
-- expect: --assets DIR
local m = gr.mesh('m', 'no-such-mesh.obj') --!
