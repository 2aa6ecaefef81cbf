-- require may not leave the scene's folder.
-- expect: require: module name '../x'
require('../x') --!
