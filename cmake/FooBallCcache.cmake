# Compiles through ccache where it is installed (scripts/install-deps installs it), unless the
# configure names a launcher of its own. Paths under the repository are hashed relative to it
# and the build directory is left out of the hash, so a clone in another folder reuses the cache
# (debug info then names the folder that first compiled an object). FOOBALL_CCACHE=OFF opts out.
option(FOOBALL_CCACHE "Compile through ccache when it is installed" ON)
find_program(FOOBALL_CCACHE_PROGRAM ccache)
cmake_path(GET CMAKE_CURRENT_LIST_DIR PARENT_PATH FOOBALL_REPOSITORY_DIR)
if(FOOBALL_CCACHE AND FOOBALL_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER env CCACHE_BASEDIR=${FOOBALL_REPOSITORY_DIR} CCACHE_NOHASHDIR=1
                                  ${FOOBALL_CCACHE_PROGRAM})
  # __FILE__ (GoogleTest's and Qt's messages) relative to the clone too: a unity batch includes
  # its files by absolute path, which would otherwise land in its preprocessed text and object.
  add_compile_options(-fmacro-prefix-map=${FOOBALL_REPOSITORY_DIR}/=)
endif()
