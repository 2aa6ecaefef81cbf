# Chapter 17's density grids from VDB files: the sources and build settings (src/media/vdb.cmake).
set(RB_MEDIA_VDB_SOURCES "")
