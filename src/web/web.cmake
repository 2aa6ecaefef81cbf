# rt_web: the whole rt program as WebAssembly, for the docs' live panels (src/web/README.md).
# Built by emcmake (make web); every chapter's sources are the native build's, unchanged.
set(list_file ${CMAKE_BINARY_DIR}/generated/features_web.cpp)
rb_features_file(${list_file} "every chapter (rt_web)" ${RB_CHAPTERS})
add_executable(rt_web ${list_file} src/web/lua_shim.cpp src/web/stb_image_impl.cpp
  src/web/posix_stubs.cpp)
target_link_libraries(rt_web PRIVATE rb_main rb_cluster rb_mpi_logic)
foreach(n IN LISTS RB_CHAPTERS)
  target_link_libraries(rt_web PRIVATE rb_ch${n})
endforeach()
# rt_web.js and rt_web.wasm: bundle.py packs the wasm into the docs' one script (so they work
# from file:// as from a server), and the page compiles it once for all its workers; node
# loads it from beside rt_web.js. The scenes and their assets are its file system, at /scenes.
target_link_options(rt_web PRIVATE
  -sMODULARIZE=1 -sEXPORT_NAME=createRaybook -sINVOKE_RUN=0
  -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=0 -sENVIRONMENT=web,worker,node
  -sEXPORTED_FUNCTIONS=_main,_malloc,_free,_rb_shim_op,_rb_shim_globals
  -sEXPORTED_RUNTIME_METHODS=callMain,FS,stringToUTF8,lengthBytesUTF8,UTF8ToString
  --embed-file ${CMAKE_SOURCE_DIR}/scenes@/scenes)
set_target_properties(rt_web PROPERTIES SUFFIX .js)
