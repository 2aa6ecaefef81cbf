# The WebAssembly build's stand-ins for the native build's dependencies (src/web/README.md),
# under the names the chapters link: emscripten has no OpenMP, and Debian's Lua, stb and GLM
# are for the host. GLM and stb are header-only here (stb's implementations are compiled into
# rt_web from Debian's headers); Lua is Debian's lua.h over src/web/lua_shim.cpp.
set(RB_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${RB_WEB_INCLUDE})
# Only the headers we mean, never all of /usr/include (glibc's would shadow emscripten's).
foreach(header lua.h lua.hpp luaconf.h lualib.h lauxlib.h)
  file(CREATE_LINK /usr/include/lua5.4/${header} ${RB_WEB_INCLUDE}/${header} SYMBOLIC)
endforeach()
file(WRITE ${RB_WEB_INCLUDE}/lua5.4-deb-multiarch.h
  "// luaconf.h includes it on Debian; the value names the WebAssembly build.\n#define DEB_HOST_MULTIARCH \"wasm32-emscripten\"\n")
file(CREATE_LINK /usr/include/glm ${RB_WEB_INCLUDE}/glm SYMBOLIC)
file(CREATE_LINK /usr/include/stb/stb_image.h ${RB_WEB_INCLUDE}/stb_image.h SYMBOLIC)
file(CREATE_LINK /usr/include/stb/stb_image_write.h ${RB_WEB_INCLUDE}/stb_image_write.h SYMBOLIC)

add_library(rb_web_deps INTERFACE)
target_include_directories(rb_web_deps SYSTEM INTERFACE ${RB_WEB_INCLUDE}
                           ${CMAKE_SOURCE_DIR}/src/web)
# C++ exceptions carry raybook's input errors; emscripten leaves their catching off unless asked.
# -fwasm-exceptions: WebAssembly's own exception handling (try/catch in the wasm), not
# -fexceptions' JavaScript emulation, which sends every call that may throw out of a function
# with something to unwind through a JavaScript trampoline (invoke_*, 31% of rt's calls):
# a node profile of chapter 17 spent 16% of its time in them (src/web/README.md, "Speed").
# Browsers: Chrome and Edge 95, Firefox 100, Safari 15.2 and later.
# SSE2 intrinsics (the wide BVH) compile to WebAssembly SIMD (Chrome and Edge 91, Firefox 89,
# Safari 16.4 and later); GCC's xmmintrin.h brings SSE2's emmintrin.h along, emscripten's
# does not.
target_compile_options(rb_web_deps INTERFACE -fwasm-exceptions -Wno-unknown-pragmas -msimd128
                       -msse2 "SHELL:-include emmintrin.h")
target_link_options(rb_web_deps INTERFACE -fwasm-exceptions -msimd128)
add_library(glm::glm ALIAS rb_web_deps)
add_library(OpenMP::OpenMP_CXX ALIAS rb_web_deps)
add_library(PkgConfig::LUA ALIAS rb_web_deps)
add_library(PkgConfig::STB ALIAS rb_web_deps)
# Chapter 17's NanoVDB (header-only, Debian's libnanovdb-dev), found here, where the
# emscripten toolchain's search would look only in its own sysroot.
if(EXISTS /usr/include/nanovdb/NanoVDB.h)
  file(CREATE_LINK /usr/include/nanovdb ${RB_WEB_INCLUDE}/nanovdb SYMBOLIC)
  set(RB_NANOVDB_INCLUDE_DIR ${RB_WEB_INCLUDE} CACHE PATH "NanoVDB headers (WebAssembly build)" FORCE)
endif()
