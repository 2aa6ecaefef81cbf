#include "core/lua_sandbox_io.h"

namespace rb {

void openReadOnlyIo(lua_State*) {}

}  // namespace rb
