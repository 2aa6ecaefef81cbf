-- require with a leading '..' (Lua's separator is the dot).
-- expect: may not leave the scene's folder
require('..fixtures.ok') --!
