-- require of a module that is not in the scene's folder: the message must name the scene
-- file and line, like every other error.
-- expect: no_such_module
require('no_such_module') --!
