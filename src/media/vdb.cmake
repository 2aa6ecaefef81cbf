# Chapter 17's density grids from VDB files: the sources and build settings (src/media/vdb.cmake).
# NanoVDB is header-only (Debian's libnanovdb-dev). Without it raybook still builds: vdbSupported()
# is false, and loading a grid tells the user to run make deps.
find_path(RB_NANOVDB_INCLUDE_DIR nanovdb/NanoVDB.h)
set(RB_MEDIA_VDB_SOURCES src/media/vdb_density.cpp)
if(RB_NANOVDB_INCLUDE_DIR)
  set_property(SOURCE src/media/vdb_density.cpp APPEND PROPERTY COMPILE_DEFINITIONS RB_HAVE_NANOVDB)
  # An explicit -I/usr/include would reorder the compiler's own system headers.
  if(NOT RB_NANOVDB_INCLUDE_DIR IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
    set_property(SOURCE src/media/vdb_density.cpp APPEND PROPERTY INCLUDE_DIRECTORIES
                 ${RB_NANOVDB_INCLUDE_DIR})
  endif()
  # rb_make_plume writes the chapter's smoke plume, scenes/assets/plume.nvdb (see make_plume.cpp).
  # It needs only NanoVDB and chapter 11's gradient noise, so it compiles that one file again.
  find_package(Threads REQUIRED)
  add_executable(rb_make_plume src/media/make_plume.cpp src/bump/gradient_noise.cpp)
  target_include_directories(rb_make_plume PRIVATE ${CMAKE_SOURCE_DIR}/src)
  if(NOT RB_NANOVDB_INCLUDE_DIR IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
    target_include_directories(rb_make_plume PRIVATE ${RB_NANOVDB_INCLUDE_DIR})
  endif()
  target_link_libraries(rb_make_plume PRIVATE glm::glm Threads::Threads)
else()
  message(STATUS "NanoVDB not found (install libnanovdb-dev, or run make deps): "
                 "chapter 17 builds without VDB density grids")
endif()
